#include "scene/transform.hpp"

#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

namespace lancer {
namespace {

// One table { scale = s | [sx,sy,sz], rotate = [ax,ay,az], translate = [x,y,z] } in S, R, T order.
glm::dmat4 read_step(const toml::table& table, const std::string& file) {
    TableReader t(table, file, "transform");
    glm::dmat4 m(1.0);
    if (const toml::node* node = t.node("scale")) {
        dvec3 s = node->is_array() ? node_vec3(*node, file, "scale") : dvec3(node_number(*node, file, "scale"));
        if (s.x == 0.0 || s.y == 0.0 || s.z == 0.0) t.fail("scale", "scale must not be zero on any axis");
        m = glm::scale(glm::dmat4(1.0), s) * m;
    }
    m = rotation_degrees(t.vec3("rotate", dvec3(0.0))) * m;
    m = glm::translate(glm::dmat4(1.0), t.vec3("translate", dvec3(0.0))) * m;
    t.finish();
    return m;
}

}  // namespace

glm::dmat4 rotation_degrees(const dvec3& angles) {
    dvec3 r = glm::radians(angles);
    glm::dmat4 m = glm::rotate(glm::dmat4(1.0), r.x, dvec3(1, 0, 0));
    m = glm::rotate(glm::dmat4(1.0), r.y, dvec3(0, 1, 0)) * m;
    m = glm::rotate(glm::dmat4(1.0), r.z, dvec3(0, 0, 1)) * m;
    return m;
}

glm::dmat4 read_transform(TableReader& object) {
    const toml::node* node = object.node("transform");
    if (!node) return glm::dmat4(1.0);
    if (const toml::table* table = node->as_table()) return read_step(*table, object.file());
    const toml::array* steps = node->as_array();
    if (!steps) object.fail("transform", "transform must be a table { scale, rotate, translate } or a list of them");
    glm::dmat4 m(1.0);
    for (const toml::node& step : *steps) {
        const toml::table* table = step.as_table();
        if (!table) throw SceneError(location_of(step, object.file()), "transform list entries must be tables");
        m = read_step(*table, object.file()) * m;
    }
    return m;
}

}  // namespace lancer
