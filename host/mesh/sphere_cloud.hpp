#pragma once
// A sphere set's spheres as read from a PLY point set (docs/scene-format.md, "Sphere sets"):
// centres and radii in float, the numbers both renderers trace, 16 bytes a sphere; colours as a
// palette of the file's distinct colours and an index per sphere. Shared by every object placed
// from the same file; the CPU reference's tree over them is built on first use.
#include <cstdint>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <glm/common.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "mesh/element_tree.hpp"

namespace lancer {

class SphereCloud {
public:
    SphereCloud(std::vector<glm::vec4> spheres, std::vector<std::uint32_t> colors, std::vector<glm::dvec3> palette);

    const std::vector<glm::vec4>& spheres() const { return spheres_; }  // (centre, radius)
    // Per sphere, its colour's index in palette(); empty where the file has no colours.
    const std::vector<std::uint32_t>& colors() const { return colors_; }
    const std::vector<glm::dvec3>& palette() const { return palette_; }  // linear RGB
    // Widens [lo, hi] to hold sphere i (exactly: its float centre plus and minus its radius).
    void extend(std::uint32_t i, glm::dvec3& lo, glm::dvec3& hi) const {
        const glm::dvec3 c(spheres_[i]);
        lo = glm::min(lo, c - double(spheres_[i].w));
        hi = glm::max(hi, c + double(spheres_[i].w));
    }
    glm::dvec3 lo() const { return lo_; }
    glm::dvec3 hi() const { return hi_; }
    // Built on the first call (thread-safe): only the CPU reference traverses it.
    const ElementTree& tree() const;

private:
    std::vector<glm::vec4> spheres_;
    std::vector<std::uint32_t> colors_;
    std::vector<glm::dvec3> palette_;
    glm::dvec3 lo_{0.0}, hi_{0.0};
    mutable std::once_flag tree_built_;
    mutable ElementTree tree_;
};

namespace mesh {

// Distinct colours of one file: each becomes a material of the scene.
constexpr std::size_t kMaxSphereColors = 4096;

// The element `vertex` of a PLY file: x y z, `radius` (else every sphere has `radius`: exactly
// one of the two), red green blue (8-bit sRGB codes, or floats taken as linear RGB; all three or
// none). Other elements and properties are read past. Errors as read_ply's (ply_reader.hpp).
std::shared_ptr<const SphereCloud> read_sphere_ply(std::string_view bytes, const std::string& name, std::optional<double> radius);

}  // namespace mesh
}  // namespace lancer
