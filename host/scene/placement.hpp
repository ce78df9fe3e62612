#pragma once
// Puts an object where its `transform` says (docs/scene-format.md, "Transforms"): applied to
// the shape where the shape's family keeps its form under the map, else kept as the object's
// Placement, through which the renderers carry rays into the shape's own coordinates.
#include <glm/mat4x4.hpp>

#include "scene/scene.hpp"

namespace lancer {

// Sets o.placement for transform m (object -> world) and applies m to o.shape where that is
// exact. Bezier, parametric and implicit shapes have had m applied by their readers already:
// their placement only carries their patterns.
void place(Object& o, const glm::dmat4& m);

// Moves an object by `offset` in the world: its shape, or its placement where the shape keeps
// its own coordinates; patterns go with it.
void translate(Object& o, const dvec3& offset);

// The scale s where the linear part of m is s times a rotation (a proper one: no mirror), to
// double's rounding; 0 where it is not.
double similarity_scale(const glm::dmat4& m);

}  // namespace lancer
