#pragma once
// A look-at camera reduced to what ray generation needs. Both renderers form the ray through
// image point (ndc_x, ndc_y) in [-1, 1]^2 (y up) as normalize(forward + ndc_x*right + ndc_y*up).
#include <glm/vec3.hpp>

#include "scene/scene.hpp"

namespace lancer {

struct CameraBasis {
    dvec3 eye;
    dvec3 forward;  // unit
    dvec3 right;    // unit right * tan(fov/2) * aspect
    dvec3 up;       // unit up * tan(fov/2)
};

// Builds the orthonormal basis from eye, look_at and up. Throws UserError when eye == look_at,
// up is zero or up is parallel to the view direction (the picture would be undefined).
CameraBasis make_camera_basis(const CameraSpec& spec, int width, int height);

// The point a renderer's working coordinates start from: the world origin while the eye is within
// kWorkingOriginRadius of it on every axis, else the eye. Secondary-ray offsets scale with the
// distance from it (both backends), and the GPU's float coordinates are relative to it: a scene
// moved far from the origin, camera and lights with it, renders the picture it renders there.
// (Near the origin the world frame is kept: pictures stay what they were, and an animation that
// only moves the camera keeps its BVH.)
constexpr double kWorkingOriginRadius = 1024.0;
dvec3 working_origin(const CameraSpec& camera);

// Direction (not normalised) through the continuous image position (sx, sy), in pixels from the
// top-left corner of the image.
dvec3 camera_ray_direction(const CameraBasis& cam, double sx, double sy, int width, int height);

}  // namespace lancer
