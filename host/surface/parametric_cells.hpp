#pragma once
// The (u, v) domain of a surface cut into cells for the GPU, each with a world-space box that
// is guaranteed to contain the surface over the cell. The GPU intersects rays with the boxes
// (through a BVH) and runs Newton from seeds inside each cell it enters, so cells must be small
// enough for Newton to converge from their seeds, and their boxes tight.
#include <cstddef>
#include <memory>
#include <vector>

#include <glm/vec3.hpp>

#include "surface/parametric_surface.hpp"
#include "surface/surface_bounds.hpp"

namespace lancer::surface {

struct CellOptions {
    int initial_grid = 8;                     // cells per side to start from
    double max_size_fraction = 1.0 / 32.0;    // a cell's box diagonal <= this * the surface's
    double min_regular_fraction = 1.0 / 512;  // below this size, stop splitting for regularity
    int max_depth = 16;                       // splits below the initial grid
    std::size_t max_cells = std::size_t{1} << 16;
};

// How far the GPU's search widens a cell on each side (of its width, within the surface's
// domain): a root on the edge between two cells lies inside one of them. The partials' bounds
// below cover a little more, so that float's rounding of the widened box stays inside them.
inline constexpr double kCellSearchInflation = 0.01;
inline constexpr double kCellBoundsInflation = 0.015;

struct SurfaceCell {
    double u0, u1, v0, v1;
    dvec3 lo, hi;  // world space; padded outward by a few ulps (round outward again for float)
    bool regular;  // proved on the whole cell: |Su x Sv| >= 1e-3 |Su| |Sv| (so nonzero, well conditioned)
    double float_pad = 0.0;  // added to the box on every side: how far the GPU's float evaluation may stray
    // In the surface's own coordinates, over the cell widened by kCellBoundsInflation (within the
    // domain): bounds of the partials (infinite where the surface is not smooth on all of it),
    // and how far the GPU's float evaluation of S may stray from S.
    IntervalVec3 Su, Sv;
    SecondPartials second;  // bounds of the second partials, for the GPU's Taylor bounds over parts of the cell
    double local_float_pad = 0.0;
    dvec3 centre_point{0.0};  // S at the cell's centre (not finite where S is undefined there)
};

// Splits a cell (along the side that is longer in world space) while its box is larger than
// max_size_fraction of the surface's, or while |Su x Sv| may vanish on it (a pole, a fold) and it
// is larger than min_regular_fraction, up to max_depth. The cells tile the domain exactly: each
// split is at the midpoint, and cells where the surface is undefined everywhere are left out.
// Throws UserError when more than max_cells are needed, or when a cell at the depth limit still
// has an unbounded box (the surface goes to infinity inside the domain).
std::vector<SurfaceCell> subdivide_surface(const ParametricSurface& surface, const CellOptions& options = {});

// subdivide_surface's cells, kept for the surfaces asked for last: the loader cuts each surface
// to prove its bounds and the GPU's packer cuts it again (the scene keeps only the bounds), so
// the second cut, and a `watch` reload of an unchanged surface, is a lookup. Keyed by everything
// the cells depend on (the expressions' nodes without their source columns, the domain, the
// transform and the options, bit for bit). Failures are not kept: each call throws anew.
std::shared_ptr<const std::vector<SurfaceCell>> surface_cells(const ParametricSurface& surface,
                                                              const CellOptions& options = {});

}  // namespace lancer::surface
