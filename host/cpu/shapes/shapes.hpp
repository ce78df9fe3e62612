#pragma once
// Ray/shape intersection for the CPU reference, one .cpp per shape family (the twins of
// shaders/shapes/*.glsl). intersect() returns the nearest hit with t in (t_min, t_max), or
// nothing, with the unit geometric normal there (not yet turned toward the ray) and the
// surface's own (u, v) where it has them.
#include <optional>

#include <glm/vec2.hpp>

#include "cpu/ray.hpp"

namespace lancer::cpu {

struct SurfaceHit {
    double t;
    dvec3 normal;
    glm::dvec2 uv{0.0};
    int part = -1;  // which patch of a Bezier surface
};

std::optional<SurfaceHit> intersect(const Sphere& s, const Ray& ray, double t_min, double t_max);
std::optional<SurfaceHit> intersect(const Plane& p, const Ray& ray, double t_min, double t_max);
std::optional<SurfaceHit> intersect(const Rectangle& r, const Ray& ray, double t_min, double t_max);
std::optional<SurfaceHit> intersect(const Box& b, const Ray& ray, double t_min, double t_max);

}  // namespace lancer::cpu
