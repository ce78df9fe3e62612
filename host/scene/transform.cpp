#include "scene/transform.hpp"

#include <cmath>

#include <fmt/format.h>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/matrix.hpp>

#include "core/magnitude.hpp"

namespace lancer {
namespace {

// One table { scale = s | [sx,sy,sz], rotate = [ax,ay,az], translate = [x,y,z] } in S, R, T order.
glm::dmat4 read_step(const toml::table& table, const std::string& file) {
    TableReader t(table, file, "transform");
    glm::dmat4 m(1.0);
    if (const toml::node* node = t.node("matrix")) {
        // POV-Ray's matrix <a, b, c, d, e, f, g, h, i, tx, ty, tz>: a point (x, y, z) becomes
        // (x a + y d + z g + tx, x b + y e + z h + ty, x c + y f + z i + tz).
        const toml::array* entries = node->as_array();
        if (!entries || entries->size() != 12)
            t.fail("matrix", "matrix must be a list of 12 numbers, as POV-Ray's matrix <a, b, c, d, e, f, g, h, i, tx, ty, tz>");
        for (const char* other : {"scale", "rotate", "translate"})
            if (t.has(other)) t.fail("matrix", std::string("matrix cannot share its table with ") + other + ": give them as separate entries of a transform list");
        for (int k = 0; k < 12; ++k) m[k / 3][k % 3] = node_number(*entries->get(std::size_t(k)), file, "matrix");
        if (!(std::abs(glm::determinant(glm::dmat3(m))) > 0.0)) t.fail("matrix", "matrix is singular: it flattens the object");
        t.finish();
        return m;
    }
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

// NaN counts as infinite: the inverse of a matrix whose determinant underflows is NaN.
double largest_linear_entry(const glm::dmat4& m) {
    double largest = 0.0;
    for (int c = 0; c < 3; ++c)
        for (int r = 0; r < 3; ++r) largest = std::isnan(m[c][r]) ? HUGE_VAL : std::max(largest, std::abs(m[c][r]));
    return largest;
}

// The GPU maps rays into a surface's own space through the inverse, in float: a scale of 1e-300
// is a valid matrix in double whose inverse is infinite in float
// (tests/fuzz/regressions/scene/transform-scale-whose-inverse-float-cannot-hold.toml). The
// matrix and its inverse both stay within lancer's limit for any number, so every product the
// tracer forms with them stays finite. Largest entries stand for the scale factors: exact for a
// scale alone, within a factor of 3 whatever the rotation.
void check_scales(TableReader& object, const glm::dmat4& m) {
    const double largest = largest_linear_entry(m), smallest = 1.0 / largest_linear_entry(glm::inverse(m));
    if (!(largest <= kMaxMagnitude && smallest >= 1.0 / kMaxMagnitude))
        object.fail("transform", fmt::format("transform scales by factors from about {:g} to {:g}, outside lancer's range of "
                                             "{:g} to {:g}: the GPU maps rays through the transform and its inverse in float",
                                             smallest, largest, 1.0 / kMaxMagnitude, kMaxMagnitude));
}

glm::dmat4 read_steps(TableReader& object) {
    const toml::node* node = object.node("transform");
    if (!node) return glm::dmat4(1.0);
    if (const toml::table* table = node->as_table()) return read_step(*table, object.file());
    const toml::array* steps = node->as_array();
    if (!steps) object.fail("transform", "transform must be a table { scale, rotate, translate } or { matrix }, or a list of them");
    glm::dmat4 m(1.0);
    for (const toml::node& step : *steps) {
        const toml::table* table = step.as_table();
        if (!table) throw SceneError(location_of(step, object.file()), "transform list entries must be tables");
        m = read_step(*table, object.file()) * m;
    }
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

glm::dmat4 read_transform(TableReader& object, const glm::dmat4& parent) {
    const glm::dmat4 m = parent * read_steps(object);
    check_scales(object, m);
    return m;
}

}  // namespace lancer
