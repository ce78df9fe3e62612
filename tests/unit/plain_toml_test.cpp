// The plain TOML reader (scene/plain_toml.hpp) against toml::parse: wherever it answers, the very
// tree toml::parse gives, node by node (source regions, integer or float, -0.0 and NaN's bits);
// where the text is not plain or is wrong, it declines and toml::parse reports the error.
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "fuzz/toml_tree_difference.hpp"
#include "scene/object_batches.hpp"
#include "scene/plain_toml.hpp"
#include "support/test_support.hpp"

namespace lancer {
namespace {

const char* const kPlainPath = "scenes/plain.toml";

// True where the plain reader answered (with toml::parse's tree, or the test fails), false where
// it declined.
bool plain_answers_alike(std::string_view text, const std::string& what) {
    const std::optional<toml::table> plain = parse_plain_toml(text, kPlainPath);
    if (!plain) return false;
    toml::table parsed;
    try {
        parsed = toml::parse(text, std::string_view(kPlainPath));
    } catch (const toml::parse_error& e) {
        ADD_FAILURE() << what << ": read, where toml::parse says: " << e.description();
        return true;
    }
    EXPECT_EQ(fuzz::toml_tree_difference(parsed, *plain), "") << what;
    return true;
}

struct PlainCount {
    int answered = 0, declined = 0;
};

// The whole text, and its [[object]] tables in batches of one and of three.
void expect_plain_alike_in_parts(const std::string& text, const std::string& what, PlainCount& count) {
    (plain_answers_alike(text, what) ? count.answered : count.declined)++;
    for (std::size_t per_batch : {1, 3}) {
        const std::optional<SceneTextParts> parts = split_object_tables(text, per_batch);
        if (!parts) continue;
        for (const ObjectBatch& b : parts->batches) {
            const std::string batch_what = what + ", the batch from line " + std::to_string(b.first_line);
            (plain_answers_alike(std::string_view(text).substr(b.begin, b.end - b.begin), batch_what) ? count.answered
                                                                                                        : count.declined)++;
        }
    }
}

std::vector<std::string> files_under(const std::string& relative, const std::string& extension) {
    std::vector<std::string> files;
    for (const auto& e : std::filesystem::recursive_directory_iterator(test::source_path(relative)))
        if (e.is_regular_file() && (extension.empty() || e.path().extension() == extension)) files.push_back(e.path().string());
    return files;
}

TEST(PlainToml, ShippedScenesAndBenchScenesReadAsTomlParseReadsThem) {
    PlainCount count;
    for (const char* dir : {"scenes", "bench"})
        for (const std::string& path : files_under(dir, ".toml")) expect_plain_alike_in_parts(test::read_file(path), path, count);
    // Most object tables are plain: a reader that declined them all would pass the above.
    EXPECT_GT(count.answered, 1000) << count.declined << " declined";
}

TEST(PlainToml, FuzzCorpusReadsAsTomlParseReadsIt) {
    PlainCount count;
    for (const std::string& path : files_under("tests/fuzz/corpus/scene", ""))
        expect_plain_alike_in_parts(test::read_file(path), path, count);
    EXPECT_GT(count.answered, 500) << count.declined << " declined";
}

// Numbers as a key's value, an array's and an inline table's: each is a number ends differently.
void expect_number_alike(const std::string& number, bool plain) {
    for (const std::string& text : {"a = " + number + "\n", "a = [" + number + ", " + number + "]", "a = {b = " + number + "}",
                                    "a = " + number + " # after\n", "a = " + number}) {
        const bool answered = plain_answers_alike(text, text);
        if (plain) {
            EXPECT_TRUE(answered) << text;
        }
    }
}

TEST(PlainToml, IntegersAreIntegersWithTheirValues) {
    for (const char* n : {"0", "-0", "+0", "7", "-7", "+7", "42", "-120", "123456789012345678", "-123456789012345678"})
        expect_number_alike(n, true);
    // Too long for the reader, or not decimal, or wrong: toml::parse's.
    for (const char* n : {"1234567890123456789", "9223372036854775807", "-9223372036854775808", "9223372036854775808", "1_000",
                          "0x1F", "0o17", "0b101", "01", "-01", "1__0", "_1", "1_", "+", "-", "++1", "1979-05-27", "07:32:00"})
        expect_number_alike(n, false);
}

TEST(PlainToml, FloatsAreFloatsCorrectlyRounded) {
    for (const char* n : {"1.0", "-0.0", "+0.0", "0.0", "0.5", "-0.5", "3.14159", "0.1", "0.30000000000000004", "123456789.123456789",
                          "1e5", "1E5", "1e+5", "1e-5", "-1.5e-3", "+2.5E+10", "1e39", "-1e39", "1e05", "0e0", "-0e0", "1e308",
                          "1.7976931348623157e308", "2.2250738585072014e-308", "-3.65635753", "0.05000000000000002", "inf", "+inf",
                          "-inf", "nan", "+nan", "-nan"})
        expect_number_alike(n, true);
    for (const char* n : {"1e400", "-1e400", "1e-400", "4.9e-324", "1.", ".5", "-.5", "1e", "1e+", "1.5.3", "1.5e3.0", "00.5",
                          "1_000.5", "1.0_1", "Inf", "NaN", "infinity", "nan1", "1.5x", "0x1p3", "1.0e1_0",
                          "1.00000000000000000000000000000000000000000000000000000000000000001"})
        expect_number_alike(n, false);
}

TEST(PlainToml, StringsBooleansAndEscapes) {
    for (const char* v : {R"("plain")", R"("")", "''", R"('literal \ back')", "\"tab\there\"", R"("esc \" \\ \n \t \b \f \r end")",
                          R"("#not a comment")", R"('[[object]]')", "true", "false"}) {
        const std::string text = std::string("a = ") + v + "\nb = [" + v + "]\nc = {d = " + v + "}\n";
        EXPECT_TRUE(plain_answers_alike(text, text));
    }
    for (const char* v : {R"("\u00e9")", R"("\U0001F600")", "\"\"\"multi\"\"\"", "'''multi'''", R"("\e")", R"("\x41")", R"("\q")",
                          "\"unterminated", "'unterminated", "\"a\"b", "\"caf\xc3\xa9\"", "\"bell\x07\"", "True", "tru", "falsey"}) {
        const std::string text = std::string("a = ") + v + "\n";
        EXPECT_FALSE(plain_answers_alike(text, text));
    }
}

TEST(PlainToml, ArraysAndInlineTables) {
    for (const char* v : {"[]", "[ ]", "[[1, 2], [3.5, [4]], []]", "[1, 2, ]", "[\n  1, # one\n  2,\n  # none\n]", "[{a = 1}, {b = [true]}]",
                          "{}", "{ a = 1, b = { c = [1, 2.0] }, d = 'x' }", "{a=1,b=2}", "[[[[[[1]]]]]]", "[\r\n1,\r\n2\r\n]"}) {
        const std::string text = std::string("a = ") + v + "\nz = 1\n";
        EXPECT_TRUE(plain_answers_alike(text, text));
    }
    for (const char* v : {"[1,,2]", "[,]", "[1 2]", "{a = 1,}", "{,}", "{a = 1\n}", "{a = 1 b = 2}", "{a.b = 1}", "{\"a\" = 1}", "[1",
                          "{a = 1", "{a = 1 # c\n}"}) {
        const std::string text = std::string("a = ") + v + "\n";
        EXPECT_FALSE(plain_answers_alike(text, text));
    }
}

TEST(PlainToml, HeadersCommentsLineEndsAndTheEnd) {
    const std::string tables =
        "# a scene's objects\n"
        "[[object]]   # the first\n"
        "type = \"sphere\"\n"
        "\tcenter = [1, 2, 3]\n"
        "\n"
        "[object.material]\n"
        "color = [1, 0, 0]\n"
        "[[object.child]]\n"
        "radius = 1\n"
        "[[ object . child ]]\n"
        "[[object]]\n"
        "type = 'box'\n"
        "[object.placement.more]\n";  // no parent `placement`: an implicit table
    for (const std::string& text : {tables, tables.substr(0, tables.rfind("[object.placement")),
                                    tables.substr(0, tables.rfind("[object.placement") - 1), std::string("a = 1"), std::string("# only"),
                                    std::string(""), std::string("\n\n"), std::string("[[object]]"), std::string("[a]\nb = 1\n[a.c]\n")}) {
        std::string crlf;
        for (char c : text) crlf += c == '\n' ? std::string("\r\n") : std::string(1, c);
        const bool lf = plain_answers_alike(text, text);
        EXPECT_EQ(plain_answers_alike(crlf, "CRLF: " + text), lf) << text;
        EXPECT_EQ(lf, text.find("placement") == std::string::npos) << text;
    }
    for (const char* text : {"a = 1\rb = 2\n", "# a\rb\n", "[[object]\n", "[ [object]]\n", "[object]]\n", "[]\n", "[\"object\"]\n",
                             "a.b = 1\n", "\"a\" = 1\n", "a = 1 b\n", "a =\n", "= 1\n", "[a]\nb = 1\n[b.c]\n", "# caf\xc3\xa9\n",
                             "\xef\xbb\xbf" "a = 1\n", "a = 1\x0b\n"})
        EXPECT_FALSE(plain_answers_alike(text, text)) << text;
}

// A key or table defined twice is toml::parse's error to report, where it reports it.
TEST(PlainToml, RedefinitionsAreLeftToTomlParse) {
    for (const char* text : {"a = 1\na = 2\n", "a = {b = 1, b = 2}\n", "[a]\n[a]\n", "[[object]]\nx = 1\n[object.x]\n",
                             "[[object]]\n[object.x]\n[object.x]\n", "a = []\n[[a]]\n", "a = [{b = 1}]\n[[a]]\n", "[a]\n[[a]]\n",
                             "[[a]]\n[a]\n", "a = {}\n[a.b]\n", "[[object]]\nx = 1\n[[object.x]]\n"}) {
        EXPECT_FALSE(parse_plain_toml(text, kPlainPath)) << text;
        EXPECT_THROW((void)toml::parse(text, std::string_view(kPlainPath)), toml::parse_error) << text;
    }
}

TEST(PlainToml, NodesShareTheDocumentsPath) {
    const std::optional<toml::table> plain = parse_plain_toml("[[object]]\nc = [1]\n", kPlainPath);
    ASSERT_TRUE(plain);
    const toml::array& objects = *plain->get_as<toml::array>("object");
    EXPECT_EQ(objects.source().path.get(), plain->source().path.get());
    EXPECT_EQ(*plain->source().path, kPlainPath);
    EXPECT_EQ(objects[0].as_table()->get("c")->source().path.get(), plain->source().path.get());
}

}  // namespace
}  // namespace lancer
