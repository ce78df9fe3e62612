#pragma once
// Whether a triangle mesh is the boundary of a solid, and which side its triangles face: what CSG
// needs of a mesh operand (docs/scene-format.md, "CSG"). Exact, on the triangles themselves:
// every edge (between positions, compared bit for bit, as the readers weld them) must be shared
// by exactly two triangles that run it in opposite directions; the signed volume then says the
// side.
#include "mesh/triangle_mesh.hpp"

namespace lancer::mesh {

// +1 where the triangles' fronts (counter-clockwise) face out of the solid, -1 where in. Throws
// UserError saying why not: an edge of one triangle only (a hole), of three or more, or run the
// same way by two (an orientation that flips), or no volume enclosed.
int outward_side(const TriangleMesh& mesh);

}  // namespace lancer::mesh
