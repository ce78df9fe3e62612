#include "mesh/sphere_cloud.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <limits>
#include <unordered_map>

#include <fmt/format.h>
#include <glm/common.hpp>

#include "core/error.hpp"
#include "core/huge_pages.hpp"
#include "image/image.hpp"
#include "mesh/mesh_assembly.hpp"
#include "mesh/ply_header.hpp"
#include "mesh/ply_values.hpp"

namespace lancer {

SphereCloud::SphereCloud(std::vector<glm::vec4> spheres, std::vector<std::uint32_t> colors, std::vector<glm::dvec3> palette)
    : spheres_(std::move(spheres)), colors_(std::move(colors)), palette_(std::move(palette)) {
    lo_ = glm::dvec3(std::numeric_limits<double>::infinity());
    hi_ = -lo_;
    for (std::uint32_t i = 0; i < spheres_.size(); ++i) extend(i, lo_, hi_);
}

const ElementTree& SphereCloud::tree() const {
    std::call_once(tree_built_, [this] {
        tree_ = build_element_tree(static_cast<std::uint32_t>(spheres_.size()),
                                   [this](std::uint32_t i, glm::dvec3& lo, glm::dvec3& hi) { extend(i, lo, hi); });
    });
    return tree_;
}

namespace mesh {
namespace {

struct ColorKey {
    std::size_t operator()(const std::array<double, 3>& c) const {
        std::uint64_t bits[3];
        std::memcpy(bits, c.data(), sizeof bits);
        return std::hash<std::uint64_t>()(bits[0] * 0x9E3779B97F4A7C15ull ^ bits[1] * 0xC2B2AE3D27D4EB4Full ^ bits[2]);
    }
};

class PointReader {
public:
    PointReader(std::string_view bytes, const std::string& name, std::optional<double> radius)
        : file_(name), header_(read_ply_header(bytes, name)), values_(bytes, header_, name), radius_(radius) {}

    std::shared_ptr<const SphereCloud> read() {
        bool seen = false;
        for (const PlyElement& e : header_.elements) {
            if (e.name != "vertex" || seen) {
                values_.skip_element(e);
                continue;
            }
            seen = true;
            read_points(e);
        }
        values_.require_end();
        if (spheres_.empty()) throw SceneError({file_, 0, 0}, "the file has no points (a vertex element with x y z): a sphere set needs at least one");
        return std::make_shared<const SphereCloud>(std::move(spheres_), std::move(colors_), std::move(palette_));
    }

private:
    [[noreturn]] void fail_in_header(int line, const std::string& message) const { throw SceneError({file_, line, 0}, message); }

    void read_points(const PlyElement& e) {
        int slot[7];  // x y z radius red green blue
        const char* names[7] = {"x", "y", "z", "radius", "red", "green", "blue"};
        for (int i = 0; i < 7; ++i) slot[i] = find_scalar(e, {names[i]});
        for (int i = 0; i < 3; ++i)
            if (slot[i] == kNoProperty) fail_in_header(e.line, fmt::format("the vertex element has no scalar property {}", names[i]));
        const bool own_radius = slot[3] != kNoProperty;
        if (own_radius == radius_.has_value())
            throw UserError(own_radius ? "the file gives each point's radius (the vertex property `radius`): leave out the object's `radius`"
                                       : "the file gives no radius (a vertex property `radius`): the object needs `radius`, every sphere's");
        const int colors = (slot[4] != kNoProperty) + (slot[5] != kNoProperty) + (slot[6] != kNoProperty);
        if (colors != 0 && colors != 3) fail_in_header(e.line, "the vertex element has some of red green blue but not all three");
        const bool bytes = colors == 3 && is_integer(e.properties[slot[4]].type);
        if (colors == 3)
            for (int i = 4; i < 7; ++i)
                if (is_integer(e.properties[slot[i]].type) != bytes || (bytes && e.properties[slot[i]].type != PlyScalar::uint8))
                    fail_in_header(e.properties[slot[i]].line, "red green blue must be all uchar (8-bit sRGB codes) or all floats (linear RGB)");
        std::vector<int> role(e.properties.size(), kNoProperty);
        for (int i = 0; i < 7; ++i)
            if (slot[i] != kNoProperty) role[slot[i]] = i;
        values_.refuse_what_cannot_fit(e);
        reserve_huge(spheres_, values_.capacity_for(e));
        std::unordered_map<std::array<double, 3>, std::uint32_t, ColorKey> palette_index;
        double v[7] = {0.0, 0.0, 0.0, radius_.value_or(0.0), 0.0, 0.0, 0.0};
        for (std::uint64_t k = 0; k < e.count; ++k) {
            values_.read_scalars(e, k, role, [&](int r, const PlyProperty& p, double x) {
                if (r < 4) {
                    if (auto problem = coordinate_problem(x)) values_.fail(fmt::format("point {}: {} {}", k, p.name, *problem));
                } else if (bytes ? !(x >= 0.0 && x <= 255.0 && x == std::floor(x)) : !(x >= 0.0 && std::isfinite(x))) {
                    values_.fail(fmt::format("point {}: {} {} is not {}", k, p.name, x,
                                             bytes ? "a whole number from 0 to 255 (an 8-bit code)" : "a finite number from 0 up"));
                }
                v[r] = x;
            });
            const glm::vec4 sphere{static_cast<float>(v[0]), static_cast<float>(v[1]), static_cast<float>(v[2]), static_cast<float>(v[3])};
            if (!(sphere.w > 0.0f)) values_.fail(fmt::format("point {}: the radius {} is not above 0 (in float)", k, v[3]));
            spheres_.push_back(sphere);
            if (colors != 3) continue;
            std::array<double, 3> c{v[4], v[5], v[6]};
            if (bytes)
                for (double& x : c) x = decode_srgb8(static_cast<std::uint8_t>(x));
            auto [found, added] = palette_index.try_emplace(c, static_cast<std::uint32_t>(palette_.size()));
            if (added) {
                if (palette_.size() == kMaxSphereColors)
                    values_.fail(fmt::format("point {}: more than {} distinct colours (each becomes a material): give the points fewer", k,
                                             kMaxSphereColors));
                palette_.emplace_back(c[0], c[1], c[2]);
            }
            colors_.push_back(found->second);
        }
    }

    std::string file_;
    PlyHeader header_;
    PlyValues values_;
    std::optional<double> radius_;
    std::vector<glm::vec4> spheres_;
    std::vector<std::uint32_t> colors_;
    std::vector<glm::dvec3> palette_;
};

}  // namespace

std::shared_ptr<const SphereCloud> read_sphere_ply(std::string_view bytes, const std::string& name, std::optional<double> radius) {
    return PointReader(bytes, name, radius).read();
}

}  // namespace mesh
}  // namespace lancer
