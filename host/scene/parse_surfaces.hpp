#pragma once
// Readers of the surface object types: "bezier" (patch sets, inline or from a patch file) and
// "parametric" (equations in u and v). Registered in shape_readers() (parse_shapes.cpp).
#include "scene/scene.hpp"
#include "scene/toml_reader.hpp"

namespace lancer {

Shape read_bezier(TableReader& t);
Shape read_parametric(TableReader& t);

}  // namespace lancer
