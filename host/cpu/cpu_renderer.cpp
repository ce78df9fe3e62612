#include "cpu/cpu_renderer.hpp"

#include "cpu/lapack.hpp"

#include <algorithm>
#include <atomic>
#include <exception>
#include <limits>
#include <mutex>
#include <system_error>
#include <thread>
#include <vector>

#include <glm/geometric.hpp>

#include "cpu/lights.hpp"
#include "cpu/photon_tracer.hpp"
#include "cpu/tracer.hpp"
#include "render/adaptive_render.hpp"
#include "render/host_adaptive_picture.hpp"
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
    tree_cache_ = one_still_ && !scene.render.aa_threshold ? nullptr : &bvh_cache_;
    if (scene.photons) return render_photons(scene, progress);
    if (!scene.render.aa_threshold) return render_grid(scene, progress);
    HostAdaptivePicture picture([&](const Scene& s, const ProgressFn& p) { return render_grid(s, p); },
                                [&](const Scene& s, const std::vector<std::uint32_t>& pixels, bool spread,
                                    const ProgressFn& p) { return render_listed(s, pixels, spread, p); });
    return render_adaptive(scene, picture, progress);
}

namespace {

// The pixel's N x N grid of samples, in the order every backend traces them; rgb = their mean,
// a = the rays traced. With `spread`, also the per-channel extremes of the samples' colours.
glm::vec4 trace_pixel(const cpu::Tracer& tracer, const CameraBasis& cam, const RenderSettings& rs, int x, int y,
                      ListedPixel* spread = nullptr) {
    const int n = rs.samples;
    dvec3 sum(0.0), lo(std::numeric_limits<double>::infinity()), hi(-std::numeric_limits<double>::infinity());
    double rays = 0.0;
    for (int j = 0; j < n; ++j) {
        for (int i = 0; i < n; ++i) {
            double sx = x + (i + 0.5) / n;
            double sy = y + (j + 0.5) / n;
            dvec3 dir = glm::normalize(camera_ray_direction(cam, sx, sy, rs.width, rs.height));
            auto seed = cpu::camera_sample_seed(x, y, std::uint32_t(j * n + i));
            const dvec3 c = tracer.trace({cam.eye, dir}, seed, rays);
            sum += c;
            if (spread) {
                lo = glm::min(lo, c);
                hi = glm::max(hi, c);
            }
        }
    }
    if (spread) {
        spread->lo = glm::vec3(lo);
        spread->hi = glm::vec3(hi);
    }
    dvec3 c = sum / double(n * n);
    return glm::vec4(float(c.r), float(c.g), float(c.b), float(rays));
}

}  // namespace

void CpuRenderer::run_parallel(std::size_t count, std::size_t chunk, const std::function<void(std::size_t)>& work,
                               const ProgressFn& progress) const {
    const std::size_t chunks = (count + chunk - 1) / chunk;
    std::atomic<std::size_t> next{0}, done{0};
    std::atomic<bool> cancelled{false};
    std::mutex progress_mutex;
    auto worker = [&] {
        for (std::size_t c; (c = next.fetch_add(1)) < chunks && !cancelled;) {
            for (std::size_t i = c * chunk; i < std::min(count, (c + 1) * chunk); ++i) work(i);
            const std::size_t finished = ++done;
            if (progress) {
                std::lock_guard lock(progress_mutex);
                if (!cancelled && !progress(double(finished) / double(chunks))) cancelled = true;
            }
        }
    };
    std::vector<std::thread> pool;
    // Joined however this scope ends: a joinable thread destroyed would terminate the process.
    struct JoinAll {
        std::vector<std::thread>& threads;
        ~JoinAll() {
            for (auto& t : threads)
                if (t.joinable()) t.join();
        }
    } join_all{pool};
    for (unsigned t = 1; t < threads_; ++t) {
        try {
            pool.emplace_back(worker);
        } catch (const std::system_error&) {
            break;  // no room for another thread's stack (an address-space limit): fewer do the work
        }
    }
    worker();
    for (auto& t : pool) t.join();
    if (cancelled) throw RenderCancelled();
}

FloatImage CpuRenderer::render_grid(const Scene& scene, const ProgressFn& progress) {
    const RenderSettings& rs = scene.render;
    const cpu::Tracer tracer(scene, acceleration_, tree_cache_);
    const CameraBasis cam = make_camera_basis(scene.camera, rs.width, rs.height);
    FloatImage image(rs.width, rs.height);
    run_parallel(
        std::size_t(rs.height), 1,
        [&](std::size_t y) {
            for (int x = 0; x < rs.width; ++x) image.at(x, int(y)) = trace_pixel(tracer, cam, rs, x, int(y));
        },
        progress);
    return image;
}

std::vector<ListedPixel> CpuRenderer::render_listed(const Scene& scene, const std::vector<std::uint32_t>& pixels,
                                                    bool spread, const ProgressFn& progress) {
    const RenderSettings& rs = scene.render;
    const cpu::Tracer tracer(scene, acceleration_, tree_cache_);
    const CameraBasis cam = make_camera_basis(scene.camera, rs.width, rs.height);
    std::vector<ListedPixel> listed(pixels.size());
    // Chunks of a row's length: as many progress reports as a full render's rows.
    run_parallel(
        pixels.size(), std::size_t(rs.width),
        [&](std::size_t i) {
            const int x = int(pixels[i] % std::uint32_t(rs.width)), y = int(pixels[i] / std::uint32_t(rs.width));
            listed[i].colour = trace_pixel(tracer, cam, rs, x, y, spread ? &listed[i] : nullptr);
        },
        progress);
    return listed;
}

FloatImage CpuRenderer::render_photons(const Scene& scene, const ProgressFn& progress) {
    check_photon_lights(scene);
    const RenderSettings& rs = scene.render;
    const PhotonSettings& ps = *scene.photons;
    cpu::Tracer tracer(scene, acceleration_, tree_cache_);
    const CameraBasis cam = make_camera_basis(scene.camera, rs.width, rs.height);
    const int first = ps.first_pass, last = ps.last_pass();
    const auto n = static_cast<std::uint32_t>(rs.samples);
    std::vector<dvec3> sum(std::size_t(rs.width) * rs.height, dvec3(0.0));
    FloatImage image(rs.width, rs.height);
    for (int pass = first; pass < last; ++pass) {
        cpu::StoredPhotons shot = cpu::shoot_photons(tracer, pass, threads_);
        const cpu::PhotonMaps maps(std::move(shot.caustic), std::move(shot.global),
                                   photon_radius(ps.caustic_radius, ps.alpha, pass),
                                   photon_radius(ps.global_radius, ps.alpha, pass));
        tracer.use_photons(&maps);
        run_parallel(
            std::size_t(rs.height), 1,
            [&](std::size_t row) {
                const int y = int(row);
                for (int x = 0; x < rs.width; ++x) {
                    cpu::PassSample s = cpu::photon_pass_sample(x, y, n, static_cast<std::uint32_t>(pass));
                    dvec3 dir = glm::normalize(camera_ray_direction(cam, x + s.dx, y + s.dy, rs.width, rs.height));
                    double rays = 0.0;
                    sum[std::size_t(y) * rs.width + x] += tracer.trace({cam.eye, dir}, s.seed, rays);
                    image.at(x, y).a += float(rays);
                }
            },
            {});
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
    const cpu::Tracer tracer(scene, acceleration_, tree_cache_);
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
