#pragma once
// Names in messages come from users: a texture file name, an object's name, a key, a path on
// the command line. A control character in one (an escape sequence, a carriage return, a NUL)
// must not reach the terminal as itself: it could rewrite the line, hide the message or, for a
// newline, split one error into two.
#include <string>
#include <string_view>

namespace lancer {

// `text` with every control character (below 0x20, and 0x7f) written as a C escape: \n, \r,
// \t, \0, or \xHH. Other bytes (UTF-8 included) are kept. With keep_newlines, '\n' stays a
// line break (messages that are several lines on purpose, such as a compiler's log).
std::string escape_control_characters(std::string_view text, bool keep_newlines = false);

}  // namespace lancer
