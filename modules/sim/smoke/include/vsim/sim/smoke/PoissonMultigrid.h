#pragma once

// The pressure Poisson operator of the MAC grid and its multigrid preconditioner (McAdams, Sifakis & Teran 2010,
// "A parallel multigrid Poisson solver for fluids simulation"): A x = sum over a fluid cell's faces of (x_cell -
// x_neighbour), with no term through a solid face (Neumann, dp/dn = 0) and x = 0 beyond an open domain face
// (Dirichlet, ambient pressure), and so in a vent cell. The hierarchy halves the grid (a coarse cell is fluid when any of its eight
// children is); one V-cycle smooths with red-black Gauss-Seidel (smoothingSweeps()), red then black going down and
// black then red coming up, so that the preconditioner is symmetric as conjugate gradients needs; the residual goes down as the
// children's sum over two (the coarse operator is the same stencil at twice the spacing), the correction comes up
// piecewise constant. Without an open face the operator is singular (pressure up to a constant): apply() and the
// V-cycle keep the mean over the fluid cells at zero then.

#include "vsim/sim/smoke/SmokeGrid.h"

#include <cstdint>
#include <vector>

namespace vsim::sim::smoke {

class PoissonMultigrid
{
public:
    /// Builds the operator and its hierarchy for the grid's solid cells and domain boundaries.
    void prepare(const SmokeGrid& grid);

    /// y = A x on the finest level (solid cells: 0). x must be 0 in the cells that are not fluid.
    void apply(const std::vector<float>& x, std::vector<float>& y) const;
    /// z = M^-1 r: one V-cycle from z = 0 (solid cells: 0; zero mean where the operator is singular).
    void precondition(const std::vector<float>& r, std::vector<float>& z) const;
    /// Sets the mean over the fluid cells to zero where the operator is singular; nothing otherwise.
    void removeNullSpace(std::vector<float>& x) const;

    /// Red-black sweeps before and after the coarse correction at `depth` (0 the finest): 2 on the finest level
    /// and 6 on the coarser ones, whose sweeps cost an eighth of the finest's or less. The coarse correction's
    /// quality is what sets the iterations: the plume warm-started needs 3.0 MGPCG iterations a projection with
    /// 6 coarse sweeps against 3.7-3.9 with 2, on the CPU at 128^3 and on the GPU at 256^3 (RESULTS.md,
    /// 2026-11-30); more sweeps on the finest level cost more than the iterations they save.
    static constexpr int smoothingSweeps(std::size_t depth) { return depth == 0 ? 2 : 6; }

    bool singular() const { return m_singular; }
    /// Whether the grid's operator is singular: no open domain face and no vent cell.
    static bool isSingular(const SmokeGrid& grid);
    int levels() const { return int(m_levels.size()); }
    /// 1 for a fluid cell of the finest level.
    const std::vector<std::uint8_t>& fluid() const { return m_levels.front().fluid; }

private:
    struct Level
    {
        int nx = 0, ny = 0, nz = 0;
        std::vector<std::uint8_t> fluid;   ///< 1: takes part in the system
        std::vector<std::uint8_t> diagonal; ///< faces that are not solid: fluid neighbours and open domain faces
        mutable std::vector<float> x, b, r; ///< the V-cycle's work (coarse levels)
        std::size_t index(int i, int j, int k) const { return std::size_t(i) + std::size_t(nx) * (j + std::size_t(ny) * k); }
    };

    /// `ambient`: 1 where a cell is a vent (x = 0 there, as beyond an open face).
    static Level makeLevel(int nx, int ny, int nz, std::vector<std::uint8_t> fluid, const std::vector<std::uint8_t>& ambient,
                           const DomainBoundaries& boundaries);
    void applyLevel(const Level& level, const std::vector<float>& x, std::vector<float>& y) const;
    void smooth(const Level& level, std::vector<float>& x, const std::vector<float>& b, int colourFirst) const;
    void vcycle(std::size_t depth, const std::vector<float>& b, std::vector<float>& x) const;

    std::vector<Level> m_levels;
    DomainBoundaries m_boundaries{};
    bool m_singular = false;
};

} // namespace vsim::sim::smoke
