#pragma once
// Where a character of a TOML string value lies in its file. An expression's error has a
// column in the string's decoded text; escapes (\t, \u0075), triple quotes and multi-line
// strings put that character elsewhere in the file, so the position is found by walking the
// string's source text. The scene loader makes the file's text available while it parses.
#include <cstddef>
#include <string>
#include <string_view>

#include "core/error.hpp"

namespace lancer {

// While alive, source_text(file) returns `text` (on this thread): parse_scene holds one.
class SourceTextScope {
public:
    SourceTextScope(const std::string& file, std::string_view text);
    ~SourceTextScope();
    SourceTextScope(const SourceTextScope&) = delete;
    SourceTextScope& operator=(const SourceTextScope&) = delete;

private:
    const std::string* previous_file_;
    std::string_view previous_text_;
};

// The text of `file` if a SourceTextScope holds it, else an empty view.
std::string_view source_text(const std::string& file);

// The file position of byte `index` of the decoded value of the TOML string that starts (at
// its opening quote) at `value`. `text` is the whole file. If the text does not hold a string
// there, the position is guessed as one quote plus `index` columns after `value`.
SourceLocation position_in_string(std::string_view text, const SourceLocation& value, std::size_t index);

}  // namespace lancer
