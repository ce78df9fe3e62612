#pragma once
// The CPU reference tracer: the model of shaders/trace.comp, written for clarity in double
// precision, sharing the scene model but none of the shader's code.
#include <glm/vec2.hpp>

#include <cstdint>
#include <vector>

#include "accel/bvh.hpp"
#include "cpu/dielectric.hpp"
#include "cpu/microfacet.hpp"
#include "cpu/ray.hpp"
#include "render/renderer.hpp"
#include "scene/camera.hpp"

namespace lancer::cpu {

class PhotonMaps;  // cpu/photon_map.hpp

struct Hit {
    double t;
    dvec3 normal;  // unit, not yet facing the ray
    glm::dvec2 uv;
    int part;  // patch index within a Bezier surface, triangle of a mesh, else -1
    const Object* object;
    std::uint32_t material;  // the object's, or a mesh triangle's or a set sphere's own (part_material)
};

class Tracer {
public:
    // With a cache, a BVH over the same boxes as the last one is not built again (animations).
    explicit Tracer(const Scene& scene, Acceleration acceleration = Acceleration::Bvh, BvhCache* cache = nullptr);

    // Colour seen along `ray`, following the ray tree of reflections and refractions; adds every
    // ray traced to `rays`. `seed` identifies the camera sample (camera_sample_seed in
    // cpu/lights.hpp), for the places of area light samples.
    dvec3 trace(Ray ray, std::uint32_t seed, double& rays) const;

    // Photon mapping: diffuse hits add the irradiance these maps estimate (caustics and indirect
    // light), and shadow rays stop at transparent surfaces, since the light through them arrives
    // as photons. nullptr: the plain ray tracer.
    void use_photons(const PhotonMaps* photons) { photons_ = photons; }

    bool closest_hit(const Ray& ray, double t_min, double t_max, Hit& hit) const;
    bool occluded(const Ray& ray, double t_min, double t_max) const;

    // Ambient + per light (sample) diffuse and specular at p of a surface with this pigment. n is
    // the geometric normal (facing the viewer: which lights are in front, where shadow rays
    // start), shading_n the normal that lights it (n, or tilted by a bump). view_dir is the ray's,
    // which travels inside `media`; `seed` places area light samples; `scale` is what the result
    // is multiplied by on its way to the pixel, for skipping samples too faint to matter.
    dvec3 shade_local(const Material& m, const dvec3& pigment, const dvec3& p, const dvec3& n, const dvec3& shading_n,
                      const dvec3& view_dir, const Media& media, std::uint32_t seed, const dvec3& scale,
                      double& rays) const;

    // The fraction of a light's colour that reaches the surface point `from` from the light point
    // q, along a straight shadow ray starting at `origin` (just off the surface) inside `media`:
    // 0 behind an opaque surface; tinted by transparent ones and absorbed by media on the way.
    dvec3 transmittance(dvec3 from, dvec3 origin, const dvec3& q, Media media) const;

    // A microfacet material's direct light: per light sample the BRDF toward the viewer (wo) times
    // the light's irradiance, for an interface from index n1 to n2 (glass).
    dvec3 shade_microfacet(const Material& m, const MicrofacetTerms& terms, const dvec3& p, const dvec3& n,
                           const dvec3& wo, double n1, double n2, const Media& media, std::uint32_t seed,
                           const dvec3& scale, double& rays) const;

    const std::vector<MicrofacetTerms>& terms() const { return terms_; }
    const Scene& scene() const { return scene_; }

    dvec3 absorption_along(const Media& media, double distance) const;  // by the innermost medium
    double ior_of(const Media& media) const;                             // of the innermost medium, 1 for air

private:
    // A ray of the tree waiting to be traced.
    struct Branch {
        Ray ray;
        dvec3 from;  // the surface point the ray leaves; its origin is just off it
        dvec3 weight;
        int depth;
        Media media;
    };
    // What a visible hit adds to the pixel, and the children it spawns (with their weights) for
    // each model: `beyond` is the media past the surface, `seed_d` the seed of this depth.
    dvec3 phong_hit(const Material& m, const Hit& hit, const dvec3& p, const dvec3& n, const Branch& b,
                    const Media& beyond, bool sheet, std::uint32_t seed_d, Branch& reflected, Branch& refracted,
                    double& rays) const;
    dvec3 microfacet_hit(const Material& m, const Hit& hit, const dvec3& p, const dvec3& n, const Branch& b,
                         const Media& beyond, bool sheet, std::uint32_t seed_d, Branch& reflected, Branch& refracted,
                         double& rays) const;
    // Whether a shadow ray from `origin` to q is blocked (any surface, transparent or not).
    bool shadowed(const dvec3& origin, const dvec3& q) const;

    // Calls visit(object) for every object whose box the ray enters within [0, t_max()], nearest
    // boxes first; visit returns false to stop. t_max is re-read as hits shrink the interval.
    template <typename Visit, typename TMax>
    void for_each_candidate(const Ray& ray, TMax t_max, Visit visit) const;

    const Scene& scene_;
    const dvec3 offset_origin_ = working_origin(scene_.camera);  // what ray offsets scale with
    bool has_transparency_ = false;  // without, shadow rays only ask whether anything is in the way
    std::vector<MicrofacetTerms> terms_;  // per material
    const PhotonMaps* photons_ = nullptr;
    std::vector<const Object*> unbounded_;  // tested by every ray (planes; everything without a BVH)
    std::vector<const Object*> bounded_;    // in BVH leaf order
    std::shared_ptr<const Bvh> bvh_;  // its nodes; shared with the renderer's BvhCache, not copied
};

// The colour or checker part of a material's pigment at a point (cpu/appearance.hpp adds
// textures and patterns).
dvec3 pigment_at(const Material& m, const dvec3& p);

}  // namespace lancer::cpu
