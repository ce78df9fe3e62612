#pragma once
// Where two TOML trees differ, node by node: keys, types, values (floats bit for bit), flags,
// inline-ness and source regions (lines, columns, the path and whether it is the root's shared
// path, which the batch reader's locations rely on). The plain TOML reader's tests and fuzz
// entry compare its trees with toml::parse's by it.
#include <string>

#include <toml++/toml.h>

namespace lancer::fuzz {

// "" where `actual` equals `expected`; otherwise the first difference, with its key path.
std::string toml_tree_difference(const toml::table& expected, const toml::table& actual);

}  // namespace lancer::fuzz
