#pragma once
// Whether a surface of patches encloses a solid, and which side its normals face: what CSG needs
// of a parametric or Bezier surface that the user declares closed (docs/scene-format.md, "CSG").
// Judged from samples: a grid of points per patch, whose boundary segments must pair up edge to
// edge, each with one running the other way (a consistent orientation), or shrink to a point (a
// pole); the signed volume of the grids' triangles then says the side. A hole narrower than the
// samples' spacing goes unseen; edges that meet only in part (a T-junction) are refused.
#include <vector>

#include <glm/vec3.hpp>

namespace lancer::surface {

using glm::dvec3;

// An (n + 1) x (n + 1) grid of a patch's points, points[i * (n + 1) + j] at the i-th u and j-th v,
// both from the patch's start to its end.
struct SampledPatch {
    int n = 0;
    std::vector<dvec3> points;
};

// +1 where the normals (the direction of S_u x S_v) point out of the solid, -1 where in. Throws
// UserError saying why not where the samples show an edge that no other meets, two patches
// that disagree in orientation, or no volume enclosed.
int outward_side(const std::vector<SampledPatch>& patches);

}  // namespace lancer::surface
