#include "gpu/scene_packing.hpp"

#include "scene/camera.hpp"

namespace lancer::gpu {
namespace {

vec4 v4(const dvec3& v, double w = 0.0) { return vec4(float(v.x), float(v.y), float(v.z), float(w)); }

struct PrimitivePacker {
    std::uint32_t material;
    Primitive operator()(const Sphere& s) const { return {SHAPE_SPHERE, material, 0, 0, v4(s.center, s.radius), {}, {}}; }
    Primitive operator()(const Plane& p) const { return {SHAPE_PLANE, material, 0, 0, v4(p.point), v4(p.normal), {}}; }
    Primitive operator()(const Rectangle& r) const {
        return {SHAPE_RECTANGLE, material, 0, 0, v4(r.corner), v4(r.edge_u), v4(r.edge_v)};
    }
    Primitive operator()(const Box& b) const { return {SHAPE_BOX, material, 0, 0, v4(b.min), v4(b.max), {}}; }
};

}  // namespace

PackedScene pack_scene(const Scene& scene) {
    PackedScene packed;
    for (const Object& o : scene.objects) packed.primitives.push_back(std::visit(PrimitivePacker{o.material}, o.shape));
    for (const lancer::Material& m : scene.materials) {
        Material g{};
        g.color = v4(m.checker ? m.checker->color_a : m.color);
        g.color2 = v4(m.checker ? m.checker->color_b : m.color);
        g.phong = vec4(float(m.ambient), float(m.diffuse), float(m.specular), float(m.shininess));
        g.reflection = float(m.reflection);
        g.pattern = m.checker ? PATTERN_CHECKER : PATTERN_SOLID;
        g.checker_size = m.checker ? float(m.checker->size) : 1.0f;
        packed.materials.push_back(g);
    }
    for (const PointLight& l : scene.lights) packed.lights.push_back({v4(l.position), v4(l.color)});
    return packed;
}

FrameParams pack_frame(const Scene& scene) {
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
    f.primitive_count = static_cast<uint>(scene.objects.size());
    f.light_count = static_cast<uint>(scene.lights.size());
    return f;
}

}  // namespace lancer::gpu
