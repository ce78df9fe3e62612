#include "gpu/packing/float_anchor.hpp"

#include <cmath>

#include <fmt/format.h>
#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "scene/shape_bounds.hpp"
#include "scene/animation.hpp"
#include "scene/camera.hpp"
#include "scene/placement.hpp"

namespace lancer::gpu {
namespace {

// Float's relative precision (2^-24) times 64 steps: an object this small for its distance from
// the anchor is far below a pixel unless the field of view is tiny, when its shape would show
// float's steps.
constexpr double kMinExtentOverDistance = 0x1p-18;

}  // namespace

glm::dvec3 float_anchor(const CameraSpec& camera) { return working_origin(camera); }

Scene rebased(const Scene& scene, const glm::dvec3& anchor) {
    Scene local = scene;
    for (Object& o : local.objects) translate(o, -anchor);
    for (lancer::Light& l : local.lights) {
        l.position -= anchor;
        if (l.point_at) *l.point_at -= anchor;
    }
    local.camera.eye -= anchor;
    local.camera.look_at -= anchor;
    // A pattern's frame maps pattern space to the world: it now ends at the rebased world.
    auto move = [&](Pattern& p) { p.to_world[3] -= glm::dvec4(anchor, 0.0); };
    for (lancer::Material& m : local.materials) {
        if (m.pattern) move(*m.pattern);
        if (m.bump) move(m.bump->pattern);
        if (m.checker && m.checker->to_checker)  // so is a checker's (its inverse: taken from the rebased world)
            (*m.checker->to_checker)[3] = *m.checker->to_checker * glm::dvec4(anchor, 1.0);
    }
    return local;
}

glm::dvec3 checker_phase(const glm::dvec3& anchor, double size) {
    const double period = 2.0 * size;
    glm::dvec3 phase;
    for (int i = 0; i < 3; ++i) {
        phase[i] = std::fmod(anchor[i], period);
        if (phase[i] < 0.0) phase[i] += period;
    }
    return phase;
}

std::vector<std::string> float_resolution_notes(const Scene& scene, const glm::dvec3& anchor) {
    std::vector<std::string> notes;
    for (const Object& o : scene.objects) {
        const std::optional<Aabb> box = object_bounds(o);
        if (!box) continue;
        const double extent = glm::length(box->hi - box->lo);
        // Float's step is set by the largest coordinate the GPU holds for the object.
        const glm::dvec3 reach = glm::max(glm::abs(box->lo - anchor), glm::abs(box->hi - anchor));
        const double distance = std::max({reach.x, reach.y, reach.z});
        if (extent >= kMinExtentOverDistance * distance) continue;
        const std::string name = o.name.empty() ? "" : " '" + o.name.str() + "'";
        notes.push_back(fmt::format(
            "the object{} at {}:{} is {:.3g} across, {:.3g} from the camera (in its largest coordinate): the "
            "GPU's float arithmetic resolves only {:.3g} there, so its picture may be coarse; --backend cpu "
            "renders it in double",
            name, o.where.file.str(), o.where.line, extent, distance, distance * 0x1p-24));
    }
    return notes;
}

}  // namespace lancer::gpu
