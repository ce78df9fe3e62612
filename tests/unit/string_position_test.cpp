// Positions inside TOML string values: where byte k of a string's decoded text is in the file,
// for every kind of TOML string (errors in expressions point there).
#include <gtest/gtest.h>

#include "scene/string_position.hpp"

namespace lancer {
namespace {

// The position of byte `index` of the string value that starts at line 1, column 5 ("x = " before it).
std::pair<int, int> at(const std::string& text, std::size_t index) {
    SourceLocation p = position_in_string(text, {"f.toml", 1, 5}, index);
    return {p.line, p.column};
}

TEST(StringPosition, PlainStringsStartAfterTheQuote) {
    EXPECT_EQ(at("x = \"u * son(v)\"", 4), std::make_pair(1, 10));  // the 's' of son
    EXPECT_EQ(at("x = 'u * son(v)'", 4), std::make_pair(1, 10));
    EXPECT_EQ(at("x = \"u\"", 1), std::make_pair(1, 7));  // the end of the text: the closing quote
}

TEST(StringPosition, TripleQuotesOnOneLine) {
    EXPECT_EQ(at("x = \"\"\"u + son(v)\"\"\"", 4), std::make_pair(1, 12));
    EXPECT_EQ(at("x = '''u + son(v)'''", 4), std::make_pair(1, 12));
}

TEST(StringPosition, EscapesTakeMoreRoomInTheFileThanInTheValue) {
    // "\u0075" is one byte of the value ('u') and six characters of the file.
    EXPECT_EQ(at("x = \"\\u0075 + son(v)\"", 4), std::make_pair(1, 15));
    EXPECT_EQ(at("x = \"\\t\\t+ son(v)\"", 4), std::make_pair(1, 12));
    // A code point of two UTF-8 bytes counts as two bytes of the value.
    EXPECT_EQ(at("x = \"\\u00e9 + son(v)\"", 5), std::make_pair(1, 15));
}

TEST(StringPosition, MultiLineStringsKeepTheirLines) {
    // The newline right after the opening quotes is not part of the value.
    std::string text = "x = '''\n  (a + cos(u))\n  * son(v)'''";
    std::string value = "  (a + cos(u))\n  * son(v)";
    EXPECT_EQ(at(text, value.find("son")), std::make_pair(3, 5));
    std::string crlf = "x = \"\"\"\r\n  u\r\n  + son(v)\"\"\"";
    EXPECT_EQ(at(crlf, std::string("  u\n  + son(v)").find("son")), std::make_pair(3, 5));
    // A line-ending backslash joins lines: "u + \<newline>   son(v)" is "u + son(v)".
    std::string joined = "x = \"\"\"u + \\\n     son(v)\"\"\"";
    EXPECT_EQ(at(joined, 4), std::make_pair(2, 6));
}

TEST(StringPosition, WithoutAStringThereItGuesses) {
    EXPECT_EQ(at("x = 12", 3), std::make_pair(1, 9));
    EXPECT_EQ(at("", 3), std::make_pair(1, 9));
}

}  // namespace
}  // namespace lancer
