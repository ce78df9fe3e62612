#include "cpu/photon_tracer.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <system_error>
#include <thread>

#include <glm/geometric.hpp>

#include "core/constants.hpp"
#include "cpu/appearance.hpp"
#include "cpu/lights.hpp"
#include "cpu/microfacet.hpp"
#include "scene/camera.hpp"

namespace lancer::cpu {
namespace {

dvec3 uniform_sphere(double u1, double u2) {
    double z = 1.0 - 2.0 * u1;
    double r = std::sqrt(std::max(0.0, 1.0 - z * z));
    double phi = 2.0 * kPi * u2;
    return {r * std::cos(phi), r * std::sin(phi), z};
}

// Any two unit vectors perpendicular to n and to each other.
void tangents(const dvec3& n, dvec3& t, dvec3& b) {
    t = glm::normalize(std::abs(n.x) > 0.5 ? glm::cross(n, dvec3(0.0, 1.0, 0.0)) : glm::cross(n, dvec3(1.0, 0.0, 0.0)));
    b = glm::cross(n, t);
}

// A direction about n with density cos(theta) / pi.
dvec3 cosine_direction(const dvec3& n, double u1, double u2) {
    dvec3 t, b;
    tangents(n, t, b);
    double r = std::sqrt(u1), phi = 2.0 * kPi * u2;
    return glm::normalize(r * std::cos(phi) * t + r * std::sin(phi) * b + std::sqrt(std::max(0.0, 1.0 - u1)) * n);
}

struct Emitter {
    std::uint32_t index;
    dvec3 flux;
    double cdf;  // the probability of this light or one before it
    // spot lights: the solid angle of the outer cone over the spot's weighted one
    double cone_over_spot = 1.0;
};

// Picks one of `choices` (their probabilities, summing to at most 1) with u, or none (-1: the
// photon is absorbed: Russian roulette).
int choose(const double* p, int n, double u) {
    for (int i = 0; i < n; ++i) {
        if (u < p[i]) return i;
        u -= p[i];
    }
    return -1;
}

class PhotonShooter {
public:
    PhotonShooter(const Tracer& tracer, bool keep_direct) : tracer_(tracer), scene_(tracer.scene()), keep_direct_(keep_direct) {
        double total = 0.0;
        for (std::uint32_t i = 0; i < scene_.lights.size(); ++i) {
            dvec3 flux = *radiant_flux(scene_.lights[i]);
            total += flux.r + flux.g + flux.b;
            emitters_.push_back({i, flux, total});
            const Light& light = scene_.lights[i];
            if (light.type == LightType::Spot) {
                double cos_outer = std::cos(light.outer_angle_deg * kPi / 180.0);
                emitters_.back().cone_over_spot = 2.0 * kPi * (1.0 - cos_outer) / spot_solid_angle(light);
            }
        }
        total_ = total;
        for (Emitter& e : emitters_) e.cdf /= total;
    }

    void shoot(int pass, std::uint32_t first, std::uint32_t last, StoredPhotons& out) const {
        const PhotonSettings& settings = *scene_.photons;
        for (std::uint32_t i = first; i < last; ++i) {
            if (total_ <= 0.0) return;
            PhotonRandom rng(settings.seed, static_cast<std::uint32_t>(pass), i);
            double u = rng.next();
            const Emitter* e = &emitters_.back();
            for (const Emitter& candidate : emitters_)
                if (u < candidate.cdf) {
                    e = &candidate;
                    break;
                }
            const Light& light = scene_.lights[e->index];
            // flux / (N P(light)), P(light) its share of the total
            dvec3 power = e->flux * (total_ / (e->flux.r + e->flux.g + e->flux.b)) / double(settings.count);
            dvec3 origin = light.position;
            dvec3 dir;
            if (light.type == LightType::Spot) {
                // Uniform in the outer cone, weighted by the spot factor: the cone's solid angle
                // over the spot's weighted one keeps the mean power.
                double cos_outer = std::cos(light.outer_angle_deg * kPi / 180.0);
                double cos_theta = 1.0 - rng.next() * (1.0 - cos_outer);
                double phi = 2.0 * kPi * rng.next();
                double sin_theta = std::sqrt(std::max(0.0, 1.0 - cos_theta * cos_theta));
                dvec3 t, b;
                tangents(light.direction, t, b);
                dir = glm::normalize(sin_theta * (std::cos(phi) * t + std::sin(phi) * b) + cos_theta * light.direction);
                power *= spot_factor(light, dir) * e->cone_over_spot;
            } else {
                if (light.type == LightType::Area) {
                    double a = rng.next() - 0.5, b = rng.next() - 0.5;
                    origin += a * light.edge_u + b * light.edge_v;
                }
                double u1 = rng.next(), u2 = rng.next();
                dir = uniform_sphere(u1, u2);
            }
            if (max_of(power) > 0.0) trace(Ray{origin, dir}, power, rng, out);
        }
    }

private:
    void store(const Photon& photon, int bounces, bool specular_only, StoredPhotons& out) const {
        if (bounces == 0) {
            if (keep_direct_) out.direct.push_back(photon);
        } else {
            (specular_only ? out.caustic : out.global).push_back(photon);
        }
    }

    void trace(Ray ray, dvec3 power, PhotonRandom& rng, StoredPhotons& out) const {
        const int max_bounces = scene_.photons->max_bounces;
        Media media;
        dvec3 from = ray.origin;
        bool specular_only = true;  // every bounce so far off a mirror, glass or metal
        int bounces = 0, passes = 0;
        while (bounces < max_bounces) {
            Hit hit;
            if (!tracer_.closest_hit(ray, 0.0, std::numeric_limits<double>::infinity(), hit)) return;
            dvec3 p = ray.origin + hit.t * ray.dir;
            if (media.size() > 0) power *= tracer_.absorption_along(media, glm::length(p - from));
            dvec3 n = glm::dot(hit.normal, ray.dir) > 0.0 ? -hit.normal : hit.normal;  // facing the photon
            const Material& m = scene_.materials[hit.material];
            const bool clear = m.transparent();
            const bool sheet = clear && is_thin_sheet(hit.object->shape);
            Media beyond = clear && !sheet ? media.crossed(hit.material) : media;
            from = p;
            if (clear && !sheet && beyond.innermost() == media.innermost()) {
                media = beyond;  // a surface that does not show
                ray = {past_surface(hit.object->shape, p, n, ray.dir, ray_offset(p, offset_origin_)), ray.dir};
                if (++passes > kMaxPassThrough) return;
                continue;
            }
            const double n1 = tracer_.ior_of(media);
            const double n2 = sheet ? m.ior : tracer_.ior_of(beyond);
            const dvec3 wo = -ray.dir;
            dvec3 weight(0.0);
            bool refracts = false;
            if (m.microfacet()) {
                std::array<double, 3> u = {rng.next(), rng.next(), rng.next()};
                if (m.conductor) {
                    Scattered s = sample_metal(m, tracer_.terms()[hit.material], n, wo, u);
                    double p_keep = std::min(1.0, max_of(s.weight));
                    if (!(rng.next() < p_keep)) return;
                    ray.dir = s.dir;
                    weight = s.weight / p_keep;
                } else {
                    GlassSplit split = sample_glass(m, sheet ? 0.0 : m.alpha(), n, wo, n1, n2, u);
                    double probabilities[2] = {max_of(split.reflected.weight), max_of(split.refracted.weight)};
                    double sum = probabilities[0] + probabilities[1];
                    if (sum > 1.0) probabilities[0] /= sum, probabilities[1] /= sum;
                    int event = choose(probabilities, 2, rng.next());
                    if (event < 0) return;
                    const Scattered& s = event == 0 ? split.reflected : split.refracted;
                    weight = s.weight / probabilities[event];
                    refracts = event == 1;
                    ray.dir = refracts && sheet ? ray.dir : s.dir;
                }
            } else {
                Appearance look = appearance_at(m, hit, p, n);
                const dvec3 transmission = clear ? m.transmission : dvec3(0.0);
                const dvec3 diffuse = (1.0 - m.reflection) * (1.0 - transmission) * m.diffuse * look.pigment;
                if (max_of(diffuse) > 0.0) store({p, ray.dir, power}, bounces, specular_only, out);
                const dvec3 bend = sheet ? n : look.normal;  // as Tracer::phong_hit bends light
                const double cos_i = std::max(glm::dot(wo, bend), 0.0);
                Fresnel f = clear ? fresnel(cos_i, n1, n2) : Fresnel{0.0, 0.0};
                const dvec3 passing = (1.0 - m.reflection) * transmission;
                const dvec3 weights[3] = {m.reflection + passing * f.reflectance, passing * (1.0 - f.reflectance), diffuse};
                double probabilities[3] = {max_of(weights[0]), max_of(weights[1]), max_of(weights[2])};
                double sum = probabilities[0] + probabilities[1] + probabilities[2];
                if (sum > 1.0)
                    for (double& q : probabilities) q /= sum;
                int event = choose(probabilities, 3, rng.next());
                if (event < 0) return;
                weight = weights[event] / probabilities[event];
                if (event == 0) {
                    ray.dir = bounce_direction(ray.dir, look.normal, n);
                } else if (event == 1) {
                    refracts = true;
                    if (!sheet) ray.dir = crossing_direction(refract(ray.dir, bend, n1 / n2, cos_i, f.cos_t), n);
                } else {
                    // Lambertian about the shading normal, kept above the geometric surface.
                    double u1 = rng.next(), u2 = rng.next();
                    dvec3 d = cosine_direction(look.normal, u1, u2);
                    if (glm::dot(d, n) <= 0.0) d = glm::normalize(d - 2.0 * glm::dot(d, n) * n);
                    ray.dir = d;
                    specular_only = false;
                }
            }
            power *= weight;
            if (max_of(power) <= 0.0) return;
            ++bounces;
            if (refracts) {
                media = beyond;
                ray.origin = past_surface(hit.object->shape, p, n, ray.dir, ray_offset(p, offset_origin_));
            } else {
                ray.origin = p + ray_offset(p, offset_origin_) * n;
            }
        }
    }

    const Tracer& tracer_;
    const Scene& scene_;
    const dvec3 offset_origin_ = working_origin(scene_.camera);  // what ray offsets scale with
    bool keep_direct_;
    std::vector<Emitter> emitters_;
    double total_ = 0.0;
};

}  // namespace

PhotonRandom::PhotonRandom(std::uint32_t seed, std::uint32_t pass, std::uint32_t photon)
    : base_(hash_u32(hash_u32(hash_u32(seed) ^ pass) ^ photon)) {}

double PhotonRandom::next() { return unit_interval(hash_u32(base_ ^ hash_u32(k_++))); }

StoredPhotons shoot_photons(const Tracer& tracer, int pass, unsigned threads, bool keep_direct) {
    const PhotonShooter shooter(tracer, keep_direct);
    const auto count = static_cast<std::uint32_t>(tracer.scene().photons->count);
    threads = std::max(1u, std::min<unsigned>(threads, count));
    // Contiguous ranges of photons per worker, joined in order: the same maps on any number of threads.
    std::vector<StoredPhotons> parts(threads);
    std::vector<std::thread> pool;
    auto run = [&](unsigned t) {
        shooter.shoot(pass, std::uint32_t(std::uint64_t(count) * t / threads),
                      std::uint32_t(std::uint64_t(count) * (t + 1) / threads), parts[t]);
    };
    // Where no more threads can start (an address-space limit), this one shoots the remaining
    // ranges itself: the same parts, so the same maps.
    unsigned started = 1;
    try {
        for (; started < threads; ++started) pool.emplace_back(run, started);
    } catch (const std::system_error&) {
    }
    run(0);
    for (unsigned t = started; t < threads; ++t) run(t);
    for (auto& t : pool) t.join();
    StoredPhotons out = std::move(parts[0]);
    for (unsigned t = 1; t < threads; ++t) {
        out.caustic.insert(out.caustic.end(), parts[t].caustic.begin(), parts[t].caustic.end());
        out.global.insert(out.global.end(), parts[t].global.begin(), parts[t].global.end());
        out.direct.insert(out.direct.end(), parts[t].direct.begin(), parts[t].direct.end());
    }
    return out;
}

}  // namespace lancer::cpu
