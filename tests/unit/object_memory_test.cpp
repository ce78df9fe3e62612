// What one object of the scene model costs: the large, rare shapes kept on the heap with a value's
// semantics, and one file name shared by every location read from the file.
#include <string>
#include <variant>

#include <gtest/gtest.h>

#include "scene/load_scene.hpp"
#include "scene/object_batches.hpp"
#include "scene/scene.hpp"

namespace lancer {
namespace {

// A million spheres are a million Objects: a new alternative of Shape far larger than a
// sphere belongs on the heap (core/heap_value.hpp), as the implicit and parametric surfaces are.
TEST(ObjectMemory, AnObjectStaysNearASpheresSize) {
    EXPECT_LE(sizeof(Shape), 128u);
    EXPECT_LE(sizeof(SourceLocation), 24u);
    EXPECT_LE(sizeof(Object), 176u);
    EXPECT_EQ(sizeof(RareString), sizeof(void*)) << "an object's name, which most lack";
}

TEST(ObjectMemory, ANameReadsAsAStringAndCopiesDeep) {
    RareString none;
    EXPECT_TRUE(none.empty());
    EXPECT_EQ(none.str(), "");
    RareString name("ball");
    EXPECT_FALSE(name.empty());
    EXPECT_EQ(name, "ball");
    EXPECT_TRUE(RareString(std::string()).empty()) << "an empty string takes no room either";
    RareString copy = name;
    name = RareString("cue");
    EXPECT_EQ(copy, "ball");
    const std::string& text = copy;
    EXPECT_EQ(text, "ball");
    copy = none;
    EXPECT_TRUE(copy.empty());
}

TEST(ObjectMemory, CopiesOfASurfaceOnTheHeapAreDeep) {
    Object a;
    ImplicitObject implicit;
    implicit.surface->box_lo = dvec3(-2.0);
    a.shape = implicit;
    Object b = a;
    std::get<ImplicitObject>(b.shape).surface->box_lo = dvec3(-3.0);
    EXPECT_EQ(std::get<ImplicitObject>(a.shape).surface->box_lo, dvec3(-2.0));
    a = b;
    EXPECT_EQ(std::get<ImplicitObject>(a.shape).surface->box_lo, dvec3(-3.0));
    EXPECT_NE(&*std::get<ImplicitObject>(a.shape).surface, &*std::get<ImplicitObject>(b.shape).surface);

    ParametricObject parametric;
    parametric.surface->u1 = 2.0;
    const ParametricObject copy = parametric;
    parametric.surface->u1 = 3.0;
    EXPECT_EQ(copy.surface->u1, 2.0);
}

// Each object's location names the scene file through one shared string, read whole or in batches.
TEST(ObjectMemory, ObjectsShareTheirFilesName) {
    std::string text = "[camera]\neye = [0, 0, -5]\nlook_at = [0, 0, 0]\n";
    for (int i = 0; i < 5; ++i) text += "[[object]]\ntype = \"sphere\"\ncenter = [" + std::to_string(i) + ", 0, 0]\nradius = 1\n";
    const std::string path = "shared/name.toml";
    const std::optional<SceneTextParts> parts = split_object_tables(text, 2);
    ASSERT_TRUE(parts);
    for (const Scene& scene : {parse_scene(text, path, {}, TomlReading::Whole), parse_scene_batches(text, *parts, path)}) {
        ASSERT_EQ(scene.objects.size(), 5u);
        for (const Object& o : scene.objects) {
            EXPECT_EQ(o.where.file.str(), path);
            EXPECT_EQ(&o.where.file.str(), &scene.objects[0].where.file.str()) << o.where.line;
        }
        EXPECT_EQ(scene.objects[4].where.line, 20);
    }
}

}  // namespace
}  // namespace lancer
