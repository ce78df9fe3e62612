#pragma once
// One reader per [[object]] type: its keys, their defaults and their checks live here, in one
// function per type.
#include <functional>
#include <map>
#include <string>

#include "scene/scene.hpp"
#include "scene/toml_reader.hpp"

namespace lancer {

using ShapeReader = std::function<Shape(TableReader&)>;

// Reads edge_u and edge_v of a parallelogram (a rectangle, an area light): non-zero and not
// parallel; `what` names it in messages.
void read_edges(TableReader& t, const std::string& what, dvec3& edge_u, dvec3& edge_v);

// Object type name -> reader, e.g. "sphere" -> read_sphere.
const std::map<std::string, ShapeReader, std::less<>>& shape_readers();

}  // namespace lancer
