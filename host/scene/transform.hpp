#pragma once
// Affine transforms of objects, as written in scenes:
//   transform = { scale = 2, rotate = [-90, 0, 0], translate = [0, 0, 1] }
// applies scale, then rotate (about x, then y, then z, in degrees, as POV-Ray's rotate <x,y,z>),
// then translate; a list applies its entries in the order written:
//   transform = [ { translate = [1, 0, 0] }, { rotate = [0, 45, 0] } ]
#include <toml++/toml.h>

#include <glm/mat4x4.hpp>

#include "scene/toml_reader.hpp"

namespace lancer {

// Reads the optional `transform` key of an object table (identity when absent), after the
// transform of the groups the object is in (`parent`): the object's map to the world.
glm::dmat4 read_transform(TableReader& object, const glm::dmat4& parent = glm::dmat4(1.0));

glm::dmat4 rotation_degrees(const dvec3& angles);  // about x, then y, then z

}  // namespace lancer
