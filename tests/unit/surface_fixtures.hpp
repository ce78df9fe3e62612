#pragma once
// The classic parametric surfaces the surface tests run on, as users would write them.
#include <numbers>
#include <string>
#include <vector>

#include "surface/expr/parser.hpp"
#include "surface/parametric_surface.hpp"

namespace lancer::test {

struct SurfaceSpec {
    std::string name;
    std::string x, y, z;
    double u0, u1, v0, v1;
    surface::Constants params;
};

inline const std::vector<SurfaceSpec>& classic_surfaces() {
    constexpr double pi = std::numbers::pi;
    static const std::vector<SurfaceSpec> specs{
        {"torus", "(R + r*cos(v))*cos(u)", "(R + r*cos(v))*sin(u)", "r*sin(v)", 0, 2 * pi, 0, 2 * pi,
         {{"R", 1.0}, {"r", 0.35}}},
        {"sphere", "R*cos(u)*cos(v)", "R*sin(u)*cos(v)", "R*sin(v)", 0, 2 * pi, -pi / 2, pi / 2, {{"R", 1.5}}},
        {"mobius", "(1 + v/2*cos(u/2))*cos(u)", "(1 + v/2*cos(u/2))*sin(u)", "v/2*sin(u/2)", 0, 2 * pi, -1, 1, {}},
        {"klein8", "(a + cos(u/2)*sin(v) - sin(u/2)*sin(2*v))*cos(u)",
         "(a + cos(u/2)*sin(v) - sin(u/2)*sin(2*v))*sin(u)", "sin(u/2)*sin(v) + cos(u/2)*sin(2*v)", 0, 2 * pi, 0,
         2 * pi, {{"a", 2.0}}},
        {"enneper", "u - u^3/3 + u*v^2", "v - v^3/3 + v*u^2", "u^2 - v^2", -2, 2, -2, 2, {}},
        {"dini", "a*cos(u)*sin(v)", "a*sin(u)*sin(v)", "a*(cos(v) + log(tan(v/2))) + b*u", 0, 4 * pi, 0.01, 2,
         {{"a", 1.0}, {"b", 0.2}}},
    };
    return specs;
}

inline surface::ParametricSurface make_surface(const SurfaceSpec& spec) {
    surface::ParametricSurface s;
    s.x = surface::parse_expression(spec.x, spec.params);
    s.y = surface::parse_expression(spec.y, spec.params);
    s.z = surface::parse_expression(spec.z, spec.params);
    s.u0 = spec.u0;
    s.u1 = spec.u1;
    s.v0 = spec.v0;
    s.v1 = spec.v1;
    return s;
}

inline const SurfaceSpec& surface_spec(const std::string& name) {
    for (const auto& s : classic_surfaces())
        if (s.name == name) return s;
    throw std::out_of_range(name);
}

}  // namespace lancer::test
