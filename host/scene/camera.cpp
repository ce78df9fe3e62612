#include "scene/camera.hpp"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

namespace lancer {

CameraBasis make_camera_basis(const CameraSpec& spec, int width, int height) {
    dvec3 view = spec.look_at - spec.eye;
    double view_len = glm::length(view);
    if (!(view_len > 0.0)) throw UserError("camera: eye and look_at are the same point");
    double up_len = glm::length(spec.up);
    if (!(up_len > 0.0)) throw UserError("camera: up vector is zero");
    dvec3 forward = view / view_len;
    // Left-handed, as POV-Ray and pbrt: +x right, +y up, +z into the screen for the default view.
    dvec3 side = glm::cross(spec.up / up_len, forward);
    // sin of the angle between up and the view direction; below ~0.06 degrees the basis is noise.
    if (glm::length(side) < 1e-6)
        throw UserError("camera: up vector is parallel to the view direction (eye -> look_at)");
    dvec3 right = glm::normalize(side);
    dvec3 true_up = glm::cross(forward, right);
    double tan_half = std::tan(spec.fov_deg * M_PI / 360.0);
    double aspect = double(width) / double(height);
    return {spec.eye, forward, right * (tan_half * aspect), true_up * tan_half};
}

dvec3 camera_ray_direction(const CameraBasis& cam, double sx, double sy, int width, int height) {
    double ndc_x = 2.0 * sx / width - 1.0;
    double ndc_y = 1.0 - 2.0 * sy / height;
    return cam.forward + ndc_x * cam.right + ndc_y * cam.up;
}

dvec3 working_origin(const CameraSpec& camera) {
    const dvec3& e = camera.eye;
    const double reach = std::max({std::abs(e.x), std::abs(e.y), std::abs(e.z)});
    return reach >= kWorkingOriginRadius ? e : dvec3(0.0);
}

}  // namespace lancer
