// Photon mapping's scene-level rules (scene.hpp): the radius schedule and which lights can shoot.
#include <cmath>

#include "scene/scene.hpp"

namespace lancer {

double photon_radius(double first_radius, double alpha, int pass) {
    double r2 = first_radius * first_radius;
    for (int i = 1; i <= pass; ++i) r2 *= (i - 1 + alpha) / i;
    return std::sqrt(r2);
}

void check_photon_lights(const Scene& scene) {
    for (const Light& light : scene.lights)
        if (!radiant_flux(light))
            throw SceneError(light.where, "photon mapping shoots photons by power, and this light has none: give it "
                                          "power or intensity (watts), or falloff = \"inverse_square\"");
}

}  // namespace lancer
