#pragma once
#include <vector>

#include "accel/bvh.hpp"
#include "render/host_adaptive_picture.hpp"
#include "render/renderer.hpp"

namespace lancer {

// The reference renderer: double precision, every core, rows handed out dynamically.
class CpuRenderer final : public Renderer {
public:
    // threads 0: one per hardware thread.
    explicit CpuRenderer(unsigned threads = 0, Acceleration acceleration = Acceleration::Bvh);
    std::string description() const override;
    FloatImage render(const Scene& scene, const ProgressFn& progress) override;
    FloatImage render_hits(const Scene& scene) override;
    void expect_one_still() override { one_still_ = true; }

    std::size_t bvh_builds() const { return bvh_cache_.builds(); }  // trees built so far (for tests)

private:
    // Photon mapping: per pass, a photon map and one camera sample per pixel; the image is the
    // mean of the passes (docs/scene-format.md, "Photon mapping").
    FloatImage render_photons(const Scene& scene, const ProgressFn& progress);
    // Every pixel's N x N grid.
    FloatImage render_grid(const Scene& scene, const ProgressFn& progress);
    // The listed pixels' N x N grids (adaptive anti-aliasing: render/adaptive_render.hpp).
    std::vector<ListedPixel> render_listed(const Scene& scene, const std::vector<std::uint32_t>& pixels, bool spread,
                                           const ProgressFn& progress);
    // work(i) for i < count on every thread, `chunk` at a time in order of i; progress after
    // each chunk, and RenderCancelled once a chunk's report has cancelled.
    void run_parallel(std::size_t count, std::size_t chunk, const std::function<void(std::size_t)>& work,
                      const ProgressFn& progress) const;

    unsigned threads_;
    Acceleration acceleration_;
    BvhCache bvh_cache_;  // frames of an animation with static geometry share one tree
    bool one_still_ = false;
    // The cache this render's tracers use: none for a still traced in one step, whose one tree
    // needs no copy of its boxes kept to compare against.
    BvhCache* tree_cache_ = &bvh_cache_;
};

}  // namespace lancer
