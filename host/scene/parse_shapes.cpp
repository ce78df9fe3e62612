#include "scene/parse_shapes.hpp"

#include "scene/parse_material_maps.hpp"
#include "scene/parse_surfaces.hpp"
#include "scene/transform.hpp"

#include <algorithm>
#include <cmath>

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

Shape read_sphere(TableReader& t, const glm::dmat4&) {
    Sphere s;
    s.center = t.required_vec3("center");
    s.radius = t.required_number("radius");
    if (!(s.radius > 0.0)) t.fail("radius", fmt::format("sphere radius must be positive, not {:g}", s.radius));
    s.orientation = glm::dmat3(rotation_degrees(t.vec3("rotate", dvec3(0.0))));
    return s;
}

Shape read_plane(TableReader& t, const glm::dmat4&) {
    Plane p;
    p.point = t.vec3("point", dvec3(0.0));
    dvec3 n = t.required_vec3("normal");
    if (!(glm::length(n) > 0.0)) t.fail("normal", "plane normal must not be the zero vector");
    p.normal = glm::normalize(n);
    set_plane_texture_axes(p);
    return p;
}

Shape read_rectangle(TableReader& t, const glm::dmat4&) {
    Rectangle r;
    r.corner = t.required_vec3("corner");
    read_edges(t, "rectangle", r.edge_u, r.edge_v);
    return r;
}

Shape read_box(TableReader& t, const glm::dmat4&) {
    Box b;
    b.min = t.required_vec3("min");
    b.max = t.required_vec3("max");
    for (int i = 0; i < 3; ++i)
        if (!(b.min[i] < b.max[i])) t.fail("max", "box max must be greater than min on every axis");
    return b;
}

// POV-Ray's disc { center, normal, radius [, hole_radius] }, with its names.
Shape read_disc(TableReader& t, const glm::dmat4&) {
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

// The ends of a cone or cylinder (POV-Ray's base and cap points) and the texture's axes about
// them. The axis must be long enough for its direction to be known from the coordinates: more
// than 1e-9 of their magnitude (a shorter one is refused as zero).
void read_cone_axis(TableReader& t, const std::string& what, Cone& c) {
    c.base = t.required_vec3("base_point");
    c.cap = t.required_vec3("cap_point");
    const dvec3 axis = c.cap - c.base;
    const double scale = std::max({std::abs(c.base.x), std::abs(c.base.y), std::abs(c.base.z), std::abs(c.cap.x),
                                   std::abs(c.cap.y), std::abs(c.cap.z)});
    if (!(glm::length(axis) > 1e-9 * scale))
        t.fail("cap_point", what + " cap_point must differ from base_point: the " + what + " has no axis");
    c.open = t.boolean("open", false);
    Plane axes;  // the texture's angle starts at the plane's u axis for the axis as a normal
    axes.normal = glm::normalize(axis);
    set_plane_texture_axes(axes);
    c.u_axis = axes.u_axis;
    c.v_axis = axes.v_axis;
}

// POV-Ray's cylinder { base, cap, radius [open] }, with its names.
Shape read_cylinder(TableReader& t, const glm::dmat4&) {
    Cone c;
    read_cone_axis(t, "cylinder", c);
    const double r = t.required_number("radius");
    if (!(r > 0.0)) t.fail("radius", fmt::format("cylinder radius must be positive, not {:g}", r));
    c.base_radius = c.cap_radius = r;
    return c;
}

// POV-Ray's cone { base, base_radius, cap, cap_radius [open] }: one radius may be 0 (a point).
Shape read_cone(TableReader& t, const glm::dmat4&) {
    Cone c;
    read_cone_axis(t, "cone", c);
    c.base_radius = t.required_number("base_radius");
    if (!(c.base_radius >= 0.0))
        t.fail("base_radius", fmt::format("cone base_radius must not be negative, not {:g}", c.base_radius));
    c.cap_radius = t.required_number("cap_radius");
    if (!(c.cap_radius >= 0.0))
        t.fail("cap_radius", fmt::format("cone cap_radius must not be negative, not {:g}", c.cap_radius));
    if (!(c.base_radius > 0.0 || c.cap_radius > 0.0))
        t.fail("cap_radius", "cone base_radius and cap_radius must not both be 0: the cone would be a line");
    return c;
}

// POV-Ray's torus { major, minor }, with a centre and an axis in place of its transforms.
Shape read_torus(TableReader& t, const glm::dmat4&) {
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
        {"superellipsoid", read_superellipsoid},
        {"blob", read_blob},
        {"sor", read_sor},
        {"text", read_text},
        {"prism", read_prism},
        {"lathe", read_lathe},
        {"disc", read_disc},
        {"cylinder", read_cylinder},
        {"cone", read_cone},
        {"torus", read_torus},
        {"mesh", read_mesh},
        {"spheres", read_spheres},
    };
    return readers;
}

}  // namespace lancer
