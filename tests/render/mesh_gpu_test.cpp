// Triangle meshes on the device: shaders/shapes/mesh.glsl is watertight. Rays through every
// vertex and every edge's midpoint of closed convex meshes (in the GPU's own floats, where a
// non-watertight test lets rays slip between triangles), from outside toward a point inside,
// meet the mesh at exactly two distances (two triangles sharing the point may both report it,
// at one distance: that is no double hit). Every triangle is tested (no BVH), so the answer is
// the intersector's alone.
#include <filesystem>
#include <random>
#include <set>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/matrix.hpp>
#include <gtest/gtest.h>

#include "gpu/packing/scene_packing.hpp"
#include "scene/load_scene.hpp"
#include "support/gpu_kernel.hpp"
#include "support/test_meshes.hpp"
#include "support/test_support.hpp"

namespace lancer {
namespace {

using glm::dvec3;
using glm::vec3;
using glm::vec4;

// In: pixels[2i] = (origin, 0), pixels[2i + 1] = (direction, 0). Out: pixels[2i] = (hits, the
// two smallest distinct t, the number of distinct ones).
const char* kWatertightKernel = R"(#version 450
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_control_flow_attributes : require
#include "interface.glsl"
layout(local_size_x = 1) in;
#include "common.glsl"
#include "scene.glsl"

void main() {
    uint i = gl_GlobalInvocationID.x;
    Ray ray = Ray(pixels[2u * i].xyz, pixels[2u * i + 1u].xyz);
    float ts[8];
    uint distinct = 0u, hits = 0u;
    for (uint k = 0u; k < frame.primitive_count; ++k) {
        float t;
        vec2 uv = vec2(0.0);
        float error = 0.0;
        if (!mesh_intersect(primitive_at(k), ray, 0.0, 1e30, t, uv, error)) continue;
        ++hits;
        bool seen = false;
        for (uint j = 0u; j < min(distinct, 8u); ++j) seen = seen || abs(ts[j] - t) <= 1e-5 * t;
        if (!seen && distinct < 8u) ts[distinct++] = t;
        else if (!seen) ++distinct;
    }
    float first = 1e30, second = 1e30;
    for (uint j = 0u; j < min(distinct, 8u); ++j) {
        if (ts[j] < first) { second = first; first = ts[j]; }
        else if (ts[j] < second) second = ts[j];
    }
    pixels[2u * i] = vec4(float(hits), first, second, float(distinct));
}
)";

void expect_watertight_on_device(const TriangleMesh& mesh, const glm::dmat4& to_world, const dvec3& inside) {
    Scene scene = test::scene_from_text("[camera]\neye = [0, 0.5, 6]\nlook_at = [0, 0, 0]\n[[light]]\nposition = [2, 3, 4]\n"
                                        "[[object]]\ntype = \"sphere\"\ncenter = [0, 0, 0]\nradius = 1\n");
    Mesh m;
    m.geometry = std::make_shared<const MeshGeometry>(mesh);
    m.to_world = to_world;
    m.to_object = glm::inverse(to_world);
    scene.objects[0].shape = m;
    gpu::PackOptions options;
    options.acceleration = Acceleration::BruteForce;
    const gpu::PackedScene packed = gpu::pack_scene(scene, options);
    const gpu::FrameParams frame = gpu::pack_frame(scene, packed);
    const vec3 centre = vec3(inside - packed.anchor);

    std::mt19937 rng(99);
    std::uniform_real_distribution<float> jitter(-0.05f, 0.05f);
    std::vector<vec4> io;
    for (const gpu::Primitive& p : packed.primitives) {
        const vec3 v[3] = {vec3(p.p0), vec3(p.p1), vec3(p.p2)};
        for (int k = 0; k < 3; ++k)
            for (const vec3 aim : {v[k], 0.5f * (v[k] + v[(k + 1) % 3])}) {
                const vec3 origin = centre + 3.0f * (aim - centre) + vec3(jitter(rng), jitter(rng), jitter(rng));
                io.push_back(vec4(origin, 0.0f));
                io.push_back(vec4(glm::normalize(aim - origin), 0.0f));
            }
    }
    const auto rays = static_cast<std::uint32_t>(io.size() / 2);
    test::GpuKernel kernel(kWatertightKernel, "", packed.features);
    const std::vector<vec4> out = kernel.run(packed, frame, io, rays);
    int failures = 0;
    for (std::uint32_t i = 0; i < rays; ++i) {
        const vec4 r = out[2 * i];
        if (r.w == 2.0f) continue;
        if (++failures <= 5)
            ADD_FAILURE() << "ray " << i << " toward (" << io[2 * i + 1].x << ", " << io[2 * i + 1].y << ", " << io[2 * i + 1].z
                          << "): " << r.x << " hits at " << r.w << " distances";
    }
    EXPECT_EQ(failures, 0) << "of " << rays << " rays";
}

TEST(MeshOnDevice, ClosedMeshesAreWatertightAtTheirVerticesAndEdges) {
    expect_watertight_on_device(test::icosphere(3), glm::dmat4(1.0), dvec3(0.01, 0.02, -0.03));
    expect_watertight_on_device(test::uv_sphere(12), glm::dmat4(1.0), dvec3(0.01, 0.02, -0.03));
    const glm::dmat4 placed = glm::translate(glm::dmat4(1.0), dvec3(30, -20, 50)) *
                              glm::rotate(glm::dmat4(1.0), 0.7, dvec3(1, 2, 3)) * glm::scale(glm::dmat4(1.0), dvec3(2.0, 0.5, 1.5));
    expect_watertight_on_device(test::icosphere(2), placed, dvec3(30, -20, 50));
}

// The benchmark's bunny (69,451 triangles from ../shared/models, smooth) and its glass twin
// (refraction through a scanned mesh), small, on both backends. The glass is compared
// up to its second bounce: deeper paths through the scan's thousands of small facets are chaotic
// at float's scale (measured: the CPU reference itself, with the bunny moved by 1e-5, the size of
// the GPU's error bounds there, changes 0.26% of the pixels by more than 4/255 at 3 bounces and
// 0.64% at 8 with a move of 1e-6; at 2 bounces the backends differ on 0.04%).
TEST(MeshOnDevice, TheStanfordBunnyIsTheSameOnBothBackends) {
    if (!std::filesystem::exists(test::source_path("../shared/models/stanford-bunny.obj")))
        GTEST_SKIP() << "../shared/models/stanford-bunny.obj is not beside the repository";
    for (const char* name : {"bunny", "bunny_glass"}) {
        Scene scene = load_scene(test::source_path(std::string("bench/") + name + ".toml"));
        scene.render.width = 96;
        scene.render.height = 54;
        scene.render.samples = 2;
        if (scene.photons) {  // the glass: its caustic's few photons through the chaotic paths would differ too
            scene.render.max_depth = 2;
            scene.photons.reset();
        }
        test::expect_same_picture(name, to_srgb8(test::render_on(test::Backend::Gpu, scene)),
                                  to_srgb8(test::render_on(test::Backend::Cpu, scene)));
    }
}

}  // namespace
}  // namespace lancer
