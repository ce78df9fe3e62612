#include "view/refinement.hpp"

#include <algorithm>

namespace lancer::view {

namespace {

std::vector<SamplePass> doubling_passes(std::uint32_t total) {
    std::vector<SamplePass> passes;
    std::uint32_t done = 0;
    while (done < total) {
        std::uint32_t count = std::max<std::uint32_t>(1, done);
        // A tail smaller than this pass would be a pass of its own for little gain: take it now.
        if (total - done - std::min(count, total - done) < count) count = total - done;
        passes.push_back({done, count});
        done += count;
    }
    return passes;
}

}  // namespace

std::vector<SamplePass> refinement_passes(int samples_per_side) {
    return doubling_passes(static_cast<std::uint32_t>(samples_per_side * samples_per_side));
}

std::uint32_t refinement_total(const Scene& scene) {
    if (scene.photons) return static_cast<std::uint32_t>(scene.photons->last_pass() - scene.photons->first_pass);
    return static_cast<std::uint32_t>(scene.render.samples * scene.render.samples);
}

std::vector<SamplePass> refinement_plan(const Scene& scene) { return doubling_passes(refinement_total(scene)); }

Scene preview_scene(const Scene& scene, int divisor) {
    Scene s = scene;
    s.render.width = std::max(1, scene.render.width / divisor);
    s.render.height = std::max(1, scene.render.height / divisor);
    s.render.samples = 1;
    if (s.photons) {
        s.photons->count = std::max(1000, s.photons->count / 8);
        s.photons->first_pass = 0;
        s.photons->pass_count = 1;
    }
    return s;
}

int preview_divisor_for(double full_size_ms, double budget_ms, int max_divisor) {
    int d = 1;
    while (d < max_divisor && full_size_ms / (double(d) * d) > budget_ms) d *= 2;
    return d;
}

int next_preview_divisor(int divisor, double preview_ms, double budget_ms, int max_divisor) {
    if (preview_ms > budget_ms) return std::min(divisor * 2, max_divisor);
    // Four times the pixels at half the divisor: only when that still fits the budget well.
    if (preview_ms * 4.0 < budget_ms * 0.5) return std::max(1, divisor / 2);
    return divisor;
}

Rgb8Image display_image(const FloatImage& sums, std::uint32_t samples_done, bool final_pass, const ToneMapping& tone) {
    if (final_pass) return to_srgb8(sums, tone);
    return to_srgb8(sums, tone, 1.0f / float(std::max<std::uint32_t>(1, samples_done)));
}

}  // namespace lancer::view
