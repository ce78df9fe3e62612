#include "gpu/scene_packing.hpp"

#include <cmath>
#include <limits>
#include <optional>

#include "accel/bvh.hpp"
#include "accel/shape_bounds.hpp"
#include "scene/camera.hpp"

namespace lancer::gpu {
namespace {

// With this few bounded primitives, testing them all beats traversing a tree (measured on
// lavapipe: the BVH loop's stack and divergence cost more than a handful of sphere tests).
constexpr std::size_t kMinPrimitivesForBvh = 16;

vec4 v4(const dvec3& v, double w = 0.0) { return vec4(float(v.x), float(v.y), float(v.z), float(w)); }

struct PrimitivePacker {
    uint material;
    uint object;
    Primitive operator()(const Sphere& s) const { return {SHAPE_SPHERE, material, 0, object, v4(s.center, s.radius), {}, {}}; }
    Primitive operator()(const Plane& p) const { return {SHAPE_PLANE, material, 0, object, v4(p.point), v4(p.normal), {}}; }
    Primitive operator()(const Rectangle& r) const {
        return {SHAPE_RECTANGLE, material, 0, object, v4(r.corner), v4(r.edge_u), v4(r.edge_v)};
    }
    Primitive operator()(const Box& b) const { return {SHAPE_BOX, material, 0, object, v4(b.min), v4(b.max), {}}; }
};

Material pack_material(const lancer::Material& m) {
    Material g{};
    g.color = v4(m.checker ? m.checker->color_a : m.color);
    g.color2 = v4(m.checker ? m.checker->color_b : m.color);
    g.phong = vec4(float(m.ambient), float(m.diffuse), float(m.specular), float(m.shininess));
    g.reflection = float(m.reflection);
    g.pattern = m.checker ? PATTERN_CHECKER : PATTERN_SOLID;
    g.checker_size = m.checker ? float(m.checker->size) : 1.0f;
    return g;
}

}  // namespace

float round_down(double x) {
    float f = static_cast<float>(x);
    return static_cast<double>(f) > x ? std::nextafter(f, -std::numeric_limits<float>::infinity()) : f;
}

float round_up(double x) {
    float f = static_cast<float>(x);
    return static_cast<double>(f) < x ? std::nextafter(f, std::numeric_limits<float>::infinity()) : f;
}

PackedScene pack_scene(const Scene& scene, Acceleration acceleration) {
    PackedScene packed;
    std::vector<Primitive> bounded, unbounded;
    std::vector<Aabb> boxes;
    for (std::size_t i = 0; i < scene.objects.size(); ++i) {
        const Object& o = scene.objects[i];
        Primitive p = std::visit(PrimitivePacker{o.material, static_cast<uint>(i)}, o.shape);
        std::optional<Aabb> box;
        if (acceleration == Acceleration::Bvh && scene.objects.size() >= kMinPrimitivesForBvh) box = shape_bounds(o.shape);
        if (box) {
            bounded.push_back(p);
            boxes.push_back(*box);
        } else {
            unbounded.push_back(p);
        }
    }
    Bvh bvh = build_bvh(boxes);
    for (std::uint32_t index : bvh.order) packed.primitives.push_back(bounded[index]);
    packed.primitives.insert(packed.primitives.end(), unbounded.begin(), unbounded.end());
    packed.unbounded_count = static_cast<uint>(unbounded.size());
    for (const lancer::BvhNode& n : bvh.nodes) {
        gpu::BvhNode g{};
        g.lo = vec4(round_down(n.box.lo.x), round_down(n.box.lo.y), round_down(n.box.lo.z), 0.0f);
        g.hi = vec4(round_up(n.box.hi.x), round_up(n.box.hi.y), round_up(n.box.hi.z), 0.0f);
        g.first = n.first;
        g.count = n.count;
        packed.nodes.push_back(g);
    }
    for (const lancer::Material& m : scene.materials) packed.materials.push_back(pack_material(m));
    for (const PointLight& l : scene.lights) packed.lights.push_back({v4(l.position), v4(l.color)});
    return packed;
}

FrameParams pack_frame(const Scene& scene, const PackedScene& packed) {
    const RenderSettings& r = scene.render;
    CameraBasis cam = make_camera_basis(scene.camera, r.width, r.height);
    FrameParams f{};
    f.eye = v4(cam.eye);
    f.forward = v4(cam.forward);
    f.right = v4(cam.right);
    f.up = v4(cam.up);
    f.background = v4(r.background);
    f.ambient = v4(scene.ambient);
    f.width = static_cast<uint>(r.width);
    f.height = static_cast<uint>(r.height);
    f.samples = static_cast<uint>(r.samples);
    f.max_depth = static_cast<uint>(r.max_depth);
    f.primitive_count = static_cast<uint>(packed.primitives.size());
    f.light_count = static_cast<uint>(packed.lights.size());
    f.node_count = static_cast<uint>(packed.nodes.size());
    f.unbounded_count = packed.unbounded_count;
    return f;
}

}  // namespace lancer::gpu
