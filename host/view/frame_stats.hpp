#pragma once
// The viewer's timings, summed up when it closes: how fast previews and refinements are on this
// device, and what showing a picture costs (the numbers behind the presentation choice, see
// docs/viewer.md).
#include <string>
#include <vector>

namespace lancer::view {

class FrameStats {
public:
    void preview(double ms, int divisor) {
        previews_.push_back(ms);
        last_divisor_ = divisor;
    }
    void pass(double ms) { passes_.push_back(ms); }
    void refinement(double ms) { refinements_.push_back(ms); }
    void convert(double ms) { converts_.push_back(ms); }  // of a refinement pass's picture
    void upload(double ms) { uploads_.push_back(ms); }
    void present(double ms) { presents_.push_back(ms); }
    // From a camera move to the first picture of it (or of a later move) on screen.
    void response(double ms) { responses_.push_back(ms); }

    // "view: camera move to picture median 12 ms (max 40 ms); 14 previews (median 9 ms, ...), ..."
    std::string summary(const std::string& renderer_name) const;

    static double median(std::vector<double> values);  // 0 for none

private:
    std::vector<double> previews_, passes_, refinements_, converts_, uploads_, presents_, responses_;
    int last_divisor_ = 1;
};

}  // namespace lancer::view
