#pragma once
// POV-Ray's colors.inc names ("Red", "SkyBlue", "Gray50", ...): a colour key may name one
// (docs/scene-format.md, "Numbers, names and loops").
#include <map>
#include <string>

#include <glm/vec3.hpp>

namespace lancer {

using glm::dvec3;

const std::map<std::string, dvec3, std::less<>>& pov_colors();

}  // namespace lancer
