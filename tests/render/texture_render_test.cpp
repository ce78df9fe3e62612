// Textures and patterns on both backends, against answers worked out here by hand: a texel
// seen where the camera ray meets the surface at that texel, the spherical mapping's angles,
// bilinear filtering and sRGB decoding, noise values at known points, and bumps that change the
// shading but not the geometry.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>

#include <fmt/format.h>
#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <gtest/gtest.h>

#include "cpu/cpu_renderer.hpp"
#include "scene/camera.hpp"
#include "scene/transform.hpp"
#include "support/perlin_reference.hpp"
#include "support/test_support.hpp"

namespace lancer {
namespace {

using glm::dvec2;

using test::Backend;

class Textures : public testing::TestWithParam<Backend> {};

double srgb_to_linear(int byte) {
    double c = byte / 255.0;
    return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}

// Writes a PNG whose texel (x, y), row 0 at the top, has the sRGB bytes fn(x, y); returns its path.
template <typename Fn>
std::string write_texture(const std::string& name, int w, int h, Fn fn) {
    Rgb8Image img{w, h, {}};
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            std::array<int, 3> c = fn(x, y);
            for (int k = 0; k < 3; ++k) img.bytes.push_back(static_cast<std::uint8_t>(c[k]));
        }
    std::string path = test::output_dir() + "/texture-" + name + ".png";
    write_png(path, img);
    return path;
}

// Distinct bytes per texel, so a colour names the texel it came from.
std::array<int, 3> label(int x, int y) { return {40 + 20 * x, 40 + 50 * y, 200 - 15 * x}; }

// The camera ray through the centre of pixel (x, y).
struct PixelRay {
    glm::dvec3 origin, dir;
};
PixelRay pixel_ray(const Scene& s, int x, int y) {
    CameraBasis cam = make_camera_basis(s.camera, s.render.width, s.render.height);
    return {cam.eye, glm::normalize(camera_ray_direction(cam, x + 0.5, y + 0.5, s.render.width, s.render.height))};
}

// Where the ray through pixel (x, y) meets the plane z = 0 (the plates the tests look at).
glm::dvec3 on_plate(const Scene& s, int x, int y) {
    PixelRay r = pixel_ray(s, x, y);
    return r.origin + (-r.origin.z / r.dir.z) * r.dir;
}

// [render] and [camera] of a test scene: one ray per pixel, the camera looking at the origin.
std::string view_of(int width, int height, const std::string& eye, double fov) {
    return fmt::format("[render]\nwidth = {}\nheight = {}\nsamples = 1\n[camera]\neye = {}\nlook_at = [0, 0, 0]\nfov = {}\n",
                       width, height, eye, fov);
}

// Lit by ambient light alone, with k_a = 1: a pixel is its pigment.
const char* kUnlit = R"(
        [ambient]
        color = [1, 1, 1]
)";

// The texel of a w x h nearest-filtered image that image coordinates (s, t) fall in (held at
// the image's edge beyond it), unless they are within `margin` texels of a texel's edge, where
// float and double may disagree.
std::optional<glm::ivec2> texel_at(double s, double t, int w, int h, double margin = 0.05) {
    double x = s * w, y = (1.0 - t) * h;
    auto near_edge = [&](double c) { return std::abs(c - std::round(c)) < margin; };
    if (near_edge(x) || near_edge(y)) return std::nullopt;
    return glm::clamp(glm::ivec2(int(std::floor(x)), int(std::floor(y))), glm::ivec2(0), glm::ivec2(w - 1, h - 1));
}

struct Placement {
    std::string keys;       // the texture table's extra keys
    dvec2 scale{1.0}, offset{0.0};
    double rotate_deg = 0.0;
    bool clamp = false;
};

// A plate facing the camera, (-1.5, -1) to (1.5, 1) in z = 0, drawn by `object` (its [[object]]
// table, of material "m") and textured with a 4 x 3 labelled image (`texture_keys`: the texture
// table's extra keys): every pixel away from the plate's and the texels' edges shows, exactly, the
// texel at image coordinates st_of(a, b), (a, b) the point's place along the plate's edges.
template <class StOf>
void expect_texels_on_plate(Backend backend, const std::string& object, const std::string& texture_keys, StOf st_of,
                            int least_checked) {
    std::string file = write_texture("labels", 4, 3, label);
    Scene s = test::scene_from_text(view_of(64, 48, "[0.2, 0.1, -4]", 45) + fmt::format(R"(
        {}
        [material.m]
        ambient = 1
        texture = {{ file = "{}", filter = "nearest"{} }}
    )", kUnlit, file, texture_keys) + object);
    FloatImage img = test::render_on(backend, s);
    int checked = 0;
    for (int y = 0; y < img.height; ++y) {
        for (int x = 0; x < img.width; ++x) {
            glm::dvec3 p = on_plate(s, x, y);
            dvec2 ab((p.x + 1.5) / 3.0, (p.y + 1.0) / 2.0);
            if (ab.x < 0.01 || ab.x > 0.99 || ab.y < 0.01 || ab.y > 0.99) continue;
            dvec2 st = st_of(ab);
            auto texel = texel_at(st.x, st.y, 4, 3);
            if (!texel) continue;
            std::array<int, 3> bytes = label(texel->x, texel->y);
            for (int c = 0; c < 3; ++c)
                ASSERT_NEAR(img.at(x, y)[c], srgb_to_linear(bytes[c]), 2e-5)
                    << texture_keys << ": pixel " << x << "," << y << " should show texel " << texel->x << "," << texel->y;
            ++checked;
        }
    }
    EXPECT_GT(checked, least_checked) << texture_keys;  // of the ~1250 pixels on the plate
}

// The plate as a rectangle, its image placed by `placement`: the documented mapping.
void expect_texels_on_rectangle(Backend backend, const Placement& placement) {
    const char* rectangle = "[[object]]\ntype = \"rectangle\"\ncorner = [-1.5, -1, 0]\nedge_u = [3, 0, 0]\nedge_v = [0, 2, 0]\n"
                            "material = \"m\"\n";
    expect_texels_on_plate(backend, rectangle, placement.keys, [&](dvec2 uv) {
        // Image (s, t) = scale^-1 rotate(-angle) (uv - offset), then repeat or clamp.
        double a = placement.rotate_deg * std::numbers::pi / 180.0;
        dvec2 d = uv - placement.offset;
        dvec2 st = dvec2(std::cos(a) * d.x + std::sin(a) * d.y, -std::sin(a) * d.x + std::cos(a) * d.y) / placement.scale;
        if (!placement.clamp) st -= glm::floor(st);  // repeat
        return st;
    }, 800);
}

TEST_P(Textures, TexelsLandWhereTheRayMeetsThemOnARectangle) {
    expect_texels_on_rectangle(GetParam(), {});
}

TEST_P(Textures, ScaleOffsetRotateAndWrapPlaceTheImageAsDocumented) {
    expect_texels_on_rectangle(GetParam(), {", scale = [0.4, 0.7]", {0.4, 0.7}});
    expect_texels_on_rectangle(GetParam(), {", offset = [0.3, -0.2]", {1.0, 1.0}, {0.3, -0.2}});
    expect_texels_on_rectangle(GetParam(), {", rotate = 30, scale = 0.5", {0.5, 0.5}, {0.0, 0.0}, 30.0});
    expect_texels_on_rectangle(GetParam(), {", scale = 0.6, offset = [0.2, 0.3], wrap = \"clamp\"", {0.6, 0.6}, {0.2, 0.3}, 0.0, true});
}

// The same plate as a mesh of two triangles (an OBJ), its texture coordinates the file's and
// turned a quarter against the plate's edges: u = 1 - b, v = a. Every pixel away from texel edges
// shows the texel those coordinates name, interpolated across either triangle (the same affine
// map on both, so the diagonal between them is no exception).
TEST_P(Textures, TexelsLandWhereAMeshsOwnTextureCoordinatesPutThem) {
    const std::string obj = test::fresh_dir("plate") + "/plate.obj";
    test::write_file(obj, "v -1.5 -1 0\nv 1.5 -1 0\nv 1.5 1 0\nv -1.5 1 0\n"
                          "vt 1 0\nvt 1 1\nvt 0 1\nvt 0 0\n"
                          "f 1/1 2/2 3/3\nf 1/1 3/3 4/4\n");
    expect_texels_on_plate(GetParam(), fmt::format("[[object]]\ntype = \"mesh\"\nfile = \"{}\"\nmaterial = \"m\"\n", obj), "",
                           [](dvec2 ab) { return dvec2(1.0 - ab.y, ab.x); }, 700);
}

// A sphere turned by rotate = [20, 35, 0]: the texel seen at each pixel is the one at the
// longitude and latitude of the hit point in the sphere's own frame.
TEST_P(Textures, SphericalMappingFollowsLongitudeAndLatitude) {
    std::string file = write_texture("sphere-labels", 7, 3, label);
    for (glm::dvec3 angles : {glm::dvec3(0.0), glm::dvec3(20.0, 35.0, 0.0)}) {
        Scene s = test::scene_from_text(view_of(63, 63, "[0, 0, -5]", 30) + fmt::format(R"(
            {}
            [material.m]
            ambient = 1
            texture = {{ file = "{}", filter = "nearest" }}
            [[object]]
            type = "sphere"
            center = [0, 0, 0]
            radius = 1
            rotate = [{}, {}, {}]
            material = "m"
        )", kUnlit, file, angles.x, angles.y, angles.z));
        FloatImage img = test::render_on(GetParam(), s);
        glm::dmat3 to_sphere = glm::transpose(glm::dmat3(rotation_degrees(angles)));
        int checked = 0;
        for (int y = 0; y < img.height; ++y) {
            for (int x = 0; x < img.width; ++x) {
                PixelRay r = pixel_ray(s, x, y);
                double b = glm::dot(r.origin, r.dir), c = glm::dot(r.origin, r.origin) - 1.0;
                if (b * b - c < 0.0) continue;
                glm::dvec3 p = r.origin + (-b - std::sqrt(b * b - c)) * r.dir;
                if (-glm::dot(p, r.dir) < 0.3) continue;  // too near the silhouette
                glm::dvec3 d = to_sphere * p;
                double u = 0.5 + std::atan2(d.x, -d.z) / (2.0 * std::numbers::pi);
                double v = 0.5 + std::asin(d.y) / std::numbers::pi;
                auto texel = texel_at(u, v, 7, 3);
                if (!texel) continue;
                std::array<int, 3> bytes = label(texel->x, texel->y);
                for (int k = 0; k < 3; ++k)
                    ASSERT_NEAR(img.at(x, y)[k], srgb_to_linear(bytes[k]), 2e-5) << "pixel " << x << "," << y;
                ++checked;
            }
        }
        EXPECT_GT(checked, 1000);
        if (angles == glm::dvec3(0.0)) {
            // The middle of the image (texel 3, 1) faces the camera at -z.
            std::array<int, 3> middle = label(3, 1);
            EXPECT_NEAR(img.at(31, 31).r, srgb_to_linear(middle[0]), 2e-5);
        }
    }
}

TEST_P(Textures, BilinearMidpointIsTheMeanOfDecodedTexels) {
    std::string black_white = write_texture("black-white", 2, 1, [](int x, int) {
        return std::array<int, 3>{255 * x, 255 * x, 255 * x};
    });
    std::string grey = write_texture("grey-128", 1, 1, [](int, int) { return std::array<int, 3>{128, 64, 255}; });
    Scene s = test::scene_from_text(view_of(5, 5, "[0, 0, -4]", 20) + fmt::format(R"(
        {}
        [material.bw]
        ambient = 1
        texture = "{}"
        [material.grey]
        ambient = 1
        texture = "{}"
        [[object]]
        type = "rectangle"
        corner = [-1, -1, 0]
        edge_u = [2, 0, 0]
        edge_v = [0, 2, 0]
        material = "bw"
    )", kUnlit, black_white, grey));
    FloatImage img = test::render_on(GetParam(), s);
    // The centre pixel's ray meets the rectangle's centre: u = 0.5, half way between the two
    // texel centres. In linear light that is 0.5 (filtering before decoding would give 0.21).
    EXPECT_NEAR(img.at(2, 2).r, 0.5, 2e-5);
    EXPECT_NEAR(img.at(2, 2).g, 0.5, 2e-5);

    ASSERT_EQ(s.materials[1].name, "grey");
    s.objects[0].material = 1;
    img = test::render_on(GetParam(), s);
    for (int x = 0; x < 5; ++x) {
        EXPECT_NEAR(img.at(x, 2).r, 0.21586050011389926, 2e-6);  // sRGB 128
        EXPECT_NEAR(img.at(x, 2).g, 0.05126945837404324, 2e-6);  // sRGB 64
        EXPECT_NEAR(img.at(x, 2).b, 1.0, 2e-6);
    }
}

using test::reference_noise;

// A rectangle facing the camera with a black-to-white ramp: each pixel is the pattern's f.
Scene pattern_plate(const std::string& pattern) {
    return test::scene_from_text(view_of(48, 48, "[0, 0, -4]", 40) + fmt::format(R"(
        {}
        [material.m]
        ambient = 1
        pattern = {{ colors = [[0, 0, 0], [1, 1, 1]], {} }}
        [[object]]
        type = "rectangle"
        corner = [-2, -2, 0]
        edge_u = [4, 0, 0]
        edge_v = [0, 4, 0]
        material = "m"
    )", kUnlit, pattern));
}

TEST_P(Textures, NoiseIsPerlinsReferenceOnBothBackends) {
    // Pattern space = world / 0.37 + (1.3, -0.2, 2.1): scale 0.37, then translate.
    Scene s = pattern_plate("type = \"noise\", scale = 0.37, translate = [0.481, -0.074, 0.777]");
    FloatImage img = test::render_on(GetParam(), s);
    double worst = 0.0;
    for (int y = 0; y < img.height; ++y) {
        for (int x = 0; x < img.width; ++x) {
            glm::dvec3 q = (on_plate(s, x, y) - glm::dvec3(0.481, -0.074, 0.777)) / 0.37;
            double expected = 0.5 + 0.5 * reference_noise(q);
            worst = std::max(worst, std::abs(img.at(x, y).g - expected));
        }
    }
    // The GPU works in float: its hit points and noise differ from double by ~1e-6.
    EXPECT_LT(worst, GetParam() == Backend::Gpu ? 1e-5 : 1e-7);
}

TEST_P(Textures, MarbleWoodAndTurbulenceAreTheDocumentedFunctionsOfNoise) {
    for (std::string type : {"marble", "wood", "turbulence"}) {
        std::string turbulence = type == "turbulence" ? "" : ", turbulence = 0.4";
        Scene s = pattern_plate(fmt::format("type = \"{}\", octaves = 3, omega = 0.6, lambda = 2.2{}", type, turbulence));
        FloatImage img = test::render_on(GetParam(), s);
        double worst = 0.0;
        for (int y = 0; y < img.height; ++y) {
            for (int x = 0; x < img.width; ++x) {
                glm::dvec3 q = on_plate(s, x, y);
                double t = 0.0, amplitude = 1.0, frequency = 1.0;
                for (int i = 0; i < 3; ++i, amplitude *= 0.6, frequency *= 2.2)
                    t += amplitude * std::abs(reference_noise(frequency * q));
                double expected = t;
                if (type == "marble") expected = 0.5 + 0.5 * std::sin(2.0 * std::numbers::pi * (q.x + 0.4 * t));
                if (type == "wood") {
                    double radius = std::hypot(q.x, q.y) + 0.4 * t;
                    expected = 1.0 - 2.0 * std::abs(radius - std::floor(radius) - 0.5);
                }
                expected = std::clamp(expected, 0.0, 1.0);  // the ramp holds its end colours
                worst = std::max(worst, std::abs(img.at(x, y).g - expected));
            }
        }
        EXPECT_LT(worst, GetParam() == Backend::Gpu ? 5e-5 : 1e-7) << type;
    }
}

// A bump on a flat plate: wood rings without turbulence have the gradient 2 (x, y, 0) / r (on
// the rising half of a ring), so the lit colour is C max(0, N'.L) with N' = normalize(N - a g).
// The material has a colour pattern too (a flat ramp, C = 0.5): both apply, each its own.
TEST_P(Textures, BumpTiltsTheNormalByTheDocumentedRule) {
    Scene s = test::scene_from_text(view_of(48, 48, "[0, 0, -4]", 40) + R"(
        [ambient]
        color = [0, 0, 0]
        [[light]]
        position = [1, 2, -6]
        [material.m]
        diffuse = 1
        pattern = { type = "marble", colors = [[0.5, 0.5, 0.5], [0.5, 0.5, 0.5]], scale = 0.1 }
        bump = { type = "wood", turbulence = 0, amount = 0.4, scale = 0.8 }
        [[object]]
        type = "rectangle"
        corner = [-2, -2, 0]
        edge_u = [4, 0, 0]
        edge_v = [0, 4, 0]
        material = "m"
    )");
    FloatImage img = test::render_on(GetParam(), s);
    int checked = 0;
    for (int y = 0; y < img.height; ++y) {
        for (int x = 0; x < img.width; ++x) {
            glm::dvec3 p = on_plate(s, x, y);
            double radius = std::hypot(p.x, p.y) / 0.8;  // in pattern units
            double fraction = radius - std::floor(radius);
            if (radius < 0.05 || std::abs(fraction - 0.5) < 0.03 || fraction < 0.03 || fraction > 0.97) continue;
            // Gradient in pattern space times the mean scale 0.8 = the world gradient x 0.8.
            glm::dvec3 g = (fraction < 0.5 ? 2.0 : -2.0) * glm::dvec3(p.x, p.y, 0.0) / std::hypot(p.x, p.y);
            glm::dvec3 n(0.0, 0.0, -1.0);
            glm::dvec3 tilted = glm::normalize(n - 0.4 * g);
            glm::dvec3 l = glm::normalize(s.lights[0].position - p);
            double expected = 0.5 * std::max(0.0, glm::dot(tilted, l));
            ASSERT_NEAR(img.at(x, y).r, expected, 2e-5) << "pixel " << x << "," << y;
            ++checked;
        }
    }
    EXPECT_GT(checked, 1500);
}

// The same sphere with and without a bump: the same pixels hit it at the same distances (the
// geometry is untouched), but the shading differs across most of its face.
TEST_P(Textures, BumpChangesShadingButNotGeometry) {
    constexpr const char* scene = R"(
        [[light]]
        position = [-3, 4, -6]
        [material.m]
        color = [0.8, 0.5, 0.3]
        specular = 0.5
        {}
        [[object]]
        type = "sphere"
        center = [0, 0, 0]
        radius = 1
        material = "m"
    )";
    const std::string view = view_of(48, 48, "[0, 0, -5]", 30);
    Scene smooth = test::scene_from_text(view + fmt::format(fmt::runtime(scene), ""));
    Scene bumpy = test::scene_from_text(view + fmt::format(fmt::runtime(scene), "bump = { type = \"noise\", amount = 0.8, scale = 0.15 }"));
    CpuRenderer cpu;
    Renderer& renderer = GetParam() == Backend::Gpu ? static_cast<Renderer&>(test::gpu_renderer()) : cpu;
    FloatImage hits_smooth = renderer.render_hits(smooth), hits_bumpy = renderer.render_hits(bumpy);
    EXPECT_EQ(hits_smooth.pixels, hits_bumpy.pixels);
    FloatImage a = test::render_on(GetParam(), smooth), b = test::render_on(GetParam(), bumpy);
    int on_sphere = 0, changed = 0;
    for (int y = 0; y < a.height; ++y)
        for (int x = 0; x < a.width; ++x) {
            if (hits_smooth.at(x, y).x < 0.0f) {
                EXPECT_EQ(a.at(x, y), b.at(x, y));  // background stays background
                continue;
            }
            ++on_sphere;
            changed += glm::length(glm::vec3(a.at(x, y)) - glm::vec3(b.at(x, y))) > 0.01f;
        }
    EXPECT_GT(on_sphere, 400);
    EXPECT_GT(changed, on_sphere / 2);
}

INSTANTIATE_TEST_SUITE_P(Backends, Textures, testing::Values(Backend::Gpu, Backend::Cpu),
                         [](const auto& info) { return info.param == Backend::Gpu ? "gpu" : "cpu"; });

}  // namespace
}  // namespace lancer
