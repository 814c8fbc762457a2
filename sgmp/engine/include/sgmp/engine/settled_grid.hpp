#pragma once
/// @file settled_grid.hpp
/// The settled particles of a drop, in the testbed's one cell grid (IncrementalGrid,
/// sgmp/pack/incremental_grid.hpp), so that a drop only looks at nearby cells and the work
/// per drop does not grow with N.
///
/// Cells are cubes of side h ≥ `min_cell` (the container's width is divided into
/// ⌊width / min_cell⌋ equal columns, so cells tile the walls exactly; CellLayout::over);
/// layers are added upward from the floor as particles settle higher, so the grid only ever
/// spans the settled pack. Points outside the walls are clamped to the edge cells. Only
/// settled particles are stored: particles still waiting to fall are never obstacles. A
/// scan sees each cell's spheres in the order they settled; dense cells turn sparse as the
/// one grid's rule says (a wide blend's small cells), with the same scans.
#include <cstddef>
#include <utility>
#include <vector>

#include "sgmp/pack/geometry.hpp"
#include "sgmp/pack/incremental_grid.hpp"

namespace sgmp::engine {

/// A settled sphere as the grid stores it (plain numbers, for cache-friendly scans).
struct Sphere {
    double x = 0.0;
    double y = 0.0;
    double z = 0.0;
    double r = 0.0;
};

using sgmp::CellRange;

class SettledGrid : public IncrementalGrid<Sphere> {
  public:
    /// `min_cell` > 0 is the smallest allowed cell side (typically the largest diameter).
    SettledGrid(const Container& container, double min_cell)
        : IncrementalGrid<Sphere>(CellLayout::over(container, min_cell)) {}

    /// Empties the grid and moves it to `container` (same cell sides as before), keeping the
    /// memory of its layers for reuse.
    void reset(const Container& container) {
        CellLayout moved = layout();
        moved.x_min = container.x_min;
        moved.z_min = container.z_min;
        moved.floor = container.floor;
        IncrementalGrid<Sphere>::reset(moved);
    }
};

/// Lowest height y ≥ `from` at which a sphere of radius r centred at (x, ·, z) overlaps no
/// sphere of `grid` (touching allowed). Every sphere j with horizontal distance h < r + r_j
/// blocks the open interval y_j ± √((r + r_j)² − h²); the answer is the first point at or
/// above `from` outside all of them. `r_max` bounds the stored radii; `scratch` is reused.
double lowest_free_height(const SettledGrid& grid, double x, double z, double r, double r_max,
                          double from, std::vector<std::pair<double, double>>& scratch);

}  // namespace sgmp::engine
