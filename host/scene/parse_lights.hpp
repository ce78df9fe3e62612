#pragma once
// [[light]] tables: the light types (point, spot, area), their keys, defaults and checks in one
// place (docs/scene-format.md, "[[light]]").
#include "scene/scene.hpp"
#include "scene/toml_reader.hpp"

namespace lancer {

Light read_light(TableReader& t);

}  // namespace lancer
