// Triangle meshes on the device: shaders/shapes/mesh.glsl is watertight. Rays through every
// vertex and every edge's midpoint of closed convex meshes (in the GPU's own floats, where a
// non-watertight test lets rays slip between triangles), from outside toward a point inside,
// meet the mesh at exactly two distances (two triangles sharing the point may both report it,
// at one distance: that is no double hit). The mesh's own intersector answers, through its
// object's frame, each crossing found again from just past the last.
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

// In: pixels[2i] = (origin, 0), pixels[2i + 1] = (direction, 0). Out: pixels[2i] = (0, the
// first two crossings' t, the number of crossings).
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
    float ts[2] = float[2](1e30, 1e30);
    uint crossings = 0u;
    float t_min = 0.0;
    Primitive p = primitive_at(0u);
    for (uint k = 0u; k < 8u; ++k) {
        float t, error;
        vec2 uv;
        if (!shape_intersect(SHAPE_MESH, p, ray, t_min, 1e30, true, t, uv, error)) break;
        if (crossings < 2u) ts[crossings] = t;
        ++crossings;
        t_min = t * (1.0 + 1e-5);  // past every triangle meeting there, far short of the next crossing
    }
    pixels[2u * i] = vec4(0.0, ts[0], ts[1], float(crossings));
}
)";

void expect_watertight_on_device(const TriangleMesh& mesh, const glm::dmat4& to_world, const dvec3& inside) {
    Scene scene = test::scene_from_text("[camera]\neye = [0, 0.5, 6]\nlook_at = [0, 0, 0]\n[[light]]\nposition = [2, 3, 4]\n"
                                        "[[object]]\ntype = \"sphere\"\ncenter = [0, 0, 0]\nradius = 1\n");
    Mesh m;
    m.geometry = std::make_shared<const MeshGeometry>(mesh);
    scene.objects[0].shape = m;
    scene.objects[0].placement = Placement{to_world, glm::inverse(to_world), true};
    const gpu::PackedScene packed = gpu::pack_scene(scene);
    const gpu::FrameParams frame = gpu::pack_frame(scene, packed);
    const vec3 centre = vec3(inside - packed.anchor);

    std::mt19937 rng(99);
    std::uniform_real_distribution<float> jitter(-0.05f, 0.05f);
    std::vector<vec4> io;
    // Aimed at the vertices as the GPU's frame maps its floats to the world (in double).
    const glm::dmat4 gpu_world = glm::translate(glm::dmat4(1.0), -packed.anchor) * to_world;
    for (const gpu::MeshTriangle& tr : packed.mesh_triangles) {
        vec3 v[3];
        for (int k = 0; k < 3; ++k) {
            const vec4& local = k == 0 ? tr.v0 : k == 1 ? tr.v1 : tr.v2;
            v[k] = vec3(dvec3(gpu_world * glm::dvec4(dvec3(vec3(local)), 1.0)));
        }
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
                          << "): " << r.w << " crossings (first at " << r.y << ", " << r.z << ")";
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
        // The glass: a ray bent along the smooth normals of 69,451 small facets takes chaotic
        // paths inside, on which float and double part after a few bounces (0.1% of pixels at
        // depth 2), and so would its caustic's photons. One bounce in the glass is compared here;
        // smooth_refraction_test.cpp compares deep paths through a ball that is not chaotic.
        if (scene.photons) {
            scene.render.max_depth = 1;
            scene.photons.reset();
        }
        test::expect_same_picture(name, to_srgb8(test::render_on(test::Backend::Gpu, scene)),
                                  to_srgb8(test::render_on(test::Backend::Cpu, scene)));
    }
}

}  // namespace
}  // namespace lancer
