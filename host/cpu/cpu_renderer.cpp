#include "cpu/cpu_renderer.hpp"

#include "cpu/lapack.hpp"

#include <algorithm>
#include <atomic>
#include <exception>
#include <limits>
#include <mutex>
#include <thread>
#include <vector>

#include <glm/geometric.hpp>

#include "cpu/lights.hpp"
#include "cpu/photon_tracer.hpp"
#include "cpu/tracer.hpp"
#include "image/adaptive.hpp"
#include "scene/camera.hpp"

namespace lancer {

CpuRenderer::CpuRenderer(unsigned threads, Acceleration acceleration)
    : threads_(threads ? threads : std::max(1u, std::thread::hardware_concurrency())), acceleration_(acceleration) {
    cpu::lapack_dggev_work();  // loaded here, before this renderer starts threads (cpu/lapack.hpp)
}

std::string CpuRenderer::description() const {
    return "cpu: reference renderer, double precision, " + std::to_string(threads_) + " threads";
}

FloatImage CpuRenderer::render(const Scene& scene, const ProgressFn& progress) {
    if (scene.photons) return render_photons(scene, progress);
    if (!scene.render.aa_threshold) return render_grid(scene, {}, progress);
    // Adaptive: one ray per pixel (exactly a one-sample render), then the full grid of the
    // pixels that differ from a neighbour (exactly those pixels of a full render).
    Scene one_ray = scene;
    one_ray.render.samples = 1;
    const double first_share = 0.1;
    FloatImage image = render_grid(one_ray, {}, [&](double f) { return !progress || progress(f * first_share); });
    const std::vector<std::uint32_t> pixels = pixels_to_refine(image, *scene.render.aa_threshold);
    std::vector<char> selected(image.pixels.size(), 0);
    for (std::uint32_t p : pixels) selected[p] = 1;
    FloatImage grid = render_grid(scene, selected, [&](double f) {
        return !progress || progress(first_share + f * (1.0 - first_share));
    });
    std::vector<glm::vec4> refined;
    refined.reserve(pixels.size());
    for (std::uint32_t p : pixels) refined.push_back(grid.pixels[p]);
    merge_refined(image, pixels, refined);
    image.refined_pixels = static_cast<long long>(pixels.size());
    return image;
}

FloatImage CpuRenderer::render_grid(const Scene& scene, const std::vector<char>& selected, const ProgressFn& progress) {
    const RenderSettings& rs = scene.render;
    const cpu::Tracer tracer(scene, acceleration_, &bvh_cache_);
    const CameraBasis cam = make_camera_basis(scene.camera, rs.width, rs.height);
    FloatImage image(rs.width, rs.height);

    std::atomic<int> next_row{0};
    std::atomic<int> rows_done{0};
    std::atomic<bool> cancelled{false};
    std::mutex progress_mutex;
    const int n = rs.samples;

    auto worker = [&] {
        for (int y; (y = next_row.fetch_add(1)) < rs.height && !cancelled;) {
            for (int x = 0; x < rs.width; ++x) {
                if (!selected.empty() && !selected[std::size_t(y) * rs.width + x]) continue;
                dvec3 sum(0.0);
                double rays = 0.0;
                for (int j = 0; j < n; ++j) {
                    for (int i = 0; i < n; ++i) {
                        double sx = x + (i + 0.5) / n;
                        double sy = y + (j + 0.5) / n;
                        dvec3 dir = glm::normalize(camera_ray_direction(cam, sx, sy, rs.width, rs.height));
                        auto seed = cpu::camera_sample_seed(x, y, std::uint32_t(j * n + i));
                        sum += tracer.trace({cam.eye, dir}, seed, rays);
                    }
                }
                dvec3 c = sum / double(n * n);
                image.at(x, y) = glm::vec4(float(c.r), float(c.g), float(c.b), float(rays));
            }
            int done = ++rows_done;
            if (progress) {
                std::lock_guard lock(progress_mutex);
                if (!cancelled && !progress(double(done) / rs.height)) cancelled = true;
            }
        }
    };
    std::vector<std::thread> pool;
    for (unsigned t = 1; t < threads_; ++t) pool.emplace_back(worker);
    worker();
    for (auto& t : pool) t.join();
    if (cancelled) throw RenderCancelled();
    return image;
}

FloatImage CpuRenderer::render_photons(const Scene& scene, const ProgressFn& progress) {
    check_photon_lights(scene);
    const RenderSettings& rs = scene.render;
    const PhotonSettings& ps = *scene.photons;
    cpu::Tracer tracer(scene, acceleration_, &bvh_cache_);
    const CameraBasis cam = make_camera_basis(scene.camera, rs.width, rs.height);
    const int first = ps.first_pass, last = ps.last_pass();
    const auto n = static_cast<std::uint32_t>(rs.samples);
    std::vector<dvec3> sum(std::size_t(rs.width) * rs.height, dvec3(0.0));
    FloatImage image(rs.width, rs.height);
    for (int pass = first; pass < last; ++pass) {
        cpu::PhotonPass shot = cpu::shoot_photons(tracer, pass, threads_);
        const cpu::PhotonMaps maps(std::move(shot.caustic), std::move(shot.global),
                                   photon_radius(ps.caustic_radius, ps.alpha, pass),
                                   photon_radius(ps.global_radius, ps.alpha, pass));
        tracer.use_photons(&maps);
        std::atomic<int> next_row{0};
        auto worker = [&] {
            for (int y; (y = next_row.fetch_add(1)) < rs.height;) {
                for (int x = 0; x < rs.width; ++x) {
                    cpu::PassSample s = cpu::photon_pass_sample(x, y, n, static_cast<std::uint32_t>(pass));
                    dvec3 dir = glm::normalize(camera_ray_direction(cam, x + s.dx, y + s.dy, rs.width, rs.height));
                    double rays = 0.0;
                    sum[std::size_t(y) * rs.width + x] += tracer.trace({cam.eye, dir}, s.seed, rays);
                    image.at(x, y).a += float(rays);
                }
            }
        };
        std::vector<std::thread> pool;
        for (unsigned t = 1; t < threads_; ++t) pool.emplace_back(worker);
        worker();
        for (auto& t : pool) t.join();
        tracer.use_photons(nullptr);
        if (progress && !progress(double(pass + 1 - first) / (last - first))) throw RenderCancelled();
    }
    for (int y = 0; y < rs.height; ++y)
        for (int x = 0; x < rs.width; ++x) {
            dvec3 c = sum[std::size_t(y) * rs.width + x] / double(last - first);
            image.at(x, y) = glm::vec4(float(c.r), float(c.g), float(c.b), image.at(x, y).a);
        }
    return image;
}

FloatImage CpuRenderer::render_hits(const Scene& scene) {
    const RenderSettings& rs = scene.render;
    const cpu::Tracer tracer(scene, acceleration_, &bvh_cache_);
    const CameraBasis cam = make_camera_basis(scene.camera, rs.width, rs.height);
    FloatImage image(rs.width, rs.height);
    for (int y = 0; y < rs.height; ++y) {
        for (int x = 0; x < rs.width; ++x) {
            dvec3 dir = glm::normalize(camera_ray_direction(cam, x + 0.5, y + 0.5, rs.width, rs.height));
            cpu::Hit hit;
            if (tracer.closest_hit({cam.eye, dir}, 0.0, std::numeric_limits<double>::infinity(), hit)) {
                image.at(x, y) = glm::vec4(float(hit.t), float(hit.uv.x), float(hit.uv.y), float(hit.part));
            } else {
                image.at(x, y) = glm::vec4(-1.0f, 0.0f, 0.0f, -1.0f);
            }
        }
    }
    return image;
}

}  // namespace lancer
