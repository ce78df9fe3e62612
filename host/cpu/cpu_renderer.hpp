#pragma once
#include <vector>

#include "accel/bvh.hpp"
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

    std::size_t bvh_builds() const { return bvh_cache_.builds(); }  // trees built so far (for tests)

private:
    // Photon mapping: per pass, a photon map and one camera sample per pixel; the image is the
    // mean of the passes (docs/scene-format.md, "Photon mapping").
    FloatImage render_photons(const Scene& scene, const ProgressFn& progress);
    // The full N x N grid of the pixels where `selected` is nonzero (all when it is empty); the
    // others are left zero.
    FloatImage render_grid(const Scene& scene, const std::vector<char>& selected, const ProgressFn& progress);

    unsigned threads_;
    Acceleration acceleration_;
    BvhCache bvh_cache_;  // frames of an animation with static geometry share one tree
};

}  // namespace lancer
