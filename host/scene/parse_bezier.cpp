// [[object]] type = "bezier": a set of bicubic (rational) Bezier patches, given as
//   file = "teapot.bpt"                        a patch file, relative to the scene file
//   control_points = [[x,y,z], ... 16]         one patch, row-major (i along u)
//   patches = [[[x,y,z], ... 16], ...]         several
// with optional weights (rational patches) shaped like the points, a transform, and the GPU's
// subdivision level.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>

#include <fmt/format.h>
#include <glm/common.hpp>

#include "scene/limits.hpp"
#include "scene/parse_surfaces.hpp"
#include "surface/patch_file.hpp"

namespace lancer {
namespace {

using surface::BezierPatch;
constexpr double kInfinity = std::numeric_limits<double>::infinity();

// 16 control points from an array of 16 [x, y, z].
std::array<dvec3, 16> read_points(const toml::node& node, const std::string& file, const std::string& what) {
    const toml::array* array = node.as_array();
    if (!array || array->size() != 16)
        throw SceneError(location_of(node, file),
                         fmt::format("{} must hold 16 control points (a bicubic patch), not {}", what,
                                     array ? std::to_string(array->size()) : std::string("a single value")));
    std::array<dvec3, 16> points;
    for (int k = 0; k < 16; ++k) points[k] = node_vec3(*array->get(k), file, fmt::format("{}[{}]", what, k));
    return points;
}

std::array<double, 16> read_weights(const toml::node& node, const std::string& file, const std::string& what) {
    const toml::array* array = node.as_array();
    if (!array || array->size() != 16)
        throw SceneError(location_of(node, file), what + " must hold 16 weights, one per control point");
    std::array<double, 16> weights;
    for (int k = 0; k < 16; ++k) {
        weights[k] = node_number(*array->get(k), file, fmt::format("{}[{}]", what, k));
        if (!(weights[k] > 0.0))
            throw SceneError(location_of(*array->get(k), file), fmt::format("{}[{}] must be positive", what, k));
    }
    return weights;
}

std::vector<BezierPatch> read_inline(TableReader& t, const toml::node& points, const toml::node* weights, bool single) {
    std::vector<BezierPatch> patches;
    if (single) {
        BezierPatch p;
        p.points = read_points(points, t.file(), "control_points");
        if (weights) p.weights = read_weights(*weights, t.file(), "weights");
        patches.push_back(p);
        return patches;
    }
    const toml::array* list = points.as_array();
    if (!list || list->empty()) t.fail("patches", "patches must be a non-empty array of patches (16 points each)");
    if (list->size() > static_cast<std::size_t>(surface::kMaxPatchesPerFile))
        t.fail("patches", fmt::format("too many patches (the limit is {})", surface::kMaxPatchesPerFile));
    const toml::array* weight_list = weights ? weights->as_array() : nullptr;
    if (weights && (!weight_list || weight_list->size() != list->size()))
        t.fail("weights", "weights must hold one list of 16 weights per patch");
    for (std::size_t i = 0; i < list->size(); ++i) {
        BezierPatch p;
        p.points = read_points(*list->get(i), t.file(), fmt::format("patches[{}]", i));
        if (weight_list) p.weights = read_weights(*weight_list->get(i), t.file(), fmt::format("weights[{}]", i));
        patches.push_back(p);
    }
    return patches;
}

}  // namespace

Shape read_bezier(TableReader& t, const glm::dmat4& to_world) {
    const toml::node* file = t.node("file");
    const toml::node* control_points = t.node("control_points");
    const toml::node* patch_list = t.node("patches");
    const toml::node* weights = t.node("weights");
    int given = (file != nullptr) + (control_points != nullptr) + (patch_list != nullptr);
    if (given != 1)
        throw SceneError(t.location(), "a bezier object needs exactly one of file, control_points or patches");

    BezierSurface surface;
    if (file) {
        std::string name = t.string("file", "");
        if (weights) t.fail("weights", "weights come from the patch file (a 4th number per point)");
        std::filesystem::path path = std::filesystem::path(t.file().str()).parent_path() / name;
        try {
            surface.patches = surface::read_patch_file(path.string());
        } catch (const SceneError& e) {
            if (e.where().line > 0) throw;  // a problem inside the patch file: its own location
            throw SceneError(t.location("file"), fmt::format("cannot read patch file '{}': {}", path.string(), e.what()));
        }
        surface.source_file = path.string();
    } else {
        surface.patches = read_inline(t, control_points ? *control_points : *patch_list, weights, control_points != nullptr);
    }
    // Weights may be scaled by any positive factor (the GPU's packing normalises them), but their
    // spread within a patch is what float has to hold: the shader's homogeneous arithmetic
    // multiplies them by Bernstein terms, and past this ratio the small ones vanish in float.
    for (std::size_t i = 0; i < surface.patches.size(); ++i) {
        auto& w = surface.patches[i].weights;
        const auto [lightest, heaviest] = std::minmax_element(w.begin(), w.end());
        if (*heaviest > limits::kMaxWeightRatio * *lightest)
            t.fail(file ? "file" : weights ? "weights" : control_points ? "control_points" : "patches",
                   fmt::format("patch {}: its weights range from {:g} to {:g}; the GPU computes in float, and the "
                               "largest weight of a patch may be at most {:g} times its smallest",
                               i, *lightest, *heaviest, limits::kMaxWeightRatio));
        // The same surface for any common factor; both renderers work with the largest weight
        // in [1, 2) (scaled by a power of two: exact; a largest weight of 1 stays). Weights of
        // 1e-50 were nothing in float on the GPU, and below the CPU reference's tolerances.
        int exponent = 0;
        std::frexp(*heaviest, &exponent);
        for (double& x : w) x = std::ldexp(x, 1 - exponent);
    }
    surface.subdivision = t.integer("subdivision", surface.subdivision);
    if (surface.subdivision < 0 || surface.subdivision > 4)
        t.fail("subdivision", "subdivision must be between 0 and 4 (each patch becomes 4^n leaves on the GPU)");
    const glm::dmat4& m = to_world;
    dvec3 lo(kInfinity), hi(-kInfinity);
    for (auto& p : surface.patches) {
        p = surface::transformed(p, m);
        surface::PatchBounds box = surface::bounds(p);
        lo = glm::min(lo, box.min);
        hi = glm::max(hi, box.max);
    }
    check_world_extent(t, t.has("transform") ? "transform" : file ? "file" : control_points ? "control_points" : "patches", lo, hi);
    if (t.boolean("closed", false)) {
        constexpr int n = 8;
        std::vector<surface::SampledPatch> grids;
        for (const surface::BezierPatch& p : surface.patches) {
            surface::SampledPatch& grid = grids.emplace_back(surface::SampledPatch{n, {}});
            for (int i = 0; i <= n; ++i)
                for (int j = 0; j <= n; ++j) grid.points.push_back(surface::evaluate(p, double(i) / n, double(j) / n));
        }
        surface.outward = outward_side_of_declared(t, grids);
    }
    return surface;
}

}  // namespace lancer
