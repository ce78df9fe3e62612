#include <glm/gtc/matrix_access.hpp>
#include <gtest/gtest.h>

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

}  // namespace
}  // namespace lancer
