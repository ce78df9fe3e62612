// Benchmark (not a test): the CPU reference's exact ray/Bezier-patch intersection on the teapot.
// Primary rays of a fixed 3/4 view (default 128x96, one ray per pixel), one thread, nearest hit
// over the 32 patches with per-patch box culling, as the renderer will do it. Prints rays/s,
// how many ray/patch pairs get past the box test, the time per such pair, and the time of the
// 18x18 generalized eigenproblem (LAPACK dggev) alone. Optionally writes a normal-shaded PNG.
//
//   OPENBLAS_NUM_THREADS=1 build/bench/lancer_bench_bezier [--width W] [--height H]
//                                                          [--png teapot.png] [--patches FILE]
#include <fmt/format.h>

#include <chrono>
#include <cstdlib>
#include <cstring>
#include <glm/geometric.hpp>
#include <random>
#include <string>

#include "cpu/shapes/bezier_algebra.hpp"
#include "cpu/shapes/shapes.hpp"
#include "image/image.hpp"
#include "scene/camera.hpp"
#include "surface/patch_file.hpp"

namespace {

using namespace lancer;
using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

struct Options {
    int width = 128;
    int height = 96;
    std::string png;
    std::string patches = std::string(LANCER_SOURCE_DIR) + "/scenes/teapot.bpt";
};

Options parse(int argc, char** argv) {
    Options o;
    for (int i = 1; i + 1 < argc; i += 2) {
        std::string key = argv[i], value = argv[i + 1];
        if (key == "--width")
            o.width = std::max(1, std::atoi(value.c_str()));
        else if (key == "--height")
            o.height = std::max(1, std::atoi(value.c_str()));
        else if (key == "--png")
            o.png = value;
        else if (key == "--patches")
            o.patches = value;
        else
            throw UserError("unknown option " + key);
    }
    return o;
}

// dggev alone, on random bicubics: its cost hardly depends on the values.
double dggev_microseconds() {
    std::mt19937 rng(1);
    std::uniform_real_distribution<double> c(-1.0, 1.0);
    const int n = 2000;
    std::vector<double> roots;
    double best = 1e30;
    for (int rep = 0; rep < 3; ++rep) {
        cpu::bezier_algebra::Bicubic f, g;
        auto start = Clock::now();
        for (int i = 0; i < n; ++i) {
            for (auto& row : f)
                for (double& x : row) x = c(rng);
            for (auto& row : g)
                for (double& x : row) x = c(rng);
            roots.clear();
            cpu::bezier_algebra::resultant_roots(f, g, 0.0, 1.0, roots);
        }
        best = std::min(best, seconds_since(start) / n * 1e6);
    }
    return best;
}

}  // namespace

int main(int argc, char** argv) try {
    Options opt = parse(argc, argv);
    std::vector<surface::BezierPatch> patches = surface::read_patch_file(opt.patches);
    CameraSpec spec;
    spec.eye = {-5.0, -8.0, 5.0};
    spec.look_at = {0.2, 0.0, 1.4};
    spec.up = {0.0, 0.0, 1.0};
    spec.fov_deg = 30.0;
    CameraBasis cam = make_camera_basis(spec, opt.width, opt.height);

    // Box-passing ray/patch pairs, counted in a separate pass so the timed loop is the renderer's.
    long long pairs = 0;
    std::vector<surface::PatchBounds> boxes;
    for (const auto& p : patches) boxes.push_back(surface::bounds(p));

    FloatImage image(opt.width, opt.height);
    long long hits = 0;
    auto start = Clock::now();
    for (int y = 0; y < opt.height; ++y)
        for (int x = 0; x < opt.width; ++x) {
            cpu::Ray ray{cam.eye, glm::normalize(camera_ray_direction(cam, x + 0.5, y + 0.5, opt.width, opt.height))};
            std::optional<cpu::SurfaceHit> best;
            for (const auto& p : patches)
                if (auto h = cpu::intersect(p, ray, 1e-9, best ? best->t : 1e30)) best = h;
            glm::vec4 colour(0.05f, 0.05f, 0.08f, 1.0f);
            if (best) {
                ++hits;
                dvec3 n = glm::dot(best->normal, ray.dir) > 0.0 ? -best->normal : best->normal;
                colour = glm::vec4(glm::vec3(0.5 + 0.5 * n) * float(0.2 + 0.8 * std::abs(glm::dot(n, ray.dir))), 1.0f);
            }
            image.at(x, y) = colour;
        }
    double secs = seconds_since(start);
    const double rays = double(opt.width) * opt.height;

    // Time per ray/patch pair past the box test (whole intersect_all: eigenproblem, roots, polish).
    auto pair_start = Clock::now();
    for (int y = 0; y < opt.height; ++y)
        for (int x = 0; x < opt.width; ++x) {
            cpu::Ray ray{cam.eye, glm::normalize(camera_ray_direction(cam, x + 0.5, y + 0.5, opt.width, opt.height))};
            for (std::size_t k = 0; k < patches.size(); ++k) {
                const auto& b = boxes[k];
                dvec3 inv = 1.0 / ray.dir;
                dvec3 t0 = (b.min - ray.origin) * inv, t1 = (b.max - ray.origin) * inv;
                dvec3 lo = glm::min(t0, t1), hi = glm::max(t0, t1);
                if (std::max({lo.x, lo.y, lo.z}) > std::min({hi.x, hi.y, hi.z})) continue;
                ++pairs;
                cpu::intersect_all(patches[k], ray, 1e-9, 1e30);
            }
        }
    double pair_secs = seconds_since(pair_start);

    fmt::print("teapot {}x{} primary rays, 1 thread: {:.3f} s, {:.0f} rays/s, {} hits\n", opt.width, opt.height, secs,
               rays / secs, hits);
    fmt::print("ray/patch pairs past the box test: {} ({:.2f} per ray), {:.1f} us each\n", pairs, pairs / rays,
               pair_secs / double(pairs) * 1e6);
    fmt::print("18x18 dggev (values only) alone: {:.1f} us\n", dggev_microseconds());
    if (!opt.png.empty()) {
        write_png(opt.png, to_srgb8(image));
        fmt::print("wrote {}\n", opt.png);
    }
    return 0;
} catch (const std::exception& e) {
    fmt::print(stderr, "{}\n", format_error(e));
    return 2;
}
