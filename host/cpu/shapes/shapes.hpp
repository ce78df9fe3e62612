#pragma once
// Ray/shape intersection for the CPU reference, one .cpp per shape family (the twins of
// shaders/shapes/*.glsl). intersect() returns the nearest t in (t_min, t_max), or nothing;
// normal() returns the unit geometric normal at a point on the surface (not yet facing the ray).
#include <optional>

#include "cpu/ray.hpp"

namespace lancer::cpu {

std::optional<double> intersect(const Sphere& s, const Ray& ray, double t_min, double t_max);
dvec3 normal(const Sphere& s, const dvec3& p);

std::optional<double> intersect(const Plane& p, const Ray& ray, double t_min, double t_max);
dvec3 normal(const Plane& p, const dvec3& point);

std::optional<double> intersect(const Rectangle& r, const Ray& ray, double t_min, double t_max);
dvec3 normal(const Rectangle& r, const dvec3& point);

std::optional<double> intersect(const Box& b, const Ray& ray, double t_min, double t_max);
dvec3 normal(const Box& b, const dvec3& point);

}  // namespace lancer::cpu
