// The driver's ray queries against lancer's own BVH, for one scene of meshes (a benchmark, not a
// test; bench/ray_query.sh runs it on the bunny, 10^6 triangles and 10^4 instances, issue 44):
//
//   build/bench/lancer_ray_query SCENE DRIVER_PNG LANCER_PNG [RUNS=3] [sorted-only]
//
// Each run, interleaved in one process: lancer's CPU-side build (pack_scene: its BVHs and the
// arrays it uploads; the mesh's own tree alone too), lancer's GpuRenderer rendering the scene at
// one ray per pixel, then the driver's build of its bottom- and top-level structures and its
// trace of the same picture (bench/ray_query.comp), twice: with the triangles and instances in
// the scene's order (first run only, and not with `sorted-only`: its trace can take minutes) and in the order of lancer's
// trees' leaves (that ordering's time counted in the build). Lancer's trace is its render less
// the packing that every render repeats (measured alone, with the same cached top-level tree).
// Both renderers are warmed up first (pipelines built, shaders compiled). Prints each quantity's
// median and "result" lines for the script; writes the driver's (lancer-ordered) and lancer's
// pictures. LANCER_VALIDATION=1 puts both devices under the Khronos validation layer: exit code
// 1 if it reported anything.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>
#include <vector>

#include "accel/bvh.hpp"
#include "core/error.hpp"
#include "gpu/gpu_renderer.hpp"
#include "gpu/packing/scene_packing.hpp"
#include "image/image.hpp"
#include "ray_query_device.hpp"
#include "ray_query_scene.hpp"
#include "ray_query_structures.hpp"
#include "ray_query_trace.hpp"
#include "scene/load_scene.hpp"

namespace {

using namespace lancer;
using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    const std::size_t n = v.size();
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

std::size_t array_bytes(const gpu::PackedScene& packed, std::initializer_list<gpu::SceneArray> arrays) {
    std::size_t n = 0;
    for (gpu::SceneArray a : arrays) n += packed.bytes(a).size();
    return n;
}

// What lancer uploads for the geometry and its trees, and for everything.
struct LancerBytes {
    std::size_t mesh = 0;   // mesh tree nodes + mesh triangles (vertices, normals, uv: 96 bytes each)
    std::size_t top = 0;    // scene BVH nodes, primitives (one per placement), their frames, mesh records
    std::size_t grids = 0;  // direction grids over the placements
    std::size_t all = 0;    // every scene array
};

LancerBytes lancer_bytes(const gpu::PackedScene& packed) {
    using A = gpu::SceneArray;
    LancerBytes b;
    b.mesh = array_bytes(packed, {A::MESH_NODES, A::MESH_TRIANGLES});
    b.top = array_bytes(packed, {A::NODES, A::PRIMITIVES, A::OBJECT_FRAMES, A::MESHES});
    b.grids = array_bytes(packed, {A::GRIDS, A::GRID_CELLS, A::GRID_ENTRIES});
    for (std::size_t a = 0; a < gpu::kSceneArrayCount; ++a) b.all += packed.bytes(static_cast<A>(a)).size();
    return b;
}

// lancer's tree over one mesh's triangles alone, as pack_scene builds it (their float boxes).
double mesh_tree_seconds(const Scene& scene) {
    const TriangleMesh& mesh = std::get<Mesh>(scene.objects.front().shape).geometry->mesh();
    const auto start = Clock::now();
    std::vector<Aabb> boxes;
    boxes.reserve(mesh.triangles.size());
    for (const auto& t : mesh.triangles) {
        Aabb box;
        for (std::uint32_t v : t) box.extend(dvec3(glm::vec3(mesh.positions[v])));
        boxes.push_back(box);
    }
    const Bvh bvh = build_bvh(boxes);
    return bvh.nodes.empty() ? 0.0 : seconds_since(start);
}

void write_picture(const std::string& path, const FloatImage& image, const Scene& scene) {
    write_png(path, to_srgb8(image, scene.render.tone));
}

// One way of handing the scene to the driver, and what each run measured of it.
struct DriverPath {
    const char* name;
    bench::MeshSet set;
    std::unique_ptr<bench::RayQueryTracer> tracer;
    std::vector<double> build, trace;
    bench::BuildReport report;
};

double mib(std::size_t bytes) { return double(bytes) / (1024.0 * 1024.0); }

int run(int argc, char** argv) {
    if (argc < 4) {
        std::fprintf(stderr, "usage: %s SCENE DRIVER_PNG LANCER_PNG [RUNS=3] [sorted-only]\n", argv[0]);
        return 2;
    }
    std::setvbuf(stdout, nullptr, _IOLBF, 0);  // each run's line as it ends, through a pipe too
    const int runs = argc > 4 ? std::max(1, std::atoi(argv[4])) : 3;
    const bool scene_order = !(argc > 5 && std::string(argv[5]) == "sorted-only");
    Scene scene = load_scene(argv[1]);
    scene.render.samples = 1;
    scene.render.aa_threshold.reset();
    const bench::MeshSet set = bench::gather_meshes(scene);
    const bench::ViewBlock view = bench::view_block(scene);
    const bool validation = gpu::validation_requested_by_environment();
    std::printf("scene %s: %zu mesh(es), %zu triangles stored, %zu instance(s), %zu triangles placed, %dx%d\n", argv[1],
                set.meshes.size(), set.indices.size() / 3, set.instances.size(), set.placed_triangles(),
                scene.render.width, scene.render.height);

    GpuRenderer lancer_renderer(gpu::ContextOptions{"", validation});
    bench::RayQueryDevice device(validation);
    std::printf("lancer: %s\ndriver: %s\n", lancer_renderer.description().c_str(), device.description().c_str());
    // The driver's two ways: the triangles and instances as the scene gives them, and in the
    // order of lancer's trees' leaves (lavapipe halves them in the order given: ray_query_scene.hpp).
    bench::MeshSet ordered = set;
    bench::order_as_lancer(ordered);
    DriverPath as_given{"driver", set, std::make_unique<bench::RayQueryTracer>(device, set, view)};
    DriverPath sorted{"driver_sorted", ordered, std::make_unique<bench::RayQueryTracer>(device, ordered, view)};
    // Warm-ups: lancer's pipeline and llvmpipe's compile of both shaders happen here.
    FloatImage lancer_picture = lancer_renderer.render(scene, {});
    BvhCache cache;  // the top-level tree that lancer's renderer keeps between renders
    gpu::pack_scene(scene, {Acceleration::Bvh, gpu::GridUse::Auto, &cache});
    {
        bench::DriverStructures warm(device, sorted.set, sorted.tracer->positions(), sorted.tracer->indices());
        sorted.tracer->trace(warm.top());
    }

    std::vector<double> lancer_build, lancer_tree, lancer_pack, lancer_render, lancer_trace;
    LancerBytes bytes;
    for (int r = 0; r < runs; ++r) {
        auto start = Clock::now();
        {
            const gpu::PackedScene packed = gpu::pack_scene(scene);
            lancer_build.push_back(seconds_since(start));
            bytes = lancer_bytes(packed);
        }
        lancer_tree.push_back(mesh_tree_seconds(scene));
        start = Clock::now();
        gpu::pack_scene(scene, {Acceleration::Bvh, gpu::GridUse::Auto, &cache});
        lancer_pack.push_back(seconds_since(start));
        start = Clock::now();
        lancer_picture = lancer_renderer.render(scene, {});
        lancer_render.push_back(seconds_since(start));
        lancer_trace.push_back(lancer_render.back() - lancer_pack.back());
        std::printf("run %d: lancer build %.3f s, render %.3f s (pack %.3f s)", r + 1, lancer_build.back(),
                    lancer_render.back(), lancer_pack.back());

        bench::MeshSet again = set;  // the ordering's cost, on a fresh copy
        start = Clock::now();
        bench::order_as_lancer(again);
        const double ordering = seconds_since(start);
        for (DriverPath* path : {&as_given, &sorted}) {
            if (path == &as_given && (r > 0 || !scene_order)) continue;  // up to minutes a trace: once at most
            bench::DriverStructures structures(device, path->set, path->tracer->positions(), path->tracer->indices());
            path->report = structures.report();
            path->build.push_back(path->report.bottom_seconds + path->report.top_seconds + (path == &sorted ? ordering : 0.0));
            path->trace.push_back(path->tracer->trace(structures.top()));
            std::printf(" | %s build %.3f s, trace %.3f s", path->name, path->build.back(), path->trace.back());
        }
        std::printf("\n");
        std::fflush(stdout);
    }
    write_picture(argv[2], sorted.tracer->picture(), scene);
    write_picture(argv[3], lancer_picture, scene);

    std::printf("medians of %d runs:\n", runs);
    std::printf("  lancer build (pack_scene: BVHs + arrays)  %8.3f s  (the mesh's tree alone %.3f s)\n", median(lancer_build),
                median(lancer_tree));
    std::printf("  lancer render, 1 ray/pixel                %8.3f s  (of which packing again %.3f s)\n", median(lancer_render),
                median(lancer_pack));
    std::printf("  lancer trace (render - packing)           %8.3f s\n", median(lancer_trace));
    std::printf("lancer bytes: %.1f MiB mesh tree + triangles, %.1f MiB scene tree + placements, %.1f MiB direction grids, "
                "%.1f MiB all arrays\n",
                mib(bytes.mesh), mib(bytes.top), mib(bytes.grids), mib(bytes.all));
    std::printf("result lancer_build=%.4f lancer_tree=%.4f lancer_bytes=%zu lancer_trace=%.4f lancer_render=%.4f\n",
                median(lancer_build), median(lancer_tree), bytes.all, median(lancer_trace), median(lancer_render));
    for (const DriverPath* path : {&as_given, &sorted}) {
        if (path->trace.empty()) continue;
        const bench::BuildReport& report = path->report;
        const std::size_t geometry_bytes = path->tracer->positions().size() + path->tracer->indices().size();
        const std::size_t kept = report.bottom_bytes + report.top_bytes + report.instance_bytes + geometry_bytes;
        std::printf("%s (%s): build %.3f s (bottom %.3f s, top %.3f s%s), trace %.3f s\n", path->name,
                    path == &sorted ? "triangles and instances in lancer's tree order" : "in the scene's order",
                    median(path->build), report.bottom_seconds, report.top_seconds,
                    path == &sorted ? ", with lancer's trees to order them" : "", median(path->trace));
        std::printf("  bytes: %.1f MiB bottom level, %.1f MiB top level, %.1f MiB instances, %.1f MiB vertices + indices "
                    "(%.1f MiB kept), %.1f MiB scratch during builds\n",
                    mib(report.bottom_bytes), mib(report.top_bytes), mib(report.instance_bytes), mib(geometry_bytes),
                    mib(kept), mib(report.scratch_bytes));
        std::printf("result %s_build=%.4f %s_bytes=%zu %s_scratch=%zu %s_trace=%.4f\n", path->name, median(path->build),
                    path->name, kept, path->name, static_cast<std::size_t>(report.scratch_bytes), path->name,
                    median(path->trace));
    }
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    try {
        const int code = run(argc, argv);  // every Vulkan object released: teardown is checked too
        if (const std::uint32_t n = gpu::validation_message_count()) {
            std::fprintf(stderr, "lancer_ray_query: error: %u Vulkan validation message(s) on the driver's path\n", n);
            return 1;
        }
        return gpu::exit_code_after_validation(code);
    } catch (const UserError& e) {
        std::fprintf(stderr, "lancer_ray_query: %s\n", e.what());
        return 2;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "lancer_ray_query: %s\n", e.what());
        return 1;
    }
}
