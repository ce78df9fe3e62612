// Light helpers of the scene model (scene.hpp).
#include <glm/geometric.hpp>

#include "scene/scene.hpp"

namespace lancer {

void aim_spot(Light& light) {
    if (light.type != LightType::Spot || !light.point_at) return;
    dvec3 axis = *light.point_at - light.position;
    if (glm::length(axis) > 0.0) light.direction = glm::normalize(axis);  // else keep the last direction
}

}  // namespace lancer
