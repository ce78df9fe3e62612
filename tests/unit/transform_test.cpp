#include <glm/gtc/matrix_access.hpp>
#include <gtest/gtest.h>

#include "scene/placement.hpp"
#include "scene/transform.hpp"
#include "support/test_support.hpp"

namespace lancer {
namespace {

glm::dmat4 transform_of(const std::string& toml) {
    toml::table t = toml::parse(toml);
    TableReader reader(t, "inline.toml", "object");
    glm::dmat4 m = read_transform(reader);
    reader.finish();
    return m;
}

dvec3 apply(const glm::dmat4& m, dvec3 p) { return dvec3(m * glm::dvec4(p, 1.0)); }

void expect_near(dvec3 a, dvec3 b) {
    EXPECT_NEAR(a.x, b.x, 1e-12);
    EXPECT_NEAR(a.y, b.y, 1e-12);
    EXPECT_NEAR(a.z, b.z, 1e-12);
}

TEST(Transform, AbsentIsIdentity) { EXPECT_EQ(transform_of(""), glm::dmat4(1.0)); }

TEST(Transform, RotationFollowsPovRay) {
    // POV-Ray: rotate <0, 90, 0> takes +x to -z, and rotate <90, 0, 0> takes +y to +z.
    expect_near(apply(transform_of("transform = { rotate = [0, 90, 0] }"), {1, 0, 0}), {0, 0, -1});
    expect_near(apply(transform_of("transform = { rotate = [90, 0, 0] }"), {0, 1, 0}), {0, 0, 1});
}

TEST(Transform, TableAppliesScaleThenRotateThenTranslate) {
    glm::dmat4 m = transform_of("transform = { translate = [1, 2, 3], scale = 2, rotate = [0, 0, 90] }");
    // (1,0,0) -> scale (2,0,0) -> rotate z 90 (0,2,0) -> translate (1,4,3)
    expect_near(apply(m, {1, 0, 0}), {1, 4, 3});
}

TEST(Transform, ListAppliesInTheOrderWritten) {
    glm::dmat4 m = transform_of("transform = [ { translate = [1, 0, 0] }, { rotate = [0, 0, 90] }, { scale = [1, 3, 1] } ]");
    // (0,0,0) -> (1,0,0) -> (0,1,0) -> (0,3,0)
    expect_near(apply(m, {0, 0, 0}), {0, 3, 0});
}

TEST(Transform, ErrorsPointAtTheProblem) {
    EXPECT_THROW(transform_of("transform = { scale = 0 }"), SceneError);
    EXPECT_THROW(transform_of("transform = { rotate = [0, 90] }"), SceneError);
    EXPECT_THROW(transform_of("transform = { shift = [0, 1, 0] }"), SceneError);
    EXPECT_THROW(transform_of("transform = 3"), SceneError);
    try {
        transform_of("x = 1\ntransform = { rotate = [0, nan, 0] }");
        FAIL();
    } catch (const SceneError& e) {
        EXPECT_EQ(e.where().line, 2);
        EXPECT_EQ(e.where().column, 28);
    }
}

TEST(Transform, ScalesWhoseInverseFloatCannotHoldAreRefused) {
    // A scale of 0.61e-300 (fuzz_scene's finding) is a valid double matrix whose inverse is
    // infinite in float, the GPU's arithmetic (and NaN in double: the determinant underflows);
    // the limit holds for the composed list too.
    for (const char* bad : {"transform = { scale = 0.61e-300 }", "transform = { scale = [1, 1e-13, 1] }",
                            "transform = [ { scale = 1e7 }, { scale = 1e7 } ]"}) {
        try {
            transform_of(std::string("x = 1\n") + bad);
            ADD_FAILURE() << bad;
        } catch (const SceneError& e) {
            EXPECT_EQ(e.where().line, 2) << bad;
            EXPECT_NE(std::string(e.what()).find("outside lancer's range of 1e-12 to 1e+12"), std::string::npos) << e.what();
        }
    }
    // Near the limit, and where the steps cancel, the transform is accepted.
    EXPECT_NO_THROW(transform_of("transform = { scale = 2e-12 }"));
    EXPECT_NO_THROW(transform_of("transform = [ { scale = 1e-9 }, { scale = 1e9 } ]"));
}

TEST(Transform, MatrixIsPovRaysRowVectorForm) {
    // POV-Ray: matrix <a, b, c, d, e, f, g, h, i, tx, ty, tz> takes (x, y, z) to
    // (x a + y d + z g + tx, x b + y e + z h + ty, x c + y f + z i + tz).
    glm::dmat4 m = transform_of("transform = { matrix = [1, 2, 3, 4, 5, 6, 7, 8, 10, 11, 12, 13] }");
    expect_near(apply(m, {1, 0, 0}), {12, 14, 16});
    expect_near(apply(m, {0, 1, 0}), {15, 17, 19});
    expect_near(apply(m, {0, 0, 1}), {18, 20, 23});
    // A shear, then a translation, in a list.
    m = transform_of("transform = [ { matrix = [1, 0, 0, 0.5, 1, 0, 0, 0, 1, 0, 0, 0] }, { translate = [0, 0, 2] } ]");
    expect_near(apply(m, {0, 1, 0}), {0.5, 1, 2});
}

TEST(Transform, MatrixErrorsSayWhy) {
    for (const char* bad : {"transform = { matrix = [1, 0, 0] }", "transform = { matrix = [1, 0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 0] }",
                            "transform = { matrix = [1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0], scale = 2 }"}) {
        try {
            transform_of(std::string("x = 1\n") + bad);
            ADD_FAILURE() << bad;
        } catch (const SceneError& e) {
            EXPECT_EQ(e.where().line, 2) << bad;
            EXPECT_NE(std::string(e.what()).find("matrix"), std::string::npos) << e.what();
        }
    }
}

// Which shapes take a transform into their own parameters (exactly) and which keep their own
// coordinates, and what the absorbed ones become.
Object placed(Shape shape, const glm::dmat4& m) {
    Object o{std::move(shape)};
    place(o, m);
    return o;
}

TEST(Placement, ASimilarityIsAppliedToASphereAndAStretchIsNot) {
    const glm::dmat4 similarity = transform_of("transform = { scale = 2, rotate = [10, 20, 30], translate = [1, 2, 3] }");
    Object o = placed(Sphere{dvec3(1, 0, 0), 0.5}, similarity);
    ASSERT_TRUE(o.placement);
    EXPECT_FALSE(o.placement->shape_in_object_space);
    const Sphere& s = std::get<Sphere>(o.shape);
    expect_near(s.center, apply(similarity, {1, 0, 0}));
    EXPECT_NEAR(s.radius, 1.0, 1e-12);
    EXPECT_NEAR(similarity_scale(similarity), 2.0, 1e-12);

    const glm::dmat4 stretch = transform_of("transform = { scale = [2, 1, 1] }");
    o = placed(Sphere{dvec3(1, 0, 0), 0.5}, stretch);
    EXPECT_TRUE(o.placement->shape_in_object_space);
    EXPECT_EQ(std::get<Sphere>(o.shape).center, dvec3(1, 0, 0));  // untouched
    EXPECT_EQ(similarity_scale(stretch), 0.0);
    EXPECT_EQ(similarity_scale(transform_of("transform = { scale = [-1, 1, 1] }")), 0.0);  // a mirror
}

TEST(Placement, EachShapeKeepsItsFormWhereItCan) {
    const glm::dmat4 turn = transform_of("transform = { rotate = [0, 30, 0], translate = [0, 1, 0] }");
    const glm::dmat4 shear = transform_of("transform = { matrix = [1, 0, 0, 0.5, 1, 0, 0, 0, 1, 0, 0, 0] }");
    const glm::dmat4 grow = transform_of("transform = { scale = [2, 3, 4], translate = [1, 1, 1] }");
    EXPECT_FALSE(placed(Rectangle{}, shear).placement->shape_in_object_space);  // a parallelogram still
    EXPECT_FALSE(placed(Box{}, grow).placement->shape_in_object_space);         // axis-aligned still
    EXPECT_TRUE(placed(Box{}, turn).placement->shape_in_object_space);          // turned
    EXPECT_FALSE(placed(Plane{}, turn).placement->shape_in_object_space);
    EXPECT_TRUE(placed(Plane{}, shear).placement->shape_in_object_space);       // its texture would shear
    EXPECT_FALSE(placed(Disc{}, turn).placement->shape_in_object_space);
    EXPECT_TRUE(placed(Disc{}, grow).placement->shape_in_object_space);         // an ellipse
    const Box b = std::get<Box>(placed(Box{}, grow).shape);
    expect_near(b.min, {-1, -2, -3});
    expect_near(b.max, {3, 4, 5});
    EXPECT_FALSE(placed(Sphere{}, glm::dmat4(1.0)).placement);  // the identity is no placement
}

TEST(Placement, MovingAnObjectMovesItsPatternsWithIt) {
    for (const char* transform : {"transform = { scale = 2, translate = [1, 0, 0] }", "transform = { scale = [2, 1, 1] }"}) {
        Object o = placed(Sphere{}, transform_of(transform));
        const Placement before = *o.placement;
        translate(o, dvec3(0.5, -1, 3));
        const dvec3 p(0.3, 0.2, 0.1);
        expect_near(o.placement->object_point(p + dvec3(0.5, -1, 3)), before.object_point(p));
        const dvec3 centre = o.placement->shape_in_object_space ? apply(o.placement->to_world, std::get<Sphere>(o.shape).center)
                                                                : std::get<Sphere>(o.shape).center;
        expect_near(centre, apply(before.to_world, dvec3(0.0)) + dvec3(0.5, -1, 3));
    }
}

}  // namespace
}  // namespace lancer
