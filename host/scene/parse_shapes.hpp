#pragma once
// One reader per [[object]] type: its keys, their defaults and their checks live here, in one
// function per type.
#include <functional>
#include <map>
#include <string>

#include <glm/mat4x4.hpp>

#include "scene/scene.hpp"
#include "scene/toml_reader.hpp"

namespace lancer {

// A reader gets the object's table and its map to the world (its `transform` after its groups'):
// the surfaces apply it to their own definitions; the placement of the others follows (place()).
using ShapeReader = std::function<Shape(TableReader&, const glm::dmat4& to_world)>;

// Reads edge_u and edge_v of a parallelogram (a rectangle, an area light): non-zero and not
// parallel; `what` names it in messages.
void read_edges(TableReader& t, const std::string& what, dvec3& edge_u, dvec3& edge_v);

// Object type name -> reader, e.g. "sphere" -> read_sphere.
const std::map<std::string, ShapeReader, std::less<>>& shape_readers();

}  // namespace lancer
