#include <gtest/gtest.h>

#include "cpu/tracer.hpp"

namespace lancer::cpu {
namespace {

Material checker(double size) {
    Material m;
    m.checker = Checker{{1, 1, 1}, {0.5, 0.5, 0.5}, size};
    return m;
}

TEST(Checker, FirstColourWhereTheCellSumIsEven) {
    Material m = checker(1.0);
    EXPECT_EQ(pigment_at(m, {0.5, 0.5, 0.5}), dvec3(1.0));
    EXPECT_EQ(pigment_at(m, {1.5, 0.5, 0.5}), dvec3(0.5));
    EXPECT_EQ(pigment_at(m, {1.5, 1.5, 0.5}), dvec3(1.0));
    EXPECT_EQ(pigment_at(m, {-0.5, 0.5, 0.5}), dvec3(0.5));  // floor, not truncation, below zero
    EXPECT_EQ(pigment_at(m, {-0.5, -0.5, 0.5}), dvec3(1.0));
}

TEST(Checker, SizeScalesTheCells) {
    Material m = checker(2.0);
    EXPECT_EQ(pigment_at(m, {1.9, 0.5, 0.5}), dvec3(1.0));
    EXPECT_EQ(pigment_at(m, {2.1, 0.5, 0.5}), dvec3(0.5));
}

// A floor at y = 0 whose hit points land a rounding error above or below zero must not flicker.
TEST(Checker, SurfaceOnAnIntegerPlaneIsStable) {
    Material m = checker(1.0);
    for (double y : {0.0, 1e-9, -1e-9, 1e-6, -1e-6}) {
        EXPECT_EQ(pigment_at(m, {0.5, y, 0.5}), dvec3(1.0)) << y;
        EXPECT_EQ(pigment_at(m, {1.5, y, 0.5}), dvec3(0.5)) << y;
    }
}

TEST(Checker, SolidMaterialIgnoresPosition) {
    Material m;
    m.color = {0.2, 0.3, 0.4};
    EXPECT_EQ(pigment_at(m, {7.5, -3.2, 1.1}), dvec3(0.2, 0.3, 0.4));
}

}  // namespace
}  // namespace lancer::cpu
