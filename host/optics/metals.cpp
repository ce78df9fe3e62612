#include "optics/metals.hpp"

namespace lancer::optics {

const std::vector<MetalPreset>& metal_presets() {
    static const std::vector<MetalPreset> presets = {
        {"gold", {{0.143119, 0.374957, 1.442479}, {3.983160, 2.385721, 1.603215}}},
        {"silver", {{0.155265, 0.116723, 0.138342}, {4.828181, 3.122249, 2.146961}}},
        {"copper", {{0.200438, 0.924033, 1.102212}, {3.912949, 2.452848, 2.142188}}},
        {"aluminium", {{1.657460, 0.880369, 0.521229}, {9.223869, 6.269523, 4.837001}}},
        // A purely imaginary index (a metal that absorbs nothing) reflects everything at every angle.
        {"perfect", {{0.0, 0.0, 0.0}, {1.0, 1.0, 1.0}}},
    };
    return presets;
}

std::optional<ComplexIor> metal_preset(const std::string& name) {
    for (const MetalPreset& p : metal_presets())
        if (p.name == name) return p.ior;
    return std::nullopt;
}

}  // namespace lancer::optics
