// Sphere sets (docs/scene-format.md, "Sphere sets"): the PLY point reader (radii, colours and
// their palette, every refusal at its place), and the CPU reference's walk through the set's own
// tree against testing every sphere.
#include <cmath>
#include <random>
#include <string>

#include <fmt/format.h>
#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "cpu/shapes/shapes.hpp"
#include "image/image.hpp"
#include "mesh/sphere_cloud.hpp"
#include "scene/load_scene.hpp"
#include "support/test_support.hpp"

namespace lancer {
namespace {

using glm::dvec3;

std::string ply(const std::string& properties, int count, const std::string& rows) {
    return fmt::format("ply\nformat ascii 1.0\nelement vertex {}\n{}end_header\n{}", count, properties, rows);
}
const std::string kXyz = "property float x\nproperty float y\nproperty float z\n";

TEST(SphereSet, ReadsCentresRadiiAndAPaletteOfColours) {
    const std::string text = ply(kXyz + "property float radius\nproperty uchar red\nproperty uchar green\nproperty uchar blue\n", 3,
                                 "0 0 0 0.5 255 0 0\n1 2 3 0.25 10 20 30\n-1 0.1 2 1 255 0 0\n");
    const auto cloud = mesh::read_sphere_ply(text, "points.ply", std::nullopt);
    ASSERT_EQ(cloud->spheres().size(), 3u);
    EXPECT_EQ(cloud->spheres()[1], glm::vec4(1, 2, 3, 0.25f));
    EXPECT_EQ(cloud->spheres()[2].y, 0.1f);  // the file's float
    ASSERT_EQ(cloud->palette().size(), 2u);  // the red of points 0 and 2 once
    EXPECT_EQ(cloud->colors(), (std::vector<std::uint32_t>{0, 1, 0}));
    EXPECT_DOUBLE_EQ(cloud->palette()[1].g, decode_srgb8(20));  // 8-bit codes are sRGB
    EXPECT_EQ(cloud->lo(), dvec3(-2, double(0.1f) - 1.0, -0.5));
    EXPECT_EQ(cloud->hi(), dvec3(1.25, 2.25, 3.25));
}

TEST(SphereSet, TakesTheObjectsRadiusWhereTheFileHasNone) {
    const auto cloud = mesh::read_sphere_ply(ply(kXyz + "property float red\nproperty float green\nproperty float blue\n", 1,
                                                 "1 1 1 0.2 0.4 0.6\n"),
                                             "p.ply", 0.3);
    EXPECT_EQ(cloud->spheres()[0], glm::vec4(1, 1, 1, 0.3f));
    EXPECT_EQ(cloud->palette()[0], dvec3(0.2, 0.4, 0.6));  // floats are linear
}

void expect_refused(const std::string& text, std::optional<double> radius, int line, const std::string& message) {
    try {
        mesh::read_sphere_ply(text, "p.ply", radius);
        ADD_FAILURE() << "read:\n" << text;
    } catch (const SceneError& e) {
        EXPECT_EQ(e.where().line, line) << e.what();
        EXPECT_NE(std::string(e.what()).find(message), std::string::npos) << e.what();
    } catch (const UserError& e) {
        EXPECT_EQ(line, -1) << e.what();
        EXPECT_NE(std::string(e.what()).find(message), std::string::npos) << e.what();
    }
}

TEST(SphereSet, RefusesWhatCannotBeASphereAtItsPlace) {
    expect_refused(ply(kXyz, 1, "0 0 0\n"), std::nullopt, -1, "the object needs `radius`");
    expect_refused(ply(kXyz + "property float radius\n", 1, "0 0 0 1\n"), 0.5, -1, "leave out the object's `radius`");
    expect_refused(ply(kXyz + "property float radius\n", 2, "0 0 0 1\n0 0 0 -1\n"), std::nullopt, 10, "not above 0");
    expect_refused(ply(kXyz + "property float radius\n", 1, "0 0 0 1e-50\n"), std::nullopt, 9, "not above 0 (in float)");
    expect_refused(ply(kXyz + "property float radius\n", 1, "0 1e300 0 1\n"), std::nullopt, 9, "y");
    expect_refused(ply("property float x\nproperty float y\n", 1, "0 0\n"), 1.0, 3, "no scalar property z");
    expect_refused(ply(kXyz + "property uchar red\nproperty uchar green\n", 1, "0 0 0 1 1\n"), 1.0, 3,
                   "some of red green blue but not all three");
    expect_refused(ply(kXyz + "property uchar red\nproperty uchar green\nproperty float blue\n", 1, "0 0 0 1 1 1\n"), 1.0, 9,
                   "all uchar");
    expect_refused(ply(kXyz + "property uchar red\nproperty uchar green\nproperty uchar blue\n", 1, "0 0 0 655 0 0\n"), 1.0, 11,
                   "red 655 is not a whole number from 0 to 255");
    expect_refused(ply(kXyz + "property float red\nproperty float green\nproperty float blue\n", 1, "0 0 0 0.5 -1 0\n"), 1.0, 11,
                   "green -1 is not a finite number from 0 up");
    expect_refused(ply(kXyz, 0, ""), 1.0, 0, "no points");
    std::string many;
    for (int i = 0; i <= static_cast<int>(mesh::kMaxSphereColors); ++i) many += fmt::format("0 0 0 {} {} 0\n", i % 256, i / 256);
    expect_refused(ply(kXyz + "property uchar red\nproperty uchar green\nproperty uchar blue\n", static_cast<int>(mesh::kMaxSphereColors) + 1, many),
                   1.0, 11 + static_cast<int>(mesh::kMaxSphereColors), "more than 4096 distinct colours");
}

// The tree's nearest hit is the nearest of every sphere's, for rays from everywhere, in and
// around a cloud of overlapping spheres (the walk must not stop at the first leaf with a hit).
TEST(SphereSet, TheTreesNearestHitIsTheNearestOfAll) {
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> u(-1.0f, 1.0f), r(0.01f, 0.2f);
    std::vector<glm::vec4> spheres;
    for (int i = 0; i < 500; ++i) spheres.emplace_back(u(rng), u(rng), u(rng), r(rng));
    SphereSet set;
    set.cloud = std::make_shared<const SphereCloud>(spheres, std::vector<std::uint32_t>{}, std::vector<dvec3>{});
    std::uniform_real_distribution<double> d(-2.0, 2.0);
    int hits = 0;
    for (int k = 0; k < 2000; ++k) {
        const cpu::Ray ray{{d(rng), d(rng), d(rng)}, glm::normalize(dvec3(d(rng), d(rng), d(rng)))};
        std::optional<double> nearest;
        int which = -1;
        for (std::size_t i = 0; i < spheres.size(); ++i)
            if (auto t = cpu::sphere_hit_t(dvec3(spheres[i]), spheres[i].w, ray, 1e-9, nearest.value_or(1e9))) {
                nearest = t;
                which = static_cast<int>(i);
            }
        const auto hit = cpu::intersect(set, ray, 1e-9, 1e9);
        ASSERT_EQ(hit.has_value(), nearest.has_value()) << k;
        if (!hit) continue;
        ++hits;
        EXPECT_EQ(hit->t, *nearest) << k;
        EXPECT_EQ(hit->part, which) << k;
        EXPECT_NEAR(glm::length(hit->normal), 1.0, 1e-6);
    }
    EXPECT_GT(hits, 300);  // the test meets spheres (about 500 of the 2000 rays do)
}

// The loader: the scene's file relative to the scene, each palette colour a material (the
// object's, its colour the point's), errors at the object's keys, and the file a dependency.
TEST(SphereSet, EachColourIsTheObjectsMaterialInThatColour) {
    const std::string dir = test::fresh_dir("sphere-set");
    test::write_file(dir + "/p.ply", ply(kXyz + "property float red\nproperty float green\nproperty float blue\n", 2,
                                         "0 0 0 1 0 0\n1 0 0 0 1 0\n"));
    const std::string stage = "[camera]\neye = [0, 0, -5]\nlook_at = [0, 0, 0]\n[[light]]\nposition = [0, 5, -5]\n"
                              "[material.shiny]\nspecular = 0.7\nreflection = 0.3\n";
    test::write_file(dir + "/s.toml", stage + "[[object]]\ntype = \"spheres\"\nfile = \"p.ply\"\nradius = 0.4\nmaterial = \"shiny\"\n");
    const Scene scene = load_scene(dir + "/s.toml");
    const auto& set = std::get<SphereSet>(scene.objects.at(0).shape);
    ASSERT_EQ(set.part_materials.size(), 2u);
    const Material& green = scene.materials.at(part_material(scene.objects[0], 1));
    EXPECT_EQ(green.color, dvec3(0, 1, 0));
    EXPECT_EQ(green.reflection, 0.3);
    EXPECT_EQ(scene.dependencies, std::vector<std::string>{dir + "/p.ply"});

    // Each refusal at its line of the scene, beside the point set.
    auto expect_refused_scene = [&](const std::string& objects, int line, const std::string& message) {
        test::write_file(dir + "/bad.toml", stage + objects);
        try {
            load_scene(dir + "/bad.toml");
            ADD_FAILURE() << "loaded:\n" << objects;
        } catch (const SceneError& e) {
            EXPECT_EQ(e.where().line, line) << e.what();
            EXPECT_NE(std::string(e.what()).find(message), std::string::npos) << e.what();
        }
    };
    expect_refused_scene("[[object]]\ntype = \"spheres\"\nfile = \"p.ply\"\n", 11, "the object needs `radius`");
    expect_refused_scene("[[object]]\ntype = \"intersection\"\nobjects = [\n  { type = \"spheres\", file = \"p.ply\", radius = 1 },\n"
                         "  { type = \"sphere\", center = [0, 0, 0], radius = 2 },\n]\n",
                         12, "a sphere set has no inside");
    expect_refused_scene("[[object]]\ntype = \"spheres\"\nfile = \"p.xyz\"\nradius = 1\n", 11, "PLY point set");
}

}  // namespace
}  // namespace lancer
