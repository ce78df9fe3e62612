// POV-Ray's superellipsoid, a shape of its own (scene/scene.hpp's Superellipsoid, drawn by
// shaders/shapes/superellipsoid.glsl and cpu/shapes/superellipsoid.cpp):
//
//   type = "superellipsoid"   e = 0.25   n = 0.5
//       POV-Ray's superellipsoid { <e, n> }: (|x|^(2/e) + |y|^(2/e))^(e/n) + |z|^(2/n) = 1, in [-1, 1]^3
#include <fmt/format.h>

#include "scene/parse_surfaces.hpp"

namespace lancer {

// e and n within [0.001, 2]: toward 0 the shape becomes the cube (exponents up to 2000); at 2 its
// edges are straight (the octahedron's); beyond, the solid is not convex and the surface has
// cusps whose gradient is infinite on the axes, which the searches are not proved for. Within
// the range, the exponents 2/e and 2/n are at least 1 and the solid is convex (scene.hpp).
Shape read_superellipsoid(TableReader& t, const glm::dmat4&) {
    auto exponent = [&](const char* key) {
        const double v = t.required_number(key);
        if (!(v >= 0.001 && v <= 2.0))
            t.fail(key, fmt::format("superellipsoid {} must be in [0.001, 2], not {:g} (0.001 is the cube to 0.06% of its "
                                    "size; beyond 2 the surface has cusps on its axes, which lancer does not draw)",
                                    key, v));
        return v;
    };
    Superellipsoid o;
    o.e = exponent("e");
    o.n = exponent("n");
    return o;
}

}  // namespace lancer
