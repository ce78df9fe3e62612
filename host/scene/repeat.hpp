#pragma once
// POV-Ray's #for on a table of the scene file: `repeat = { i = [first, last] }` reads the table
// once for each whole i from first to last, with i a name its numbers' expressions may use (an
// object, a group's member, a blob's component; docs/scene-format.md, "Numbers, names and loops").
#include <functional>
#include <string>

#include "scene/toml_reader.hpp"

namespace lancer {

// Where `t` has a repeat: `admit(copies, fail)` first (fail(message) reports at the repeat's
// index), then `body` for each copy, with the index bound; else `body(t)` once.
void read_repeated(TableReader& t, const std::function<void(double copies, const std::function<void(const std::string&)>& fail)>& admit,
                   const std::function<void(TableReader&)>& body);

}  // namespace lancer
