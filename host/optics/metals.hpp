#pragma once
// Complex indices of refraction of the metals a material can name (metal = "gold"): n + i k at
// the red, green and blue primaries (about 650, 550 and 450 nm), fitted from measured optical
// constants (Johnson and Christy 1972 for gold, silver and copper; Rakic 1995 for aluminium).
// "perfect" reflects everything at every angle (a lossless mirror, for furnace tests and as a
// reference).
#include <optional>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

namespace lancer::optics {

struct ComplexIor {
    glm::dvec3 eta;
    glm::dvec3 k;
};

struct MetalPreset {
    std::string name;
    ComplexIor ior;
};

const std::vector<MetalPreset>& metal_presets();
std::optional<ComplexIor> metal_preset(const std::string& name);

}  // namespace lancer::optics
