#include "cpu/tracer.hpp"

#include <array>
#include <cmath>
#include <limits>
#include <optional>

#include <glm/geometric.hpp>

#include "scene/shape_bounds.hpp"
#include "core/constants.hpp"
#include "cpu/appearance.hpp"
#include "cpu/lights.hpp"
#include "cpu/pattern.hpp"
#include "cpu/photon_map.hpp"
#include "cpu/shapes/shapes.hpp"

namespace lancer::cpu {
namespace {

// Below this remaining weight a ray cannot change the 8-bit result (as the shader).
constexpr double kMinWeight = 1.0 / 1024.0;
// The ray tree's rule, as the shader's: at most this many rays wait while one is followed.
constexpr std::size_t kPendingSize = 8;
// On a transparent surface, a light sample that would add less than this to the pixel unshadowed
// is skipped, shadow ray and all (as the shader): mostly highlights far from their peak.
constexpr double kMinLight = 1.0 / 65536.0;
// A shadow ray passes through at most this many transparent surfaces; more block the light.
constexpr int kMaxShadowCrossings = 16;

dvec3 mirror(const dvec3& d, const dvec3& n) { return d - 2.0 * glm::dot(d, n) * n; }

// The sky in unit direction d: its pattern's colour at d, or its ramp at d's height, wrapped as
// POV-Ray's gradient y.
dvec3 sky_color(const Sky& sky, const dvec3& d) {
    if (sky.pattern) return pattern_color(*sky.pattern, glm::normalize(d));
    return ramp_color(sky.colors, d.y - std::floor(d.y));
}

}  // namespace

dvec3 pigment_at(const Material& m, const dvec3& object_point) {
    if (!m.checker) return m.color;
    const dvec3 p = m.checker->to_checker ? dvec3(*m.checker->to_checker * glm::dvec4(object_point, 1.0)) : object_point;
    // First colour where floor(x)+floor(y)+floor(z) is even; the bias keeps a floor lying on an
    // integer plane on one side of it despite rounding.
    // The parity by fmod, not by converting to an integer: a checker much finer than the scene
    // (size 1e-12 at 1e3) has cell numbers beyond any integer type.
    dvec3 cell = glm::floor(p / m.checker->size + 1e-4);
    bool odd = std::fmod(std::abs(cell.x + cell.y + cell.z), 2.0) == 1.0;
    return odd ? m.checker->color_b : m.checker->color_a;
}

Tracer::Tracer(const Scene& scene, Acceleration acceleration, BvhCache* cache)
    : scene_(scene), terms_(microfacet_terms(scene)) {
    for (const Material& m : scene.materials) has_transparency_ |= m.transparent();
    std::vector<Aabb> boxes;
    boxes.reserve(scene.objects.size());  // sized once: doubling would hold two arrays at once
    bounded_.reserve(scene.objects.size());
    bool all_cheap = true;
    for (const Object& object : scene.objects) {
        std::optional<Aabb> box;
        if (acceleration != Acceleration::BruteForce) box = object_bounds(object);
        if (box) {
            bounded_.push_back(&object);
            boxes.push_back(*box);
            all_cheap &= shape_has(shape_type(object.shape), SHAPE_CHEAP);
        } else {
            unbounded_.push_back(&object);
        }
    }
    const BvhOptions options = tree_options(boxes.size(), all_cheap);
    bvh_ = cache ? cache->build(boxes, options) : std::make_shared<const Bvh>(build_bvh_from(std::move(boxes), options));
    std::vector<Aabb>().swap(boxes);
    std::vector<const Object*> ordered;
    ordered.reserve(bvh_->order.size());
    for (std::uint32_t i : bvh_->order) ordered.push_back(bounded_[i]);
    bounded_ = std::move(ordered);
}

namespace {

// Entry distance of the ray into the box within [0, t_max], or nothing.
std::optional<double> box_entry(const Aabb& b, const Ray& ray, const dvec3& inv_dir, double t_max) {
    double enter = 0.0, leave = t_max;
    for (int a = 0; a < 3; ++a) {
        double t0 = (b.lo[a] - ray.origin[a]) * inv_dir[a];
        double t1 = (b.hi[a] - ray.origin[a]) * inv_dir[a];
        if (std::isnan(t0) || std::isnan(t1)) continue;  // origin on a slab plane of a parallel ray
        if (t0 > t1) std::swap(t0, t1);
        enter = std::max(enter, t0);
        leave = std::min(leave, t1);
    }
    if (enter > leave) return std::nullopt;
    return enter;
}

}  // namespace

template <typename Visit, typename TMax>
void Tracer::for_each_candidate(const Ray& ray, TMax t_max, Visit visit) const {
    for (const Object* object : unbounded_)
        if (!visit(*object)) return;
    const std::vector<BvhNode>& nodes = bvh_->nodes;
    if (nodes.empty()) return;
    dvec3 inv_dir = 1.0 / ray.dir;
    if (!box_entry(nodes[0].box, ray, inv_dir, t_max())) return;
    std::vector<std::pair<std::uint32_t, double>> stack;
    stack.reserve(64);
    stack.emplace_back(0u, 0.0);
    while (!stack.empty()) {
        auto [index, entry] = stack.back();
        stack.pop_back();
        if (entry > t_max()) continue;
        const BvhNode& node = nodes[index];
        if (node.leaf()) {
            for (std::uint32_t i = node.first; i < node.first + node.count; ++i)
                if (!visit(*bounded_[i])) return;
            continue;
        }
        auto near_t = box_entry(nodes[node.first].box, ray, inv_dir, t_max());
        auto far_t = box_entry(nodes[node.first + 1].box, ray, inv_dir, t_max());
        std::uint32_t near_child = node.first, far_child = node.first + 1;
        if (far_t && (!near_t || *far_t < *near_t)) {
            std::swap(near_t, far_t);
            std::swap(near_child, far_child);
        }
        if (far_t) stack.emplace_back(far_child, *far_t);
        if (near_t) stack.emplace_back(near_child, *near_t);  // popped first
    }
}

bool Tracer::closest_hit(const Ray& ray, double t_min, double t_max, Hit& hit) const {
    hit.object = nullptr;
    hit.t = t_max;
    for_each_candidate(ray, [&] { return hit.t; }, [&](const Object& object) {
        auto h = intersect(object, ray, t_min, hit.t);
        if (h) {
            hit.t = h->t;
            hit.normal = h->normal;
            hit.uv = h->uv;
            hit.part = h->part;
            // A CSG hit is its leaf's: shaded with the leaf's material, placement and texture.
            const auto* csg = std::get_if<Csg>(&object.shape);
            hit.object = csg ? &csg->leaves[static_cast<std::size_t>(h->part)] : &object;
            hit.material = csg ? hit.object->material : part_material(object, h->part);
        }
        return true;
    });
    return hit.object != nullptr;
}

bool Tracer::occluded(const Ray& ray, double t_min, double t_max) const {
    bool blocked = false;
    for_each_candidate(ray, [&] { return t_max; }, [&](const Object& object) {
        auto h = intersect(object, ray, t_min, t_max);
        blocked = h.has_value();
        return !blocked;
    });
    return blocked;
}

dvec3 Tracer::transmittance(dvec3 from, dvec3 origin, const dvec3& q, Media media) const {
    dvec3 through(1.0);
    for (int crossings = 0;; ++crossings) {
        dvec3 to_light = q - origin;
        double dist = glm::length(to_light);
        Ray ray{origin, to_light / dist};
        Hit hit;
        if (!closest_hit(ray, 0.0, dist, hit)) return through * absorption_along(media, glm::length(q - from));
        const Material& m = scene_.materials[hit.material];
        if (crossings == kMaxShadowCrossings || !m.transparent()) return dvec3(0.0);
        dvec3 p = ray.origin + hit.t * ray.dir;
        through *= absorption_along(media, glm::length(p - from));  // between surface points
        bool sheet = is_thin_sheet(hit.object->shape);
        Media beyond = sheet ? media : media.crossed(hit.material);
        if (sheet || beyond.innermost() != media.innermost()) through *= (1.0 - m.reflection) * m.transmission;
        if (std::max({through.r, through.g, through.b}) < kMinWeight) return dvec3(0.0);
        media = beyond;
        from = p;
        origin = past_surface(hit.object->shape, p, hit.normal, ray.dir, ray_offset(p, offset_origin_));
    }
}

dvec3 Tracer::absorption_along(const Media& media, double distance) const {
    auto medium = media.innermost();
    return medium ? beer_lambert(scene_.materials[*medium].absorption, distance) : dvec3(1.0);
}

double Tracer::ior_of(const Media& media) const {
    auto medium = media.innermost();
    return medium ? scene_.materials[*medium].ior : 1.0;
}

dvec3 Tracer::shade_local(const Material& m, const dvec3& surface_pigment, const dvec3& p, const dvec3& n,
                          const dvec3& shading_n, const dvec3& view_dir, const Media& media, std::uint32_t seed,
                          const dvec3& scale, double& rays) const {
    // Ambient and diffuse light the part of the surface that does not transmit; the highlight
    // stays whole, so glass keeps its highlights.
    dvec3 pigment = surface_pigment * (1.0 - m.transmission);
    dvec3 color = m.ambient * pigment * scene_.ambient;
    dvec3 mirrored = mirror(view_dir, shading_n);
    dvec3 origin = p + ray_offset(p, offset_origin_) * n;  // shadow rays start here; shading uses p itself
    for (std::size_t i = 0; i < scene_.lights.size(); ++i) {
        const Light& light = scene_.lights[i];
        const int count = light_sample_count(light);
        for (int s = 0; s < count; ++s) {
            dvec3 q = light_sample_position(light, static_cast<std::uint32_t>(i), s, seed);
            dvec3 l = glm::normalize(q - p);
            if (glm::dot(n, l) <= 0.0) continue;  // the light (sample) is behind the surface
            double n_dot_l = std::max(0.0, glm::dot(shading_n, l));
            dvec3 diffuse = m.diffuse * n_dot_l * pigment;
            double highlight = m.highlight == Highlight::Blinn ? glm::dot(shading_n, glm::normalize(l - view_dir))
                                                              : glm::dot(mirrored, l);
            double shine = highlight > 0.0 && m.specular > 0.0 ? m.specular * std::pow(highlight, m.shininess) : 0.0;
            dvec3 intensity = light_intensity(light, q, p, count);
            dvec3 unshadowed = scale * (diffuse + shine) * intensity;
            if (m.transparent() && std::max({unshadowed.r, unshadowed.g, unshadowed.b}) < kMinLight) continue;
            rays += 1.0;
            if (has_transparency_ && !photons_) {
                intensity *= transmittance(p, origin, q, media);
                if (intensity == dvec3(0.0)) continue;
            } else if (shadowed(origin, q)) {
                continue;
            }
            color += diffuse * intensity;
            if (shine > 0.0) color += shine * intensity;
        }
    }
    return color;
}

bool Tracer::shadowed(const dvec3& origin, const dvec3& q) const {
    dvec3 to_light = q - origin;
    double dist = glm::length(to_light);
    return occluded({origin, to_light / dist}, 0.0, dist);
}

dvec3 Tracer::shade_microfacet(const Material& m, const MicrofacetTerms& terms, const dvec3& p, const dvec3& n,
                               const dvec3& wo, double n1, double n2, const Media& media, std::uint32_t seed,
                               const dvec3& scale, double& rays) const {
    dvec3 color(0.0);
    if (terms.alpha == 0.0) return color;  // a perfect mirror shows no point of light
    dvec3 origin = p + ray_offset(p, offset_origin_) * n;
    for (std::size_t i = 0; i < scene_.lights.size(); ++i) {
        const Light& light = scene_.lights[i];
        const int count = light_sample_count(light);
        for (int s = 0; s < count; ++s) {
            dvec3 q = light_sample_position(light, static_cast<std::uint32_t>(i), s, seed);
            dvec3 l = glm::normalize(q - p);
            double cos_l = glm::dot(n, l);
            if (cos_l <= 0.0) continue;
            // A light's colour is its irradiance at normal incidence over pi (scene-format.md):
            // the radiance toward the viewer is f pi cos(theta_l) times it.
            dvec3 value = kPi * cos_l * microfacet_brdf(m, terms, n, wo, l, n1, n2) * light_intensity(light, q, p, count);
            if (std::max({value.r * scale.r, value.g * scale.g, value.b * scale.b}) < kMinLight) continue;
            rays += 1.0;
            if (has_transparency_ && !photons_) {
                value *= transmittance(p, origin, q, media);
            } else if (shadowed(origin, q)) {
                continue;
            }
            color += value;
        }
    }
    return color;
}

dvec3 Tracer::phong_hit(const Material& m, const Hit& hit, const dvec3& p, const dvec3& n, const Branch& b,
                        const Media& beyond, bool sheet, std::uint32_t seed_d, Branch& reflected, Branch& refracted,
                        double& rays) const {
    const bool clear = m.transparent();
    Appearance look = appearance_at(m, hit, p, n);
    dvec3 scale = b.weight * (1.0 - m.reflection);
    dvec3 color = scale * shade_local(m, look.pigment, p, n, look.normal, b.ray.dir, b.media, seed_d, scale, rays);
    if (photons_ && m.diffuse > 0.0) {
        // Caustics and indirect light: the diffuse BRDF k_d C' / pi times the photons' irradiance.
        dvec3 irradiance = photons_->irradiance(p, n);
        color += scale * (m.diffuse / kPi) * look.pigment * (1.0 - m.transmission) * irradiance;
    }
    // A bump or a smooth mesh tilts the mirror direction, and the refracted one where it can.
    reflected = {{p + ray_offset(p, offset_origin_) * n, bounce_direction(b.ray.dir, look.normal, n)}, p, b.weight * m.reflection,
                 b.depth + 1, b.media};
    refracted = {{p, b.ray.dir}, p, dvec3(0.0), b.depth + 1, beyond};
    if (clear) {
        // Fresnel splits what the surface transmits between the mirror and the refracted ray.
        double n1 = ior_of(b.media);
        double n2 = sheet ? m.ior : ior_of(beyond);
        // About the shading normal, as POV-Ray bends light; grazing it, all is reflected.
        const dvec3 bend = sheet ? n : look.normal;
        double cos_i = std::max(-glm::dot(b.ray.dir, bend), 0.0);
        Fresnel f = fresnel(cos_i, n1, n2);
        dvec3 passing = b.weight * (1.0 - m.reflection) * m.transmission;
        reflected.weight += passing * f.reflectance;
        refracted.weight = passing * (1.0 - f.reflectance);
        if (!sheet) refracted.ray.dir = crossing_direction(refract(b.ray.dir, bend, n1 / n2, cos_i, f.cos_t), n);
        refracted.ray.origin = past_surface(hit.object->shape, p, n, refracted.ray.dir, ray_offset(p, offset_origin_));
    }
    return color;
}

dvec3 Tracer::microfacet_hit(const Material& m, const Hit& hit, const dvec3& p, const dvec3& n, const Branch& b,
                             const Media& beyond, bool sheet, std::uint32_t seed_d, Branch& reflected,
                             Branch& refracted, double& rays) const {
    const MicrofacetTerms& terms = terms_[hit.material];
    const dvec3 wo = -b.ray.dir;
    const double n1 = ior_of(b.media);
    const double n2 = sheet ? m.ior : ior_of(beyond);
    dvec3 color = b.weight * shade_microfacet(m, terms, p, n, wo, n1, n2, b.media, seed_d, b.weight, rays);
    const std::array<double, 3> u = surface_sample_numbers(seed_d);
    reflected = {{p + ray_offset(p, offset_origin_) * n, dvec3(0.0)}, p, dvec3(0.0), b.depth + 1, b.media};
    refracted = {{p, b.ray.dir}, p, dvec3(0.0), b.depth + 1, beyond};
    if (m.conductor) {
        Scattered s = sample_metal(m, terms, n, wo, u);
        reflected.ray.dir = s.dir;
        reflected.weight = b.weight * s.weight;
        return color;
    }
    // A thin sheet has no inside to bend into: it reflects and transmits as a smooth one.
    GlassSplit split = sample_glass(m, sheet ? 0.0 : terms.alpha, n, wo, n1, n2, u);
    reflected.ray.dir = split.reflected.dir;
    reflected.weight = b.weight * split.reflected.weight;
    refracted.weight = b.weight * split.refracted.weight;
    if (!sheet) refracted.ray.dir = split.refracted.dir;
    refracted.ray.origin = past_surface(hit.object->shape, p, n, refracted.ray.dir, ray_offset(p, offset_origin_));
    return color;
}

dvec3 Tracer::trace(Ray camera_ray, std::uint32_t seed, double& rays) const {
    const double inf = std::numeric_limits<double>::infinity();
    dvec3 color(0.0);
    Branch b{camera_ray, camera_ray.origin, dvec3(1.0), 0, Media{}};
    int passes = 0;  // surfaces passed through on this path
    std::array<Branch, kPendingSize> pending;
    std::size_t waiting = 0;
    for (;;) {
        rays += 1.0;
        Hit hit;
        bool found = closest_hit(b.ray, 0.0, inf, hit);
        // Media absorb between surface points (not from the offset origin): the true thickness.
        if (b.media.size() > 0) b.weight *= absorption_along(b.media, found ? glm::length(b.ray.origin + hit.t * b.ray.dir - b.from) : inf);
        if (scene_.fog) {  // the fog in front of what the ray meets, and its veil over it
            const double length = found ? glm::length(b.ray.origin + hit.t * b.ray.dir - b.from) : inf;
            const double through = std::exp(-fog_depth(*scene_.fog, b.from, glm::normalize(b.ray.dir), length) / scene_.fog->distance);
            color += b.weight * (1.0 - through) * scene_.fog->color;
            b.weight *= through;
        }
        bool goes_on = false;
        if (!found) {
            color += b.weight * (scene_.sky ? sky_color(*scene_.sky, b.ray.dir) : scene_.render.background);
        } else {
            dvec3 p = b.ray.origin + hit.t * b.ray.dir;
            dvec3 n = glm::dot(hit.normal, b.ray.dir) > 0.0 ? -hit.normal : hit.normal;  // two-sided
            const Material& m = scene_.materials[hit.material];
            const bool clear = m.transparent();
            const bool sheet = clear && is_thin_sheet(hit.object->shape);
            Media beyond = clear && !sheet ? b.media.crossed(hit.material) : b.media;
            if (clear && !sheet && beyond.innermost() == b.media.innermost()) {
                // The same medium on both sides (a liquid's wall inside its glass): invisible.
                b.media = beyond;
                b.ray = {past_surface(hit.object->shape, p, n, b.ray.dir, ray_offset(p, offset_origin_)), b.ray.dir};
                b.from = p;
                goes_on = ++passes <= kMaxPassThrough;
            } else {
                Branch reflected, refracted;
                std::uint32_t seed_d = hash_u32(seed + std::uint32_t(b.depth));
                color += m.microfacet() ? microfacet_hit(m, hit, p, n, b, beyond, sheet, seed_d, reflected, refracted, rays)
                                        : phong_hit(m, hit, p, n, b, beyond, sheet, seed_d, reflected, refracted, rays);
                // Past max_depth the children contribute black (POV-Ray's max_trace_level rule);
                // a material that spawns no rays (the predicate the GPU's grids rely on) ends the path.
                const bool spawns = m.spawns_secondary_rays() && b.depth < scene_.render.max_depth;
                bool reflects = spawns && max_of(reflected.weight) >= kMinWeight;
                bool refracts = spawns && max_of(refracted.weight) >= kMinWeight;
                if (reflects && refracts) {
                    // The heavier goes on now, the lighter waits (dropped when the stack is full).
                    bool reflected_first = max_of(reflected.weight) > max_of(refracted.weight);
                    if (waiting < kPendingSize) pending[waiting++] = reflected_first ? refracted : reflected;
                    b = reflected_first ? reflected : refracted;
                } else if (reflects || refracts) {
                    b = reflects ? reflected : refracted;
                }
                goes_on = reflects || refracts;
            }
        }
        if (goes_on) continue;
        if (waiting == 0) return color;
        b = pending[--waiting];
        passes = 0;
    }
}

}  // namespace lancer::cpu
