// Groups (POV-Ray's union): members placed by the group's transform after their own, given its
// material unless they name theirs, nested, moved as one by an animation; and the errors.
#include <string>

#include <fmt/format.h>
#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include "scene/animation.hpp"
#include "scene/transform.hpp"
#include "support/test_support.hpp"

namespace lancer {
namespace {

const char* const kGroupHead = R"(
    [camera]
    eye = [0, 0, -5]
    look_at = [0, 0, 0]
    [material.red]
    color = [1, 0, 0]
    [material.blue]
    color = [0, 0, 1]
)";

Scene group_scene(const std::string& objects) { return test::scene_from_text(std::string(kGroupHead) + objects); }

dvec3 group_member_centre(const Object& o) {
    const Sphere& s = std::get<Sphere>(o.shape);
    return o.placement && o.placement->shape_in_object_space ? dvec3(o.placement->to_world * glm::dvec4(s.center, 1.0)) : s.center;
}

void expect_same_point(const dvec3& a, const dvec3& b) {
    EXPECT_NEAR(a.x, b.x, 1e-12);
    EXPECT_NEAR(a.y, b.y, 1e-12);
    EXPECT_NEAR(a.z, b.z, 1e-12);
}

TEST(Group, MembersArePlacedByTheGroupAfterTheirOwnTransformAndTakeItsMaterial) {
    const Scene s = group_scene(R"(
        [[object]]
        type = "sphere"
        center = [9, 9, 9]
        radius = 1
        [[object]]
        type = "group"
        material = "red"
        transform = [ { rotate = [0, 0, 90] }, { translate = [0, 0, 5] } ]
        objects = [
            { type = "sphere", center = [1, 0, 0], radius = 0.5 },
            { type = "sphere", center = [0, 0, 0], radius = 0.5, material = "blue", transform = { translate = [2, 0, 0] } },
            { type = "group", transform = { scale = 2 }, objects = [ { type = "sphere", center = [1, 0, 0], radius = 1 } ] },
        ]
    )");
    ASSERT_EQ(s.objects.size(), 4u);  // the group is flattened into its three spheres
    // rotate z 90 takes +x to +y; then translate z 5.
    expect_same_point(group_member_centre(s.objects[1]), {0, 1, 5});
    expect_same_point(group_member_centre(s.objects[2]), {0, 2, 5});
    expect_same_point(group_member_centre(s.objects[3]), {0, 2, 5});  // scaled by 2 in the inner group first
    EXPECT_NEAR(std::get<Sphere>(s.objects[3].shape).radius, 2.0, 1e-12);
    const std::uint32_t red = s.objects[1].material, blue = s.objects[2].material;
    EXPECT_EQ(s.materials[red].name, "red");
    EXPECT_EQ(s.materials[blue].name, "blue");  // a member's own material wins
    EXPECT_EQ(s.objects[3].material, red);       // inherited through the inner group
    EXPECT_NE(s.objects[0].material, red);       // the object outside keeps the default
    // Patterns ride on the members: each member's frame is the group's map after its own.
    ASSERT_TRUE(s.objects[2].placement);
    expect_same_point(s.objects[2].placement->object_point({0, 2, 5}), {0, 0, 0});
}

TEST(Group, AnAnimationMovesTheWholeGroupByItsName) {
    const Scene s = group_scene(R"(
        [[object]]
        type = "group"
        name = "pair"
        objects = [ { type = "sphere", center = [1, 0, 0], radius = 0.5 },
                    { type = "sphere", center = [-1, 0, 0], radius = 0.5 } ]
        [[object]]
        type = "sphere"
        name = "alone"
        center = [0, 3, 0]
        radius = 0.5
        [animation]
        frames = 2
        [[animation.object]]
        object = "pair"
        keys = [{ time = 0.0, translate = [0, 0, 0] }, { time = 1.0, translate = [0, 0, 2] }]
    )");
    const Scene end = scene_at(s, 1.0);
    expect_same_point(group_member_centre(end.objects[0]), {1, 0, 2});
    expect_same_point(group_member_centre(end.objects[1]), {-1, 0, 2});
    expect_same_point(group_member_centre(end.objects[2]), {0, 3, 0});  // the next entry is not part of it
}

// POV-Ray's #declare and object { }: declared once, placed many times, each placement with its
// own transform (after the declared one's) and material (for the parts without their own).
TEST(Group, ADeclaredObjectIsPlacedManyTimes) {
    const Scene s = group_scene(R"(
        [declare.pair]
        type = "group"
        transform = { translate = [0, 1, 0] }
        objects = [ { type = "sphere", center = [1, 0, 0], radius = 0.5 },
                    { type = "sphere", center = [-1, 0, 0], radius = 0.5, material = "blue" } ]
        [[object]]
        type = "object"
        of = "pair"
        material = "red"
        [[object]]
        type = "object"
        of = "pair"
        name = "second"
        transform = { translate = [0, 0, 5] }
        [[object]]
        type = "difference"
        objects = [ { type = "box", min = [-2, -2, -2], max = [2, 2, 2] },
                    { type = "object", of = "pair", inverse = false } ]
        [animation]
        frames = 2
        [[animation.object]]
        object = "second"
        keys = [{ time = 0.0, translate = [0, 0, 0] }, { time = 1.0, translate = [3, 0, 0] }]
    )");
    ASSERT_EQ(s.objects.size(), 5u);
    expect_same_point(group_member_centre(s.objects[0]), {1, 1, 0});
    expect_same_point(group_member_centre(s.objects[3]), {-1, 1, 5});
    EXPECT_EQ(s.materials[s.objects[0].material].name, "red");
    EXPECT_EQ(s.materials[s.objects[1].material].name, "blue");
    EXPECT_NE(s.objects[2].material, s.objects[0].material);  // the second placement gives none: the default
    const Csg& csg = std::get<Csg>(s.objects[4].shape);
    EXPECT_EQ(csg.leaves.size(), 3u);  // the box and the pair's two spheres
    const Scene end = scene_at(s, 1.0);
    expect_same_point(group_member_centre(end.objects[2]), {4, 1, 5});  // the named placement moves
    expect_same_point(group_member_centre(end.objects[0]), {1, 1, 0});  // the other does not
}

// kGroupHead's 8 lines come first.
void expect_error_at(const std::string& objects, int line, const std::string& words) {
    test::expect_scene_error(std::string(kGroupHead) + objects, line + 8, -1, words);
}

TEST(Group, ErrorsSayWhereAndWhy) {
    expect_error_at("[[object]]\ntype = \"group\"\n", 2, "a group needs `objects`");
    expect_error_at("[[object]]\ntype = \"group\"\nobjects = []\n", 3, "a group needs `objects`");
    expect_error_at("[[object]]\ntype = \"group\"\nobjects = [3]\n", 3, "a group's objects must be tables");
    expect_error_at("[[object]]\ntype = \"group\"\nobjects = [{ type = \"sphere\", center = [0, 0, 0], radius = 1, name = \"x\" }]\n",
                    3, "cannot have its own name");
    expect_error_at("[[object]]\ntype = \"group\"\nobjects = [{ type = \"spere\", center = [0, 0, 0], radius = 1 }]\n", 3,
                    "did you mean 'sphere'");
    expect_error_at("[[object]]\ntype = \"group\"\nobjects = [{ type = \"sphere\", center = [0, 0, 0], radius = -1 }]\n", 3,
                    "radius must be positive");
    expect_error_at("[[object]]\ntype = \"group\"\nmaterial = \"green\"\nobjects = [{ type = \"sphere\", center = [0, 0, 0], radius = 1 }]\n",
                    3, "unknown material 'green'");
    // Scales compose: each step within range, the product beyond it.
    expect_error_at("[[object]]\ntype = \"group\"\ntransform = { scale = 1e7 }\n"
                    "objects = [{ type = \"sphere\", center = [0, 0, 0], radius = 1, transform = { scale = 1e7 } }]\n",
                    4, "outside lancer's range");
    expect_error_at("[[object]]\ntype = \"object\"\nof = \"chair\"\n", 3, "no object is declared as 'chair'");
    expect_error_at("[declare.loop]\ntype = \"object\"\nof = \"loop\"\n[[object]]\ntype = \"object\"\nof = \"loop\"\n", 3,
                    "objects nest at most 64 deep");
    // Declarations that place each other twice, 20 deep: a million objects from a few lines.
    std::string doubling;
    for (int i = 0; i < 20; ++i)
        doubling += fmt::format("[declare.d{}]\ntype = \"group\"\nobjects = [{{ type = \"object\", of = \"d{}\" }}, "
                                "{{ type = \"object\", of = \"d{}\", transform = {{ translate = [1, 0, 0] }} }}]\n",
                                i, i + 1, i + 1);
    doubling += "[declare.d20]\ntype = \"sphere\"\ncenter = [0, 0, 0]\nradius = 1\n[[object]]\ntype = \"object\"\nof = \"d0\"\n";
    try {
        group_scene(doubling);
        ADD_FAILURE() << "a million placements accepted";
    } catch (const SceneError& e) {
        EXPECT_NE(std::string(e.what()).find("too many placements of declared objects"), std::string::npos) << e.what();
    }
    // Nesting deeper than the limit.
    std::string deep = "[[object]]\ntype = \"group\"\nobjects = [";
    for (int i = 0; i < 70; ++i) deep += "{ type = \"group\", objects = [";
    deep += "{ type = \"sphere\", center = [0, 0, 0], radius = 1 }";
    for (int i = 0; i < 70; ++i) deep += "] }";
    expect_error_at(deep + "]\n", 3, "groups nest at most 64 deep");
}

}  // namespace
}  // namespace lancer
