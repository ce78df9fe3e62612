#pragma once
// Readers of the surface object types: "bezier" (patch sets, inline or from a patch file) and,
// with them, their shared pieces. Registered in shape_readers() (parse_shapes.cpp).
#include "scene/scene.hpp"
#include "scene/toml_reader.hpp"

namespace lancer {

Shape read_bezier(TableReader& t);

}  // namespace lancer
