// POV-Ray's blob:
//   type = "blob"   threshold = 0.6
//   spheres = [{ center = [0, 0, 0], radius = 1, strength = 1 }, ...]
//   cylinders = [{ base_point = [-1, 0, 0], cap_point = [1, 0, 0], radius = 0.5, strength = 1 }, ...]
// Each component's field is strength (1 - d^2 / radius^2)^2 within radius of its centre (or of
// its segment: a cylinder with round ends), 0 beyond; the surface is where the fields' sum is
// the threshold, the inside where it is more (scene.hpp's Blob).
#include <algorithm>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <glm/geometric.hpp>
#include <glm/vector_relational.hpp>

#include "scene/limits.hpp"
#include "scene/parse_surfaces.hpp"
#include "scene/repeat.hpp"
#include "scene/shape_bounds.hpp"

namespace lancer {
namespace {

struct ReadComponent {
    BlobComponent component;
    SourceLocation at;
    std::string what;
};

BlobComponent read_component(TableReader& c, bool cylinder) {
    BlobComponent k;
    const std::string& what = c.what();
    if (cylinder) {
        k.a = c.required_vec3("base_point");
        k.b = c.required_vec3("cap_point");
        if (!(glm::length(k.b - k.a) > 0.0)) c.fail("cap_point", what + ": base_point and cap_point are the same point");
    } else {
        k.a = k.b = c.required_vec3("center");
    }
    k.radius = c.required_number("radius");
    if (!(k.radius > 0.0)) c.fail("radius", fmt::format("{}: radius must be positive, not {:g}", what, k.radius));
    k.strength = c.required_number("strength");
    if (!(k.strength != 0.0)) c.fail("strength", what + ": a strength of 0 adds nothing");
    c.finish();
    return k;
}

// Each entry of the list, or its copies where it repeats (POV-Ray's #while around a component).
void read_components(TableReader& t, const char* key, bool cylinder, std::vector<ReadComponent>& out) {
    const toml::array* list = t.array(key);
    if (!list) return;
    for (std::size_t i = 0; i < list->size(); ++i) {
        const toml::table* table = list->get(i)->as_table();
        const SourceLocation at = location_of(*list->get(i), t.file());
        if (!table) throw SceneError(at, fmt::format("{} {}[{}]: expected a table {{ ... }}", t.what(), key, i));
        TableReader entry(*table, t.file(), fmt::format("{} {}[{}]", t.what(), key, i));
        read_repeated(
            entry,
            [&](double copies, const auto& fail) {
                if (copies + double(out.size()) > double(limits::kMaxBlobComponents))
                    fail(fmt::format("beyond the {} components a blob may have", limits::kMaxBlobComponents));
            },
            [&](TableReader& c) { out.push_back({read_component(c, cylinder), at, c.what()}); });
    }
}

// The distance between segments [p0, p1] and [q0, q1] (either may be a point): the nearest
// points' parameters, each clamped to its segment and the other recomputed (Ericson 2005, 5.1.9).
double segment_distance(const dvec3& p0, const dvec3& p1, const dvec3& q0, const dvec3& q1) {
    const dvec3 d1 = p1 - p0, d2 = q1 - q0, r = p0 - q0;
    const double a = glm::dot(d1, d1), e = glm::dot(d2, d2), f = glm::dot(d2, r);
    double s = 0.0, t = 0.0;
    if (a == 0.0 && e == 0.0) return glm::length(r);
    if (a == 0.0) {
        t = std::clamp(f / e, 0.0, 1.0);
    } else {
        const double c = glm::dot(d1, r);
        if (e == 0.0) {
            s = std::clamp(-c / a, 0.0, 1.0);
        } else {
            const double b = glm::dot(d1, d2), denominator = a * e - b * b;
            s = denominator > 0.0 ? std::clamp((b * f - c * e) / denominator, 0.0, 1.0) : 0.0;
            t = (b * s + f) / e;
            if (t < 0.0) {
                t = 0.0;
                s = std::clamp(-c / a, 0.0, 1.0);
            } else if (t > 1.0) {
                t = 1.0;
                s = std::clamp((b - c) / a, 0.0, 1.0);
            }
        }
    }
    return glm::length((p0 + s * d1) - (q0 + t * d2));
}

// Whether two components' supports (capsules) meet.
bool overlap(const BlobComponent& p, const BlobComponent& q) {
    return segment_distance(p.a, p.b, q.a, q.b) < p.radius + q.radius;
}

// The GPU searches a ray in windows of BLOB_MAX_OVERLAP components, nearest first; a window moves
// on only where fewer components than that hold a point (shaders/shapes/blob.glsl). A point
// inside k supports makes each of those k meet the other k - 1, so no component meeting more
// than BLOB_MAX_OVERLAP - 1 others proves it (found through the blob's tree, each search
// stopping at the limit).
void check_overlap(const Blob& blob, const std::vector<ReadComponent>& read) {
    const ElementTree& tree = *blob.tree;
    std::vector<std::uint32_t> stack;
    for (std::size_t i = 0; i < read.size(); ++i) {
        const BlobComponent& k = blob.components[i];
        const dvec3 lo = glm::min(k.a, k.b) - k.radius, hi = glm::max(k.a, k.b) + k.radius;
        unsigned meets = 0;
        stack.assign(1, 0u);
        while (!stack.empty() && meets < BLOB_MAX_OVERLAP) {
            const ElementTree::Node& n = tree.nodes[stack.back()];
            stack.pop_back();
            if (glm::any(glm::lessThan(n.hi, lo)) || glm::any(glm::greaterThan(n.lo, hi))) continue;
            if (n.count == 0) {
                stack.push_back(n.first);
                stack.push_back(n.first + 1);
                continue;
            }
            for (std::uint32_t e = n.first; e < n.first + n.count; ++e) {
                const std::uint32_t j = tree.order[e];
                if (j != i && overlap(k, blob.components[j])) ++meets;
            }
        }
        if (meets >= BLOB_MAX_OVERLAP)
            throw SceneError(read[i].at, fmt::format("{} meets {} or more other components of the blob; at most {} may (the "
                                                     "GPU follows a ray through at most {} overlapping components at a time)",
                                                     read[i].what, BLOB_MAX_OVERLAP, BLOB_MAX_OVERLAP - 1, BLOB_MAX_OVERLAP));
    }
}

}  // namespace

Shape read_blob(TableReader& t, const glm::dmat4&) {
    Blob blob;
    blob.threshold = t.required_number("threshold");
    if (!(blob.threshold > 0.0))
        t.fail("threshold", fmt::format("blob threshold must be positive, not {:g} (the field is 0 far from every "
                                        "component: a threshold of 0 or less would fill space)",
                                        blob.threshold));
    std::vector<ReadComponent> read;
    read_components(t, "spheres", false, read);
    read_components(t, "cylinders", true, read);
    if (read.empty())
        throw SceneError(t.location(), t.what() + ": a blob needs components: spheres = [{ center, radius, strength "
                                                  "}, ...] or cylinders = [{ base_point, cap_point, radius, strength }, ...]");
    for (const ReadComponent& r : read) blob.components.push_back(r.component);
    prepare_blob(blob);
    check_overlap(blob, read);
    if (!(blob.lo.x < blob.hi.x))
        t.fail("threshold", t.what() + ": every component's strength is negative: the field never reaches the threshold");
    check_world_extent(t, "threshold", blob.lo, blob.hi);
    return blob;
}

}  // namespace lancer
