#include "view/frame_stats.hpp"

#include <algorithm>

#include <fmt/format.h>

namespace lancer::view {

double FrameStats::median(std::vector<double> values) {
    if (values.empty()) return 0.0;
    std::size_t mid = values.size() / 2;
    std::nth_element(values.begin(), values.begin() + mid, values.end());
    return values[mid];
}

std::string FrameStats::summary(const std::string& renderer_name) const {
    std::string moves = "view: the camera did not move";
    if (!responses_.empty()) {
        double slowest = *std::max_element(responses_.begin(), responses_.end());
        moves = fmt::format("view: camera move to picture median {:.1f} ms (max {:.0f} ms); {} preview(s) (median {:.1f} "
                            "ms, last at 1/{} size)",
                            median(responses_), slowest, previews_.size(), median(previews_), last_divisor_);
    }
    return fmt::format(
        "{}; {} refinement(s) (median {:.0f} ms; passes median {:.1f} ms, full-size to sRGB median {:.2f} ms); window "
        "(SDL renderer '{}'): upload median {:.2f} ms, draw and present median {:.2f} ms",
        moves, refinements_.size(), median(refinements_), median(passes_), median(converts_), renderer_name,
        median(uploads_), median(presents_));
}

}  // namespace lancer::view
