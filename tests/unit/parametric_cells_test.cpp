// Cells for the GPU: they tile the (u, v) domain exactly, every sampled point of the surface lies
// in its cell's box (also after a transform), the boxes are small, and the limits are errors.
#include <algorithm>
#include <cmath>
#include <iostream>
#include <numbers>
#include <random>

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include "surface/expr/evaluate.hpp"
#include "surface/parametric_cells.hpp"
#include "unit/surface_fixtures.hpp"

namespace lancer::surface {
namespace {

using std::numbers::pi;

void expect_tiling(const ParametricSurface& s, const std::vector<SurfaceCell>& cells) {
    double area = 0.0;
    for (const auto& c : cells) {
        ASSERT_LT(c.u0, c.u1);
        ASSERT_LT(c.v0, c.v1);
        ASSERT_GE(c.u0, s.u0);
        ASSERT_LE(c.u1, s.u1);
        ASSERT_GE(c.v0, s.v0);
        ASSERT_LE(c.v1, s.v1);
        area += (c.u1 - c.u0) * (c.v1 - c.v0);
    }
    EXPECT_NEAR(area, (s.u1 - s.u0) * (s.v1 - s.v0), 1e-12 * (s.u1 - s.u0) * (s.v1 - s.v0));
    // No two cells overlap (sorted by u0, only cells starting before c ends can overlap it).
    std::vector<SurfaceCell> sorted = cells;
    std::sort(sorted.begin(), sorted.end(), [](const auto& a, const auto& b) { return a.u0 < b.u0; });
    for (std::size_t i = 0; i < sorted.size(); ++i) {
        for (std::size_t j = i + 1; j < sorted.size() && sorted[j].u0 < sorted[i].u1; ++j) {
            bool overlap = sorted[j].v0 < sorted[i].v1 && sorted[i].v0 < sorted[j].v1;
            ASSERT_FALSE(overlap) << "cells " << i << " and " << j << " overlap";
        }
    }
}

void expect_containment(const ParametricSurface& s, const std::vector<SurfaceCell>& cells, std::mt19937& rng) {
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (const auto& c : cells) {
        for (int k = 0; k < 12; ++k) {
            double a = k < 4 ? (k & 1) : unit(rng), b = k < 4 ? (k >> 1) : unit(rng);
            double u = k < 4 ? (a == 0 ? c.u0 : c.u1) : c.u0 + (c.u1 - c.u0) * a;
            double v = k < 4 ? (b == 0 ? c.v0 : c.v1) : c.v0 + (c.v1 - c.v0) * b;
            dvec3 p = evaluate_surface(s, std::min(u, c.u1), std::min(v, c.v1)).P;
            for (int i = 0; i < 3; ++i) {
                ASSERT_GE(p[i], c.lo[i]) << "at (" << u << ", " << v << ") axis " << i;
                ASSERT_LE(p[i], c.hi[i]) << "at (" << u << ", " << v << ") axis " << i;
            }
        }
    }
}

TEST(ParametricCells, TileTheDomainAndContainTheSurface) {
    std::mt19937 rng(21);
    for (const auto& spec : test::classic_surfaces()) {
        SCOPED_TRACE(spec.name);
        ParametricSurface s = test::make_surface(spec);
        auto cells = subdivide_surface(s);
        std::size_t regular = std::count_if(cells.begin(), cells.end(), [](const auto& c) { return c.regular; });
        std::cout << "[ cells    ] " << spec.name << ": " << cells.size() << " cells, " << regular << " regular\n";
        expect_tiling(s, cells);
        expect_containment(s, cells, rng);
    }
}

TEST(ParametricCells, TransformedSurfaceBoxesContainTheWorldSurface) {
    std::mt19937 rng(22);
    for (const char* name : {"torus", "klein8"}) {
        ParametricSurface s = test::make_surface(test::surface_spec(name));
        s.to_world = glm::translate(glm::dmat4(1.0), glm::dvec3(3.0, -1.0, 20.0)) *
                     glm::rotate(glm::dmat4(1.0), 0.7, glm::normalize(glm::dvec3(1.0, 2.0, -0.5))) *
                     glm::scale(glm::dmat4(1.0), glm::dvec3(2.0, 0.5, 1.25));
        auto cells = subdivide_surface(s);
        expect_tiling(s, cells);
        expect_containment(s, cells, rng);
    }
}

TEST(ParametricCells, BoxesAreSmallAndPolesAreIrregular) {
    ParametricSurface torus = test::make_surface(test::surface_spec("torus"));
    auto cells = subdivide_surface(torus);
    const double torus_diagonal = std::sqrt(2.7 * 2.7 * 2 + 0.7 * 0.7);
    for (const auto& c : cells) {
        EXPECT_TRUE(c.regular);
        EXPECT_LE(glm::length(c.hi - c.lo), torus_diagonal / 32.0 * 1.0001);
    }
    ParametricSurface sphere = test::make_surface(test::surface_spec("sphere"));
    auto sphere_cells = subdivide_surface(sphere);
    for (const auto& c : sphere_cells) {
        bool at_pole = c.v0 == sphere.v0 || c.v1 == sphere.v1;
        EXPECT_EQ(c.regular, !at_pole) << c.v0 << " " << c.v1;
    }
}

TEST(ParametricCells, MeanValueFormMakesBoxesTighterThanTheNaturalExtension) {
    // The natural extension of u - u^3/3 + u v^2 bounds each term separately and overestimates;
    // the mean-value form is nearly exact for small cells. Never looser, always containing.
    for (const char* name : {"enneper", "torus"}) {
        ParametricSurface s = test::make_surface(test::surface_spec(name));
        CellOptions coarse;
        coarse.initial_grid = 16;
        coarse.max_size_fraction = 1.0;  // no refinement: compare boxes of the same cells
        auto cells = subdivide_surface(s, coarse);
        ASSERT_EQ(cells.size(), 256u);
        double volume = 0.0, natural_volume = 0.0;
        for (const auto& c : cells) {
            Interval U(c.u0, c.u1), V(c.v0, c.v1);
            Interval x = evaluate(s.x, U, V), y = evaluate(s.y, U, V), z = evaluate(s.z, U, V);
            // The boxes also hold the surface as the GPU evaluates it, in float: that margin is
            // added to both.
            const double pad = 2.0 * c.float_pad;
            double natural = (x.width() + pad) * (y.width() + pad) * (z.width() + pad);
            double box = (c.hi.x - c.lo.x) * (c.hi.y - c.lo.y) * (c.hi.z - c.lo.z);
            EXPECT_LE(box, natural * (1 + 1e-9) + 1e-300) << name;
            natural_volume += natural;
            volume += box;
        }
        if (std::string(name) == "enneper") {
            EXPECT_LT(volume, 0.7 * natural_volume);
        }
    }
}

// The bounds the GPU's search relies on (shapes/parametric.glsl): at points of each cell widened
// as the search widens it, S's partials lie within the cell's first-partial bounds, and their
// change over small steps (finite differences of the exact partials) within the second-partial
// bounds; S at the cell's centre is the one stored.
TEST(ParametricCells, PartialsLieWithinTheCellsBounds) {
    auto within = [](const Interval& b, double x, double slack) { return x >= b.lo - slack && x <= b.hi + slack; };
    for (const auto& spec : test::classic_surfaces()) {
        SCOPED_TRACE(spec.name);
        ParametricSurface s = test::make_surface(spec);
        std::mt19937 rng(7);
        std::uniform_real_distribution<double> unit(0.0, 1.0);
        int checked = 0;
        for (const SurfaceCell& c : subdivide_surface(s)) {
            const double wu = kCellSearchInflation * (c.u1 - c.u0), wv = kCellSearchInflation * (c.v1 - c.v0);
            const double u0 = std::max(s.u0, c.u0 - wu), u1 = std::min(s.u1, c.u1 + wu);
            const double v0 = std::max(s.v0, c.v0 - wv), v1 = std::min(s.v1, c.v1 + wv);
            const SurfacePoint centre = evaluate_surface(s, 0.5 * (c.u0 + c.u1), 0.5 * (c.v0 + c.v1));
            for (int k = 0; k < 3; ++k) {
                if (std::isfinite(centre.P[k])) {
                    EXPECT_NEAR(c.centre_point[k], centre.P[k], 1e-12 * (1.0 + std::abs(centre.P[k])));
                }
            }
            for (int n = 0; n < 4; ++n) {
                const double u = u0 + (u1 - u0) * unit(rng), v = v0 + (v1 - v0) * unit(rng);
                const SurfacePoint p = evaluate_surface(s, u, v);
                const double h = 1e-6 * std::max(u1 - u0, v1 - v0);
                const SurfacePoint pu = evaluate_surface(s, std::min(u + h, u1), v);
                const SurfacePoint pv = evaluate_surface(s, u, std::min(v + h, v1));
                const double hu = std::min(u + h, u1) - u, hv = std::min(v + h, v1) - v;
                for (int k = 0; k < 3; ++k) {
                    if (!std::isfinite(p.Pu[k]) || !std::isfinite(p.Pv[k])) continue;
                    const double scale = 1e-9 * (1.0 + std::abs(p.Pu[k]) + std::abs(p.Pv[k]));
                    EXPECT_TRUE(within(c.Su[k], p.Pu[k], scale)) << "S_u at (" << u << ", " << v << ")";
                    EXPECT_TRUE(within(c.Sv[k], p.Pv[k], scale)) << "S_v at (" << u << ", " << v << ")";
                    // Finite differences carry an error of the order of the step times the third
                    // partials: a relative slack of 1e-4.
                    const double fd = 1e-4 * (1.0 + std::abs(c.second.Suu[k].lo) + std::abs(c.second.Suu[k].hi) +
                                             std::abs(c.second.Suv[k].lo) + std::abs(c.second.Suv[k].hi) +
                                             std::abs(c.second.Svv[k].lo) + std::abs(c.second.Svv[k].hi));
                    if (hu > 0.0) {
                        EXPECT_TRUE(within(c.second.Suu[k], (pu.Pu[k] - p.Pu[k]) / hu, fd)) << "S_uu at (" << u << ", " << v << ")";
                        EXPECT_TRUE(within(c.second.Suv[k], (pu.Pv[k] - p.Pv[k]) / hu, fd)) << "S_uv at (" << u << ", " << v << ")";
                    }
                    if (hv > 0.0) {
                        EXPECT_TRUE(within(c.second.Svv[k], (pv.Pv[k] - p.Pv[k]) / hv, fd)) << "S_vv at (" << u << ", " << v << ")";
                    }
                    ++checked;
                }
            }
        }
        EXPECT_GT(checked, 100);
    }
}

TEST(ParametricCells, UndefinedPartsAreLeftOut) {
    ParametricSurface s;
    s.x = parse_expression("u", {});
    s.y = parse_expression("v", {});
    s.z = parse_expression("sqrt(u - 0.5)", {});
    auto cells = subdivide_surface(s);
    double area = 0.0;
    for (const auto& c : cells) {
        EXPECT_GE(c.u1, 0.5);  // cells ending at u = 0.5 hold the defined line u = 0.5
        if (c.u0 >= 0.5) area += (c.u1 - c.u0) * (c.v1 - c.v0);
    }
    EXPECT_NEAR(area, 0.5, 1e-12);
    std::mt19937 rng(23);
    std::vector<SurfaceCell> defined;
    for (const auto& c : cells)
        if (c.u0 >= 0.5) defined.push_back(c);
    expect_containment(s, defined, rng);
}

TEST(ParametricCells, TooManyCellsIsAUserError) {
    ParametricSurface s = test::make_surface(test::surface_spec("klein8"));
    CellOptions options;
    options.max_cells = 100;
    try {
        subdivide_surface(s, options);
        FAIL() << "no error";
    } catch (const UserError& e) {
        EXPECT_NE(std::string(e.what()).find("more than 100 cells"), std::string::npos) << e.what();
    }
}

TEST(ParametricCells, AnUnboundedSurfaceIsAUserError) {
    ParametricSurface s;
    s.x = parse_expression("1/u", {});
    s.y = parse_expression("v", {});
    s.z = parse_expression("0", {});
    try {
        subdivide_surface(s);
        FAIL() << "no error";
    } catch (const UserError& e) {
        EXPECT_NE(std::string(e.what()).find("cannot bound the surface near (u, v) = (0"), std::string::npos)
            << e.what();
    }
    s.u0 = 0.1;  // away from the pole it is fine
    EXPECT_NO_THROW(subdivide_surface(s));
}

TEST(ParametricCells, BadDomainsAreUserErrors) {
    ParametricSurface s = test::make_surface(test::surface_spec("torus"));
    s.u1 = s.u0;
    EXPECT_THROW(subdivide_surface(s), UserError);
    s = test::make_surface(test::surface_spec("torus"));
    s.v1 = kInf;
    EXPECT_THROW(subdivide_surface(s), UserError);
}

// The loader and the GPU's packer both ask for a surface's cells: the second asks for a surface
// built anew from the same text, and must get the cells the first computed, not cut them again.
TEST(ParametricCells, AnEqualSurfaceGetsTheCellsCutBefore) {
    const ParametricSurface torus = test::make_surface(test::surface_spec("torus"));
    auto first = surface_cells(torus);
    auto again = surface_cells(test::make_surface(test::surface_spec("torus")));
    EXPECT_EQ(first.get(), again.get());
    const std::vector<SurfaceCell> cut = subdivide_surface(torus);
    ASSERT_EQ(first->size(), cut.size());
    for (std::size_t i = 0; i < cut.size(); ++i) {
        EXPECT_EQ(first->at(i).lo, cut[i].lo);
        EXPECT_EQ(first->at(i).hi, cut[i].hi);
    }
}

// Anything the cells depend on makes another entry: a constant, the domain, the transform, the
// options.
TEST(ParametricCells, ASurfaceThatDiffersGetsItsOwnCells) {
    const ParametricSurface torus = test::make_surface(test::surface_spec("torus"));
    auto base = surface_cells(torus);

    ParametricSurface constant = test::make_surface(test::surface_spec("torus"));
    auto it = std::find_if(constant.x.nodes.begin(), constant.x.nodes.end(),
                           [](const Node& n) { return n.op == Op::Constant && n.value != 0.0; });
    ASSERT_NE(it, constant.x.nodes.end());
    it->value = std::nextafter(it->value, 1e300);  // one ulp
    auto changed = surface_cells(constant);
    EXPECT_NE(changed.get(), base.get());

    ParametricSurface domain = test::make_surface(test::surface_spec("torus"));
    domain.u1 = 0.5 * (domain.u0 + domain.u1);
    auto half = surface_cells(domain);
    EXPECT_NE(half.get(), base.get());
    EXPECT_LT(half->size(), base->size());

    ParametricSurface moved = test::make_surface(test::surface_spec("torus"));
    moved.to_world = glm::translate(glm::dmat4(1.0), glm::dvec3(5.0, 0.0, 0.0));
    auto shifted = surface_cells(moved);
    ASSERT_NE(shifted.get(), base.get());
    EXPECT_EQ(shifted->front().lo.x, subdivide_surface(moved).front().lo.x);
    EXPECT_GT(shifted->front().lo.x, base->front().lo.x + 4.0);

    CellOptions coarse;
    coarse.max_size_fraction = 1.0 / 8.0;
    auto fewer = surface_cells(torus, coarse);
    EXPECT_NE(fewer.get(), base.get());
    EXPECT_LT(fewer->size(), base->size());
    EXPECT_EQ(surface_cells(torus).get(), base.get());  // still kept
}

}  // namespace
}  // namespace lancer::surface
