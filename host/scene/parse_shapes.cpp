#include "scene/parse_shapes.hpp"

#include "scene/parse_material_maps.hpp"
#include "scene/parse_surfaces.hpp"
#include "scene/transform.hpp"

#include <algorithm>

#include <fmt/format.h>
#include <glm/geometric.hpp>

namespace lancer {

void read_edges(TableReader& t, const std::string& what, dvec3& edge_u, dvec3& edge_v) {
    edge_u = t.required_vec3("edge_u");
    edge_v = t.required_vec3("edge_v");
    double lu = glm::length(edge_u), lv = glm::length(edge_v);
    if (!(lu > 0.0)) t.fail("edge_u", what + " edge_u must not be the zero vector");
    if (!(lv > 0.0)) t.fail("edge_v", what + " edge_v must not be the zero vector");
    if (glm::length(glm::cross(edge_u, edge_v)) <= 1e-9 * lu * lv)
        t.fail("edge_v", what + " edges are parallel: the " + what + " has no area");
}

namespace {

Shape read_sphere(TableReader& t) {
    Sphere s;
    s.center = t.required_vec3("center");
    s.radius = t.required_number("radius");
    if (!(s.radius > 0.0)) t.fail("radius", fmt::format("sphere radius must be positive, not {:g}", s.radius));
    s.orientation = glm::dmat3(rotation_degrees(t.vec3("rotate", dvec3(0.0))));
    return s;
}

Shape read_plane(TableReader& t) {
    Plane p;
    p.point = t.vec3("point", dvec3(0.0));
    dvec3 n = t.required_vec3("normal");
    if (!(glm::length(n) > 0.0)) t.fail("normal", "plane normal must not be the zero vector");
    p.normal = glm::normalize(n);
    set_plane_texture_axes(p);
    return p;
}

Shape read_rectangle(TableReader& t) {
    Rectangle r;
    r.corner = t.required_vec3("corner");
    read_edges(t, "rectangle", r.edge_u, r.edge_v);
    return r;
}

Shape read_box(TableReader& t) {
    Box b;
    b.min = t.required_vec3("min");
    b.max = t.required_vec3("max");
    for (int i = 0; i < 3; ++i)
        if (!(b.min[i] < b.max[i])) t.fail("max", "box max must be greater than min on every axis");
    return b;
}

// POV-Ray's disc { center, normal, radius [, hole_radius] }, with its names.
Shape read_disc(TableReader& t) {
    Disc d;
    d.center = t.required_vec3("center");
    dvec3 n = t.required_vec3("normal");
    if (!(glm::length(n) > 0.0)) t.fail("normal", "disc normal must not be the zero vector");
    d.normal = glm::normalize(n);
    d.radius = t.required_number("radius");
    if (!(d.radius > 0.0)) t.fail("radius", fmt::format("disc radius must be positive, not {:g}", d.radius));
    d.hole_radius = t.number("hole_radius", 0.0);
    if (!(d.hole_radius >= 0.0))
        t.fail("hole_radius", fmt::format("disc hole_radius must not be negative, not {:g}", d.hole_radius));
    if (!(d.hole_radius < d.radius))
        t.fail("hole_radius", fmt::format("disc hole_radius ({:g}) must be less than its radius ({:g}): the disc "
                                          "would have no surface",
                                          d.hole_radius, d.radius));
    Plane axes;  // the texture's angle starts at the plane's u axis for this normal
    axes.normal = d.normal;
    set_plane_texture_axes(axes);
    d.u_axis = axes.u_axis;
    d.v_axis = axes.v_axis;
    return d;
}

// POV-Ray's torus { major, minor }, with a centre and an axis in place of its transforms.
Shape read_torus(TableReader& t) {
    Torus o;
    o.center = t.vec3("center", dvec3(0.0));
    dvec3 a = t.vec3("axis", dvec3(0.0, 1.0, 0.0));
    if (!(glm::length(a) > 0.0)) t.fail("axis", "torus axis must not be the zero vector");
    o.axis = glm::normalize(a);
    o.major_radius = t.required_number("major_radius");
    if (!(o.major_radius > 0.0))
        t.fail("major_radius", fmt::format("torus major_radius must be positive, not {:g}", o.major_radius));
    o.minor_radius = t.required_number("minor_radius");
    if (!(o.minor_radius > 0.0))
        t.fail("minor_radius", fmt::format("torus minor_radius must be positive, not {:g}", o.minor_radius));
    // Float's shader scales the torus by R + r: radii 10^7 apart would leave the smaller one
    // below float's resolution of the larger (a thread or a sphere, not a torus).
    const double ratio = std::max(o.major_radius, o.minor_radius) / std::min(o.major_radius, o.minor_radius);
    if (!(ratio <= 1e6))
        t.fail("minor_radius", fmt::format("torus radii {:g} and {:g} are more than 10^6 apart", o.major_radius, o.minor_radius));
    Plane axes;  // the texture's angle about the axis starts at the plane's u axis for it
    axes.normal = o.axis;
    set_plane_texture_axes(axes);
    o.u_axis = axes.u_axis;
    o.v_axis = axes.v_axis;
    return o;
}

}  // namespace

const std::map<std::string, ShapeReader, std::less<>>& shape_readers() {
    static const std::map<std::string, ShapeReader, std::less<>> readers = {
        {"sphere", read_sphere},
        {"plane", read_plane},
        {"rectangle", read_rectangle},
        {"box", read_box},
        {"bezier", read_bezier},
        {"parametric", read_parametric},
        {"implicit", read_implicit},
        {"disc", read_disc},
        {"torus", read_torus},
    };
    return readers;
}

}  // namespace lancer
