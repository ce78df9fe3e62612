#pragma once
// The CPU reference's dielectrics: the media a ray is inside, Fresnel's equations, Snell's law
// and Beer-Lambert absorption, in double precision. Written independently of
// shaders/dielectric.glsl; docs/scene-format.md ("Refraction") states the model both follow.
#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>

#include "scene/scene.hpp"

namespace lancer::cpu {

// A path passes through at most this many surfaces that do not show (a surface with the same
// medium on both sides, such as a liquid's wall inside its glass), as the shader's MAX_PASS_THROUGH.
inline constexpr int kMaxPassThrough = 16;

// The transparent materials (indices into Scene::materials) a ray is inside. Crossing a surface
// of a transparent material toggles being inside it; the innermost material is the medium the
// ray travels in (none: air, index of refraction 1).
class Media {
public:
    static constexpr std::size_t kDepth = 4;  // beyond this, the outermost medium is forgotten

    std::optional<std::uint32_t> innermost() const;
    // The media after crossing a surface of `material`: its innermost entry removed if the ray is
    // inside it, else `material` added as the innermost.
    Media crossed(std::uint32_t material) const;
    std::size_t size() const { return count_; }

private:
    std::array<std::uint32_t, kDepth> materials_{};  // outermost first
    std::size_t count_ = 0;
};

// Unpolarised reflectance of a dielectric interface, light going from index n1 to index n2 at
// an angle of incidence with cosine cos_i (> 0); 1 beyond the critical angle (total internal
// reflection), where cos_t is 0.
struct Fresnel {
    double reflectance;
    double cos_t;  // cosine of the angle of refraction
};
Fresnel fresnel(double cos_i, double n1, double n2);

// Snell's law: the refracted direction of unit d at a surface with unit normal n facing d's
// origin, for eta = n1 / n2 and the cosines of fresnel().
dvec3 refract(const dvec3& d, const dvec3& n, double eta, double cos_i, double cos_t);

// A refracted direction t kept across the surface of geometric normal n (facing the incoming ray):
// refraction about a shading normal (a smooth mesh's, a bump's) can bend a grazing ray back out;
// such a t is mirrored in the surface's plane, which leaves every t that crosses it unchanged and
// turns continuously (bounce_direction's rule for mirror rays). Twin of shaders/dielectric.glsl's.
dvec3 crossing_direction(const dvec3& t, const dvec3& n);

// Beer-Lambert: the fraction of light left after `distance` through a medium of absorption
// coefficient a (per unit distance, per channel); a channel with a = 0 keeps everything.
dvec3 beer_lambert(const dvec3& a, double distance);

// Where a ray going on through a surface at p (unit normal n, either side) in direction d starts:
// on its own line, `offset` (ray_offset) past the tangent plane like every secondary ray, but at most
// 100 ray_offset along the ray for grazing rays. On the line, paths through media keep their
// true length (Beer-Lambert).
dvec3 past_surface(const dvec3& p, const dvec3& n, const dvec3& d, double offset);
// The same for a hit on `shape`: a mesh's facet meets neighbours that turn at its edges, which a
// grazing ray carried along its line could pass to their far side; there it starts straight
// across, `offset` off the facet (its path through a medium is then longer by at most that).
dvec3 past_surface(const Shape& shape, const dvec3& p, const dvec3& n, const dvec3& d, double offset);

// Shapes without an inside (SHAPE_SHEET: rectangles) are, transparent, thin sheets, which reflect and
// transmit without bending the ray or changing the medium.
bool is_thin_sheet(const Shape& shape);

}  // namespace lancer::cpu
