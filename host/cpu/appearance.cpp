#include "cpu/appearance.hpp"

#include <glm/geometric.hpp>

#include "cpu/pattern.hpp"
#include "cpu/shapes/shapes.hpp"
#include "cpu/texture.hpp"

namespace lancer::cpu {

Appearance appearance_at(const Material& m, const Hit& hit, const dvec3& p, const dvec3& n) {
    // Checkers and patterns are fixed to the object: evaluated at its own coordinates.
    const HeapOptional<Placement>& placed = hit.object->placement;
    const dvec3 q = placed ? placed->object_point(p) : p;
    // A smooth mesh shades with its interpolated vertex normals; a bump tilts that.
    const auto* mesh = std::get_if<Mesh>(&hit.object->shape);
    Appearance a{pigment_at(m, q), mesh && mesh->smooth ? mesh_shading_normal(*mesh, *placed, hit.part, hit.uv, n) : n};
    if (m.texture) a.pigment *= texture_color(*m.texture, texture_uv(hit, p));
    if (m.pattern) a.pigment *= pattern_color(*m.pattern, q);
    if (m.bump) a.normal = bumped_normal(*m.bump, q, a.normal, placed ? glm::dmat3(placed->to_world) : glm::dmat3(1.0));
    return a;
}

dvec3 bounce_direction(const dvec3& d, const dvec3& shading_normal, const dvec3& geometric_normal) {
    dvec3 r = d - 2.0 * glm::dot(d, shading_normal) * shading_normal;
    double below = glm::dot(r, geometric_normal);
    return below < 0.0 ? r - 2.0 * below * geometric_normal : r;
}

}  // namespace lancer::cpu
