#include "cpu/texture.hpp"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include "cpu/shapes/shapes.hpp"

namespace lancer::cpu {

glm::dvec2 texture_uv(const Hit& hit, const dvec3& world_point) {
    // A shape kept in its own coordinates (an ellipsoid, a turned box) is mapped there.
    const HeapOptional<Placement>& placed = hit.object->placement;
    const bool local = placed && placed->shape_in_object_space;
    const dvec3 p = local ? placed->object_point(world_point) : world_point;
    const dvec3 normal = local ? glm::normalize(glm::transpose(glm::dmat3(placed->to_world)) * hit.normal) : hit.normal;
    struct Mapping {
        const Hit& hit;
        const dvec3& p;
        const dvec3& normal;
        glm::dvec2 operator()(const Sphere& s) const { return cpu::texture_uv(s, p); }
        glm::dvec2 operator()(const Plane& plane) const { return cpu::texture_uv(plane, p); }
        glm::dvec2 operator()(const Box& b) const { return cpu::texture_uv(b, p, normal); }
        glm::dvec2 operator()(const Rectangle&) const { return hit.uv; }         // (a, b) along the edges
        glm::dvec2 operator()(const Disc& d) const { return cpu::texture_uv(d, p); }
        glm::dvec2 operator()(const Cone& c) const { return cpu::texture_uv(c, p, int(hit.uv.x)); }  // uv.x: the part
        glm::dvec2 operator()(const Torus& o) const { return cpu::texture_uv(o, p); }
        glm::dvec2 operator()(const Mesh& m) const { return cpu::mesh_texture_uv(m, hit.part, hit.uv); }  // uv: barycentric
        glm::dvec2 operator()(const SphereSet& s) const { return cpu::sphere_set_texture_uv(s, hit.part, p); }
        glm::dvec2 operator()(const Csg&) const { return hit.uv; }  // never: a CSG hit is its leaf's (Tracer)
        glm::dvec2 operator()(const BezierSurface&) const { return hit.uv; }     // each patch's (u, v)
        glm::dvec2 operator()(const ParametricObject& o) const {                  // the domain, as [0, 1]^2
            const auto& s = *o.surface;
            return {(hit.uv.x - s.u0) / (s.u1 - s.u0), (hit.uv.y - s.v0) / (s.v1 - s.v0)};
        }
        glm::dvec2 operator()(const ImplicitObject&) const { return hit.uv; }  // x and y across the box
        glm::dvec2 operator()(const Blob& o) const { return cpu::texture_uv(o, p); }
        glm::dvec2 operator()(const Sor& o) const { return cpu::texture_uv(o, p); }
        glm::dvec2 operator()(const Prism& o) const { return cpu::texture_uv(o, p); }
        glm::dvec2 operator()(const Lathe& o) const { return cpu::texture_uv(o, p, hit.uv); }  // uv: (segment, s)
        glm::dvec2 operator()(const Superellipsoid& o) const { return cpu::texture_uv(o, p); }
    };
    return std::visit(Mapping{hit, p, normal}, hit.object->shape);
}

namespace {

double decode_srgb(std::uint8_t byte) {
    double c = byte / 255.0;
    return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}

// A texel index along one axis of `size` texels: wrapped around, or held at the edge.
int wrap_index(long long i, int size, TextureWrap wrap) {
    if (wrap == TextureWrap::Clamp) return static_cast<int>(std::clamp<long long>(i, 0, size - 1));
    long long m = i % size;
    return static_cast<int>(m < 0 ? m + size : m);
}

dvec3 texel(const TextureImage& image, int x, int y) {
    const std::uint8_t* t = &image.rgba[(std::size_t(y) * std::size_t(image.width) + std::size_t(x)) * 4];
    return {decode_srgb(t[0]), decode_srgb(t[1]), decode_srgb(t[2])};
}

// An image coordinate in [0, 1] (repeat: its fractional part; clamp: held to the image).
double image_coordinate(double s, TextureWrap wrap) {
    return wrap == TextureWrap::Repeat ? s - std::floor(s) : std::clamp(s, 0.0, 1.0);
}

}  // namespace

dvec3 texture_color(const ImageTexture& texture, const glm::dvec2& uv) {
    const TextureImage& image = *texture.image;
    // Surface (u, v) -> image (s, t): undo the offset, the rotation and the scale, in that order.
    double angle = texture.rotate_deg * M_PI / 180.0;
    glm::dvec2 d = uv - texture.offset;
    glm::dvec2 turned(std::cos(angle) * d.x + std::sin(angle) * d.y, -std::sin(angle) * d.x + std::cos(angle) * d.y);
    glm::dvec2 st = turned / texture.scale;
    double s = image_coordinate(st.x, texture.wrap_u);
    double t = image_coordinate(st.y, texture.wrap_v);
    // Texel (i, j) covers [i, i + 1] x [j, j + 1] in these units; row 0 is the top (t = 1).
    double x = s * image.width;
    double y = (1.0 - t) * image.height;
    if (texture.filter == TextureFilter::Nearest) {
        auto i = static_cast<long long>(std::floor(x));
        auto j = static_cast<long long>(std::floor(y));
        return texel(image, wrap_index(i, image.width, texture.wrap_u), wrap_index(j, image.height, texture.wrap_v));
    }
    // Bilinear between the four texels whose centres surround (x, y).
    x -= 0.5;
    y -= 0.5;
    double fx = x - std::floor(x), fy = y - std::floor(y);
    auto i0 = static_cast<long long>(std::floor(x));
    auto j0 = static_cast<long long>(std::floor(y));
    int xa = wrap_index(i0, image.width, texture.wrap_u), xb = wrap_index(i0 + 1, image.width, texture.wrap_u);
    int ya = wrap_index(j0, image.height, texture.wrap_v), yb = wrap_index(j0 + 1, image.height, texture.wrap_v);
    dvec3 top = (1.0 - fx) * texel(image, xa, ya) + fx * texel(image, xb, ya);
    dvec3 bottom = (1.0 - fx) * texel(image, xa, yb) + fx * texel(image, xb, yb);
    return (1.0 - fy) * top + fy * bottom;
}

}  // namespace lancer::cpu
