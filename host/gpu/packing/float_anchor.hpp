#pragma once
// The GPU computes in float, whose precision is relative to a coordinate's magnitude: a scene
// placed 10^6 from the world origin would keep only about 0.06 of a unit there. So everything the
// GPU sees is rebased, in double, on an anchor point near the camera before it is rounded to
// float: precision then follows the distance from the camera, as what the picture needs does.
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "scene/scene.hpp"

namespace lancer::gpu {

// The point the GPU's coordinates are relative to: the scene's working origin (scene/camera.hpp:
// the world origin near it, where float resolves 6e-5 or better, else the eye).
glm::dvec3 float_anchor(const CameraSpec& camera);

// The scene with every position moved by -anchor: shapes, lights, the camera, and the
// patterns' frames, so that the rebased scene looks the same. (Solid checkers depend on world
// coordinates too: the packer gives each its phase, checker_phase.)
Scene rebased(const Scene& scene, const glm::dvec3& anchor);

// Where `anchor` is in a solid checker of cells of `size`: anchor modulo twice the size (the
// checker's period), in [0, 2 size) per axis. floor((p + phase) / size) then has the parity of
// floor((p + anchor) / size) for any p.
glm::dvec3 checker_phase(const glm::dvec3& anchor, double size);

// Objects too small for float at their distance from the anchor (their extent spans fewer than
// 64 float steps there): one line each naming the object, for the renderer's notes.
std::vector<std::string> float_resolution_notes(const Scene& scene, const glm::dvec3& anchor);

}  // namespace lancer::gpu
