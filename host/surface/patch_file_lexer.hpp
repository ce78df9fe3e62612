#pragma once
// The line-and-token view of a patch file that both format readers walk: comments stripped,
// blank lines dropped, each token with its 1-based line and column for error messages.
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "core/error.hpp"

namespace lancer::surface::detail {

struct Token {
    std::string_view text;
    int line = 0;
    int column = 0;
};

struct Record {  // one non-blank line
    int line = 0;
    int end_column = 0;  // just past the last character before any comment
    bool has_comma = false;
    std::vector<Token> tokens;
};

class PatchLexer {
public:
    PatchLexer(std::string_view text, std::string file_name);

    bool at_end() const { return next_ >= records_.size(); }
    std::size_t records_left() const { return records_.size() - next_; }
    // The next record; past the end it throws "file ends early: <what_was_expected>".
    const Record& next(const std::string& what_was_expected);
    const Record& peek() const { return records_[next_]; }
    void unread() {
        if (next_ > 0) --next_;
    }  // to look at a record before choosing its reader

    [[noreturn]] void fail(const Token& at, const std::string& message) const;
    [[noreturn]] void fail_at_end_of(const Record& r, const std::string& message) const;
    [[noreturn]] void fail_at_eof(const std::string& message) const;

    // Numbers: the whole token must be the number.
    long long whole_number(const Token& t, const std::string& what) const;
    double finite_number(const Token& t, const std::string& what) const;

private:
    std::string file_;
    std::vector<Record> records_;
    std::size_t next_ = 0;
    int eof_line_ = 1;
    int eof_column_ = 1;
};

}  // namespace lancer::surface::detail
