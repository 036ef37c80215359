#pragma once

// The launchers of the smoke step's kernels (host functions; each runs on the default stream). The algorithm is
// the CPU's, file by file: AdvectionKernels.cu is modules/sim/smoke's Advection.cpp, ForceKernels.cu its
// SmokeForces.cpp, the sources, the solids and VortexParticles.cpp, ProjectionKernels.cu its PressureProjection.cpp
// and PoissonMultigrid.cpp's operator, ReductionKernels.cu the sums and maxima they need.

#include "SmokeDevice.cuh"

#include "vsim/sim/smoke/PressureWarmStart.h"

namespace vsim::cuda::smoke {

// ---- advection (AdvectionKernels.cu)
/// The semi-Lagrangian (and with `macCormack` the corrected) advection of lattice `kind` (0, 1, 2 the u, v, w
/// faces, 3 the cells) into `field` from `old`, through the velocity (u0, v0, w0) of the step's start.
/// `forward`: scratch of the lattice's size.
void advectLattice(const GridView& g, int kind, float* field, const float* old, const float* u0, const float* v0,
                   const float* w0, float dtCells, bool macCormack, float* forward);
/// One axis's sweep of the conservative transport of density and temperature (Advection.cpp's transportAlong):
/// `velocity` the axis's face velocities at the step's start, `substeps` sub-steps of `ratio` = dt / substeps / h,
/// `start` the two fields at the step's start (density then temperature, cells() each). Each sub-step writes the
/// spare arrays from the current ones and swaps them: afterwards `density` and `temperature` (and g's) point at
/// the result, the spares at the other buffers. `clampLast`: the last sub-step writes clampScalars' values.
void transportAxis(GridView& g, int axis, const float* velocity, int substeps, float ratio, const float* start,
                   float*& density, float*& temperature, float*& spareDensity, float*& spareTemperature, bool clampLast);
/// Negative smoke and heat to zero; none in cells that are not fluid.
void clampScalars(const GridView& g);

// ---- forces, sources, solids, particles (ForceKernels.cu)
/// A source's cells in the box [lo, hi] (cells, inclusive): smoke and heat over dt, or its velocity on their faces.
void applySource(const GridView& g, const int lo[3], const int hi[3], double cx, double cy, double cz, double radius,
                 float densityAdded, float temperature, float vx, float vy, float vz, bool setVelocity);
/// temperature *= keep, then the buoyancy along `up` (SmokeForces.cpp's addBuoyancy).
void addHeatForces(const GridView& g, float keep, double dt, double alpha, double beta, const double up[3]);
/// force (3 per cell, zeroed here) = vorticity confinement (epsilon); `omega` 3 per cell and `magnitude` 1 per
/// cell are scratch.
void vorticityConfinement(const GridView& g, double epsilon, float* force, float* omega, float* magnitude);
/// The vortex particles' forcing added to `force` (particles: 6 doubles each, position then vorticity).
void particleForcing(const GridView& g, const double* particles, int count, double epsilon, double radius, float* force);
/// u += dt f on the faces between cells that are not solid (SmokeForces.cpp's addCellForces).
void addCellForces(const GridView& g, const float* force, float dt);
/// The solids: the static mask and the sphere (radius <= 0: none) with its velocity; solid cells lose their smoke
/// and heat. Sets *changed (device) to 1 when a cell's kind changed.
void placeSolids(const GridView& g, const std::uint8_t* staticSolid, double cx, double cy, double cz, double radius,
                 float vx, float vy, float vz, int* changed);
/// VortexParticles::advance on `count` particles (6 doubles each) in place; keep[n] = 0 for those to remove.
void advanceParticles(const GridView& g, double* particles, int count, double dt, int* keep);
/// The grid's vorticity at `count` places (3 doubles each) into particles (6 doubles each); keep[n] = 0 where the
/// place is not in a fluid cell.
void seedParticles(const GridView& g, const double* places, int count, double* particles, int* keep);

// ---- the projection (ProjectionKernels.cu)
/// Faces of solids and of the domain's walls take the solid's normal velocity (applySolidBoundaries); without
/// any solid or vent cell (`anySolid` false) only the walls' faces are visited, as the CPU's.
void applySolidBoundaries(const GridView& g, bool anySolid);
/// The largest |div u - sink| over the cells (1/s; NaN counts as +infinity; `scratch`: a double on the device).
double largestDivergenceLeft(const GridView& g, const float* sink, double* scratch);

// ---- the Poisson operator and its multigrid levels (ProjectionKernels.cu)
/// A level's cell code: 0 outside the fluid; in it kFluidCode plus the diagonal (its faces towards fluid, a vent or
/// an open domain face, 0 ... 6): one byte, one load, for the operator, the smoother and the transfers.
inline constexpr std::uint8_t kFluidCode = 8;
__host__ __device__ inline int diagonalOf(std::uint8_t code)
{
    return code & 7;
}

/// A multigrid level: its shape, its cell codes and where its arrays keep cell (i, j, k) (`slot`). The finest
/// level keeps its cells by colour (`byColour`: the red ones, i + j + k even, first, then the black; row by row,
/// (nx + 1) / 2 slots a row), so that a red-black half pass reads the other colour's x and writes its own in whole
/// sectors, where the x-fastest order would read and write every other float; the coarser levels x fastest.
/// Arrays over a level have slots() entries; a slot that holds no cell (odd nx) stays 0.
struct LevelView
{
    int nx, ny, nz;
    const std::uint8_t* code;
    bool byColour;
    __host__ __device__ std::size_t cells() const { return std::size_t(nx) * ny * nz; }
    __host__ __device__ unsigned half() const { return unsigned(nx + 1) / 2; }
    __host__ __device__ unsigned colourSlots() const { return half() * unsigned(ny) * unsigned(nz); }
    __host__ __device__ std::size_t slots() const { return byColour ? 2 * std::size_t(colourSlots()) : cells(); }
    __host__ __device__ unsigned slot(int i, int j, int k) const
    {
        if (!byColour)
            return unsigned(i) + unsigned(nx) * (unsigned(j) + unsigned(ny) * unsigned(k));
        return unsigned((i + j + k) & 1) * colourSlots() + unsigned(i >> 1) + half() * (unsigned(j) + unsigned(ny) * unsigned(k));
    }
};
/// b = -h^2 (div u - sink) on the fluid cells (0 elsewhere); the first guess psi = start.current psi +
/// start.previous previous on the fluid cells, 0 elsewhere, and previous = the psi it had (b, psi, previous and the
/// flags in the finest level's slots; sink x fastest).
void projectionRightSide(const GridView& g, const LevelView& finest, const std::uint8_t* fluid, const float* sink, float* b,
                         sim::smoke::PressureWarmStart::Weights start, float* psi, float* previous);
/// u -= grad psi / h on the faces between fluid cells and between fluid and the ambient (open faces, vents); psi in
/// the finest level's slots.
void correctVelocity(const GridView& g, const LevelView& finest, const float* psi);
/// fluid and ambient (vent) flags of the finest level (in its slots) from the solid kinds.
void finestFlags(const GridView& g, const LevelView& finest, std::uint8_t* fluid, std::uint8_t* ambient);
/// A coarse level's flags from the fine one's (fluid when a child is; ambient when none is fluid and one is).
void coarsenFlags(const LevelView& fine, const std::uint8_t* fineFluid, const std::uint8_t* fineAmbient,
                  const LevelView& coarse, std::uint8_t* fluid, std::uint8_t* ambient);
/// The level's cell codes (kFluidCode | the diagonal on the fluid cells, else 0).
void levelCodes(const LevelView& level, const std::uint8_t* fluid, const std::uint8_t* ambient, const std::uint8_t open[6],
                std::uint8_t* code);
/// r = b - A x on the level.
void residualOf(const LevelView& level, const float* b, const float* x, float* r);
/// One red-black pass pair: colour `colourFirst`, then the other.
void smoothLevel(const LevelView& level, float* x, const float* b, int colourFirst);
/// smoothLevel from x = 0, without reading x (x's previous values are not used).
void smoothLevelFromZero(const LevelView& level, float* x, const float* b, int colourFirst);
/// The coarsest level: `sweeps` pass pairs from colour 0, then `sweeps` from colour 1, in one block.
void solveCoarsest(const LevelView& level, float* x, const float* b, int sweeps);
/// Whether solveBottom takes these two levels (both x fastest, small enough for one block's shared memory).
bool bottomFits(const LevelView& upper, const LevelView& coarsest);
/// The V-cycle from `upper` down (upper, then the coarsest below it) in one block: x = the cycle's result for the
/// right side rhs, as smoothing `sweeps` pairs, the coarse correction by `coarsestSweeps` pairs each way, smoothing.
void solveBottom(const LevelView& upper, const LevelView& coarsest, const float* rhs, float* x, int sweeps, int coarsestSweeps);
/// coarse.b = half the sum over each coarse cell's fluid children of the residual b - A x.
void restrictResidual(const LevelView& fine, const float* b, const float* x, const LevelView& coarse, float* coarseB);
/// x += the parent's correction on the fluid cells.
void prolongCorrection(const LevelView& fine, float* x, const LevelView& coarse, const float* coarseX);
/// x -= mean on the fluid cells.
void subtractOnFluid(const LevelView& level, float* x, float mean);
/// psi += alpha p; r -= alpha q; returns the new r's squared norm (`scratch`: 2 doubles on the device).
double updateSolution(std::size_t n, float alpha, const float* p, const float* q, float* psi, float* r, double* scratch);
/// y = A x on the level; returns x . y (`partials`: a double for each block of its launch, partialCount;
/// `scratch`: 2 doubles on the device). Each block writes its sum, and few blocks add those up: one atomic
/// addition per block to one double would queue 65,536 of them at 256^3.
double applyLevelDot(const LevelView& level, const float* x, float* y, double* partials, double* scratch);
/// The blocks of applyLevelDot's launch over the level: the partial sums it needs.
std::size_t partialCount(const LevelView& level);
/// p = z + beta p.
void updateDirection(std::size_t n, float beta, const float* z, float* p);

// ---- reductions (ReductionKernels.cu): each returns its value to the host (one small copy)
/// The blocks of a grid-stride reduction over n values (at most 1,024: few atomic additions).
unsigned reduceBlocks(std::size_t n);
/// The sum of `count` partial sums on the device, through scratch[0].
double sumPartials(const double* partials, unsigned count, double* scratch);
/// The double at `scratch` on the device, copied to the host.
double fetchScalar(const double* scratch);
double dot(const float* a, const float* b, std::size_t n, double* scratch);
/// Sum and count of x over the fluid cells.
void sumOnFluid(const float* x, const std::uint8_t* fluid, std::size_t n, double* scratch, double& sum, double& count);
/// The largest |u|, |v| and |w| of the grid's faces, each (NaN counts as +infinity), in one launch
/// (`scratch`: 3 doubles on the device).
void faceSpeeds(const GridView& g, double* scratch, double largest[3]);
/// The number of values that are not finite over the grid's velocity, smoke and temperature.
double countNotFinite(const GridView& g, double* scratch);

} // namespace vsim::cuda::smoke
