#include "render/host_adaptive_picture.hpp"

#include "image/adaptive.hpp"

namespace lancer {

void HostAdaptivePicture::render_first(const Scene& one_ray, const ProgressFn& progress) {
    image_ = every_pixel_(one_ray, progress);
    refined_ = false;
    traced_.clear();
    last_.clear();
    chosen_.clear();
}

std::size_t HostAdaptivePicture::choose(double threshold, bool by_spread) {
    std::vector<char> candidates;
    if (refined_) {
        candidates.assign(image_.pixels.size(), 0);
        for (std::uint32_t p : traced_) candidates[p] = 1;
    }
    chosen_ = pixels_to_refine(image_, threshold, candidates);
    if (by_spread) {
        std::vector<char> refine(image_.pixels.size(), 0);
        for (std::uint32_t p : chosen_) refine[p] = 1;
        for (std::size_t i = 0; i < traced_.size(); ++i)
            if (sample_spread(last_[i].lo, last_[i].hi) > threshold) refine[traced_[i]] = 1;
        chosen_.clear();
        for (std::uint32_t p : traced_)
            if (refine[p]) chosen_.push_back(p);
    }
    return chosen_.size();
}

void HostAdaptivePicture::refine(const Scene& grid, bool keep_spread, const ProgressFn& progress) {
    last_ = listed_(grid, chosen_, keep_spread, progress);
    for (std::size_t i = 0; i < chosen_.size(); ++i) {
        glm::vec4& p = image_.pixels[chosen_[i]];
        p = glm::vec4(glm::vec3(last_[i].colour), p.a + last_[i].colour.a);
    }
    traced_ = std::move(chosen_);
    chosen_.clear();
    refined_ = true;
}

}  // namespace lancer
