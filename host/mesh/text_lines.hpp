#pragma once
// The line-by-line view of OBJ and MTL files: each line split at blanks into tokens that know their
// column, '#' comments removed, and numbers read with errors at file:line:column.
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace lancer::mesh {

struct LineToken {
    std::string_view text;
    int column = 0;  // 1-based
};

class TextLines {
public:
    TextLines(std::string_view text, std::string file_name) : text_(text), file_(std::move(file_name)) {}

    // The next line with any token; false at the end of the text.
    bool next();
    int line() const { return line_; }
    const std::vector<LineToken>& tokens() const { return tokens_; }
    // The rest of the line from token `first` on, as written (a file name with spaces).
    std::string_view rest_from(std::size_t first) const;
    const std::string& file() const { return file_; }

    [[noreturn]] void fail(const LineToken& at, const std::string& message) const;
    [[noreturn]] void fail_at_line(const std::string& message) const;  // column 0
    [[noreturn]] void fail_after_last(const std::string& message) const;  // just past the last token

    // The whole token as a number; `what` names it in the message.
    double number(const LineToken& t, const std::string& what) const;
    long long integer(const LineToken& t, std::string_view digits, const std::string& what) const;

private:
    std::string_view text_;
    std::string file_;
    std::size_t pos_ = 0;
    int line_ = 0;
    std::string_view current_;
    std::vector<LineToken> tokens_;
};

// A token quoted for a message: at most 40 characters, control and non-ASCII bytes as '?'.
std::string excerpt(std::string_view s);

}  // namespace lancer::mesh
