// Property tests of the direction grids (gpu/packing/direction_grids.hpp): a ray along a half-line from a
// grid's origin, its cell found with the shader's float arithmetic (scene.glsl's grid_hit), lists
// every box the ray enters, with a distance no greater than where it enters; the grids refuse
// what they cannot hold.
#include <algorithm>
#include <cstring>
#include <random>

#include <gtest/gtest.h>

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>

#include "gpu/packing/direction_grids.hpp"

namespace lancer::gpu {
namespace {

using glm::dvec3;

std::vector<Aabb> lattice_of_boxes(unsigned seed, double size) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> jitter(-0.2, 0.2), half(0.5 * size, size);
    std::vector<Aabb> boxes;
    for (int i = 0; i < 10; ++i)
        for (int j = 0; j < 10; ++j)
            for (int k = 0; k < 6; ++k) {
                dvec3 c(i - 4.5 + jitter(rng), 0.6 + 0.65 * k + jitter(rng), j - 4.5 + jitter(rng));
                dvec3 h(half(rng), half(rng), half(rng));
                boxes.push_back({c - h, c + h});
            }
    return boxes;
}

// A corner of a random box: rays aimed at corners graze their boxes' footprints, where the
// grids' margins for rounding matter.
dvec3 random_corner(const std::vector<Aabb>& boxes, std::mt19937& rng) {
    const Aabb& b = boxes[std::uniform_int_distribution<std::size_t>(0, boxes.size() - 1)(rng)];
    const unsigned c = std::uniform_int_distribution<unsigned>(0, 7)(rng);
    return dvec3(c & 1 ? b.hi.x : b.lo.x, c & 2 ? b.hi.y : b.lo.y, c & 4 ? b.hi.z : b.lo.z);
}

// Whether direction d is a camera ray's: forward + x right + y up with |x|, |y| <= 1.
bool in_view(const EyeView& view, const dvec3& d) {
    const double z = glm::dot(d, view.forward);
    const double x = glm::dot(d, view.right) / glm::dot(view.right, view.right) / z;
    const double y = glm::dot(d, view.up) / glm::dot(view.up, view.up) / z;
    return z > 0.0 && std::abs(x) <= 1.0 && std::abs(y) <= 1.0;
}

// Where the ray o + t d (t in [0, t_max]) enters the box, or -1 if it misses it.
double entry(const dvec3& o, const dvec3& d, double t_max, const Aabb& b) {
    double t0 = 0.0, t1 = t_max;
    for (int a = 0; a < 3; ++a) {
        if (d[a] == 0.0) {
            if (o[a] < b.lo[a] || o[a] > b.hi[a]) return -1.0;
            continue;
        }
        double u = (b.lo[a] - o[a]) / d[a], v = (b.hi[a] - o[a]) / d[a];
        t0 = std::max(t0, std::min(u, v));
        t1 = std::min(t1, std::max(u, v));
    }
    return t0 <= t1 ? t0 : -1.0;
}

struct Listed {
    std::vector<std::pair<uint, float>> entries;  // primitive, distance
};

// The cell of direction w as grid_hit finds it, in float.
Listed cell_of(const DirectionGrid& g, const DirectionGrids& grids, glm::vec3 w) {
    Listed out;
    auto xyz = [](const vec4& v) { return glm::vec3(v.x, v.y, v.z); };
    float z = glm::dot(w, xyz(g.axis));
    glm::vec2 c = (glm::vec2(glm::dot(w, xyz(g.across_u)), glm::dot(w, xyz(g.across_v))) / z - glm::vec2(g.window.x, g.window.y)) *
                  glm::vec2(g.window.z, g.window.w);
    if (!(z > 0.0f && c.x >= 0.0f && c.y >= 0.0f && c.x < float(g.columns) && c.y < float(g.rows))) return out;
    uint cell = g.first_cell + uint(c.y) * g.columns + uint(c.x);
    for (uint e = grids.cells[cell]; e < grids.cells[cell + 1]; ++e) {
        float near;
        std::memcpy(&near, &grids.entries[2 * e + 1], sizeof near);
        out.entries.emplace_back(grids.entries[2 * e], near);
    }
    return out;
}

void expect_listed(const Listed& cell, uint index, double t_enter, const char* what) {
    auto it = std::find_if(cell.entries.begin(), cell.entries.end(), [&](const auto& e) { return e.first == index; });
    ASSERT_NE(it, cell.entries.end()) << what << ": box " << index << ", entered at " << t_enter << ", is not listed";
    EXPECT_LE(it->second, t_enter) << what << ": box " << index;
}

void expect_nearest_first(const Listed& cell) {
    for (std::size_t k = 1; k < cell.entries.size(); ++k) EXPECT_LE(cell.entries[k - 1].second, cell.entries[k].second);
}

TEST(DirectionGrids, ALightsGridListsEveryBoxAShadowSegmentEnters) {
    const std::vector<Aabb> boxes = lattice_of_boxes(7, 0.25);
    const std::vector<dvec3> lights = {{-10, 18, -12}, {12, 10, -8}, {0.3, 30, 0.2}, {0, 2.5, -40}};
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> x(-7, 7), y(-0.5, 6), unit(0, 1);
    for (const dvec3& light : lights) {
        DirectionGrids grids;
        const DirectionGrid g = direction_grid(light, boxes, nullptr, grids);
        ASSERT_EQ(g.valid, 1u) << "light at " << light.x << ", " << light.y << ", " << light.z;
        int entered = 0;
        for (int r = 0; r < 20000; ++r) {
            // A surface point anywhere around the boxes, or beyond a box's corner as seen from the
            // light; its shadow segment runs to the light.
            const dvec3 p = r % 2 ? light + std::uniform_real_distribution<double>(1.2, 2.0)(rng) * (random_corner(boxes, rng) - light)
                                  : dvec3(x(rng), y(rng), x(rng));
            const glm::vec3 pf(p);
            const Listed cell = cell_of(g, grids, pf - glm::vec3(light));
            expect_nearest_first(cell);
            const dvec3 d = dvec3(glm::vec3(light)) - dvec3(pf);
            for (uint i = 0; i < boxes.size(); ++i) {
                double t = entry(dvec3(pf), d, 1.0, boxes[i]);
                if (t < 0.0) continue;
                ++entered;
                // The shader compares a box's distance from the light with the point's.
                expect_listed(cell, i, glm::length(pf - glm::vec3(light)), "shadow segment");
                if (HasFailure()) return;
            }
        }
        EXPECT_GT(entered, 1000);
    }
}

TEST(DirectionGrids, TheEyesGridListsEveryBoxACameraRayEnters) {
    const std::vector<Aabb> boxes = lattice_of_boxes(3, 0.3);
    const dvec3 eye(0.2, 6, -16);
    const dvec3 forward = glm::normalize(dvec3(0, 3, 0) - eye);
    const dvec3 right = 0.6 * glm::normalize(glm::cross(dvec3(0, 1, 0), forward));
    const dvec3 up = 0.45 * glm::normalize(glm::cross(forward, right));
    const EyeView view{eye, forward, right, up};
    DirectionGrids grids;
    const DirectionGrid g = direction_grid(eye, boxes, &view, grids);
    ASSERT_EQ(g.valid, 1u);
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> ndc(-1, 1);
    int entered = 0;
    for (int r = 0; r < 20000; ++r) {
        glm::vec3 d = glm::normalize(glm::vec3(r % 2 ? random_corner(boxes, rng) - eye : forward + ndc(rng) * right + ndc(rng) * up));
        if (!in_view(view, dvec3(d))) continue;
        const Listed cell = cell_of(g, grids, d);
        expect_nearest_first(cell);
        for (uint i = 0; i < boxes.size(); ++i) {
            double t = entry(dvec3(glm::vec3(eye)), dvec3(d), 1e9, boxes[i]);
            if (t < 0.0) continue;
            ++entered;
            expect_listed(cell, i, t, "camera ray");
            if (HasFailure()) return;
        }
    }
    EXPECT_GT(entered, 10000);
}

// common.glsl's spawn offset for a hit on a plane (shapes/plane.glsl's error bound), in float.
float plane_spawn_offset(glm::vec3 origin, glm::vec3 point, float t, glm::vec3 p) {
    auto max_abs = [](glm::vec3 v) { return std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)}); };
    const float rounding = 5.9604645e-8f;
    const float error = 16.0f * rounding * (max_abs(origin) + max_abs(point) + t);
    return 2.0f * error + 4.0f * rounding * max_abs(p);
}

// The grids of the lights and of the view, as the acceleration plan makes them.
DirectionGrids direction_grids(const EyeView& view, const Mirror* mirror, std::span<const Light> lights, std::span<const Aabb> boxes) {
    DirectionGrids grids = no_grids();
    add_light_grids(lights, boxes, grids);
    add_view_grids(view, mirror, boxes, grids);
    return grids;
}

// Camera rays from `eye` (every other one toward the mirror image of a point `target` picks,
// the rest anywhere in view), their hits on the floor (y = 0, given by `floor.point`) and their
// reflections as the shader makes them: the mirror's grid lists every box a reflection enters.
template <class Target>
void expect_reflections_listed(const std::vector<Aabb>& boxes, const dvec3& eye, const Mirror& floor, Target target) {
    const dvec3 forward = glm::normalize(dvec3(0, 2, 0) - eye);
    const dvec3 right = 0.7 * glm::normalize(glm::cross(dvec3(0, 1, 0), forward));
    const dvec3 up = 0.4 * glm::normalize(glm::cross(forward, right));
    const EyeView view{dvec3(glm::vec3(eye)), forward, right, up};
    const DirectionGrids grids = direction_grids(view, &floor, {}, boxes);
    const DirectionGrid& g = grids.grids[DIRECTION_GRID_MIRROR];
    ASSERT_EQ(g.valid, 1u) << "eye at " << eye.y << ", floor point at " << floor.point.x;
    std::mt19937 rng(17);
    std::uniform_real_distribution<double> ndc(-1, 1);
    int entered = 0;
    for (int r = 0; r < 20000; ++r) {
        dvec3 aim = forward + ndc(rng) * right + ndc(rng) * up;
        if (r % 2) {
            const dvec3 c = target(rng);
            aim = dvec3(c.x, -c.y, c.z) - view.eye;
        }
        const glm::vec3 o(view.eye), d = glm::normalize(glm::vec3(aim));
        if (!(d.y < 0.0f) || !in_view(view, dvec3(d))) continue;
        const float t = -o.y / d.y;
        const glm::vec3 p = o + t * d, n(0, 1, 0);
        const glm::vec3 start = p + plane_spawn_offset(o, glm::vec3(floor.point), t, p) * n;
        const glm::vec3 dir = glm::reflect(d, n);
        const Listed cell = cell_of(g, grids, dir);
        expect_nearest_first(cell);
        const double from_image = glm::length(start - glm::vec3(g.origin));
        for (uint i = 0; i < boxes.size(); ++i) {
            double enter = entry(dvec3(start), dvec3(dir), 1e9, boxes[i]);
            if (enter < 0.0) continue;
            ++entered;
            expect_listed(cell, i, from_image + enter, "reflected camera ray");
            if (::testing::Test::HasFailure()) return;
        }
    }
    EXPECT_GT(entered, 1000);
}

TEST(DirectionGrids, TheMirrorsGridListsEveryBoxACameraRaysReflectionEnters) {
    const std::vector<Aabb> boxes = lattice_of_boxes(9, 0.3);
    const Mirror floor{dvec3(0.0), dvec3(0, 1, 0)};
    for (const dvec3& eye : {dvec3(0.2, 6, -16), dvec3(20, 2.5, -30), dvec3(-3, 14, -6)}) {
        expect_reflections_listed(boxes, eye, floor, [&](std::mt19937& rng) { return random_corner(boxes, rng); });
        if (HasFailure()) return;
    }
}

// A floor given by a point far from the scene: a reflection starts above the floor by a spawn
// offset that grows with that point (plane.glsl's error bound). Aimed at a point below a box's
// bottom edge by less than that offset, it passes over that point into the box while its
// direction, seen from the image eye, lies outside the box's footprint: only the mirror grid's
// slack allows for that (the boxes' and footprints' padding scale with the boxes and the
// projection, not with the floor's point; without the slack, 57 of these rays find their box
// unlisted). Few boxes, so that the grid is still worth its slack.
TEST(DirectionGrids, TheMirrorsGridAllowsForTheSpawnOffsetsOfAFarFloorPoint) {
    std::vector<Aabb> boxes;
    std::mt19937 place(23);
    std::uniform_real_distribution<double> across(-5, 5), height(0.6, 3), half(0.15, 0.3);
    for (int i = 0; i < 50; ++i) {
        const dvec3 c(across(place), height(place), across(place)), h(half(place), half(place), half(place));
        boxes.push_back({c - h, c + h});
    }
    const Mirror floor{dvec3(3000, 0, -2000), dvec3(0, 1, 0)};
    const dvec3 eye(0.2, 6, -16);
    // The least spawn offset, over the floor's points: the reflections start that far above it.
    const double below = plane_spawn_offset(glm::vec3(eye), glm::vec3(floor.point), 0.0f, glm::vec3(0.0f));
    expect_reflections_listed(boxes, eye, floor, [&](std::mt19937& rng) {
        const Aabb& b = boxes[std::uniform_int_distribution<std::size_t>(0, boxes.size() - 1)(rng)];
        std::uniform_real_distribution<double> unit(0, 1);
        const double along = unit(rng), depth = unit(rng) * below;
        const unsigned edge = std::uniform_int_distribution<unsigned>(0, 3)(rng);
        const double x = edge < 2 ? b.lo.x + along * (b.hi.x - b.lo.x) : edge == 2 ? b.lo.x : b.hi.x;
        const double z = edge >= 2 ? b.lo.z + along * (b.hi.z - b.lo.z) : edge == 0 ? b.lo.z : b.hi.z;
        return dvec3(x, b.lo.y - depth, z);
    });
}

TEST(DirectionGrids, BoxesAroundTheEyesPlaneAreInEveryCellAndThoseBehindInNone) {
    std::vector<Aabb> boxes = lattice_of_boxes(3, 0.3);
    const dvec3 eye(0, 3, -2);  // among the boxes
    const EyeView view{eye, dvec3(0, 0, 1), dvec3(0.6, 0, 0), dvec3(0, 0.45, 0)};
    boxes.push_back({dvec3(-0.1, 2.9, -2.1), dvec3(0.1, 3.1, -1.9)});  // around the eye
    DirectionGrids grids;
    const DirectionGrid g = direction_grid(eye, boxes, &view, grids);
    ASSERT_EQ(g.valid, 1u);
    const uint around = static_cast<uint>(boxes.size() - 1);
    for (uint cell = 0; cell < g.columns * g.rows; ++cell) {
        bool found = false, behind = false;
        for (uint e = grids.cells[g.first_cell + cell]; e < grids.cells[g.first_cell + cell + 1]; ++e) {
            found |= grids.entries[2 * e] == around;
            behind |= boxes[grids.entries[2 * e]].hi.z < eye.z;
        }
        EXPECT_TRUE(found) << "cell " << cell;
        EXPECT_FALSE(behind) << "cell " << cell;
    }
}

TEST(DirectionGrids, ALightAmongTheBoxesOrTooMuchDepthGetsNoGrid) {
    const std::vector<Aabb> boxes = lattice_of_boxes(7, 0.25);
    DirectionGrids grids;
    EXPECT_EQ(direction_grid(dvec3(0, 3, 0), boxes, nullptr, grids).valid, 0u) << "a light among the boxes";
    // A thousand boxes one behind the other: every cell would list them all.
    std::vector<Aabb> column;
    for (int i = 0; i < 1000; ++i) column.push_back({dvec3(-1, -1, 2.0 * i), dvec3(1, 1, 2.0 * i + 1)});
    EXPECT_EQ(direction_grid(dvec3(0, 0, -10), column, nullptr, grids).valid, 0u) << "too deep";
}

TEST(DirectionGrids, AreaLightsAndLightsBeyondTheGridsHaveNone) {
    const std::vector<Aabb> boxes = lattice_of_boxes(7, 0.25);
    std::vector<Light> lights(DIRECTION_GRID_COUNT + 2);
    for (std::size_t k = 0; k < lights.size(); ++k) {
        lights[k].type = k == 2 ? LIGHT_AREA : (k == 3 ? LIGHT_SPOT : LIGHT_POINT);
        lights[k].position = vec4(-10.0f + float(k), 18.0f, -12.0f, 0.0f);
    }
    const EyeView view{dvec3(0, 6, -16), dvec3(0, 0, 1), dvec3(0.6, 0, 0), dvec3(0, 0.45, 0)};
    const DirectionGrids grids = direction_grids(view, nullptr, lights, boxes);
    ASSERT_EQ(grids.grids.size(), DIRECTION_GRID_COUNT);
    EXPECT_EQ(grids.grids[DIRECTION_GRID_EYE].valid, 1u);
    for (uint k = 0; k + DIRECTION_GRID_LIGHT < DIRECTION_GRID_COUNT; ++k)
        EXPECT_EQ(grids.grids[DIRECTION_GRID_LIGHT + k].valid, k == 2 ? 0u : 1u) << "light " << k;
}

}  // namespace
}  // namespace lancer::gpu
