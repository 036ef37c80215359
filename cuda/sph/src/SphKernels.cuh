#pragma once

// The kernels of the GPU SPH step (CudaSph.h), each the CPU loop of the same name in modules/sim/sph
// (SphRates.cpp, SphSolver.cpp), in single precision. Layout: packed arrays (SphArrays) in the cell-sorted
// order, positions (m) relative to the domain box's low corner; one thread per particle; a neighbour loop
// scans the cells within the support around the particle's cell (cellStart / cellEnd: the sorted run of each
// cell, both 0 when it is empty).

#include <cstddef>
#include <cstdint>

namespace vsim::cuda::sph {

/// Everything a kernel needs besides the arrays (SI).
struct SphParams
{
    float h, invH, wNorm, gradNorm; ///< h (m), 1 / h; 315 / (208 pi h^3) (1/m^3); wNorm / h^2 (1/m^5)
    float support2, eta2;           ///< (2h)^2, 0.001 h^2 (m^2)
    float diffusion;                ///< delta h c0 (m^2/s); 0: no delta-SPH term
    float shifting;                 ///< A h of the particle shift (m; SphRates.h); 0: no shifting
    float shiftingReciprocalWeight; ///< 1 / W(spacing), m^3
    float shiftingSpeed;            ///< m/s: the shift's speed floor (FluidModel::shiftingSpeedMS)
    float antiClumping;             ///< R of the anti-clumping term (FluidModel::kAntiClumping)
    float soundSpeed, gamma;
    float restDensity, gasDensity, viscosity, gasViscosity; ///< rho_p, rho_g (kg/m^3), mu_p, mu_g (Pa s)
    float gravity[3];    ///< m/s^2: what the walls' pressure extrapolation uses
    float pressureFloor; ///< Pa: 0 with a free surface, -inf in vessels
    int tension; ///< FluidModel::tension: 0 holds the density at or above the rest density and the pressure at 0
    float cell;          ///< the cell's edge (m, = h)
    int dims[3];         ///< cells per axis
    int tile;            ///< rows of cells (y, z) are numbered in tiles of tile x tile rows (rowOf)
    int tilesY;          ///< tiles along y: ceil(dims[1] / tile)
    float boxHigh[3];    ///< m from the low corner: beyond it (or below 0) a particle has escaped
    float betaMax;       ///< the no-slip extrapolation's cap (SphRates.cpp)
    float repulsion, repulsionRange, repulsionPlateau; ///< the walls' backstop D (m^2/s^2; 0: off), r0 (m),
                                                       ///< r' / r0 (FluidModel.h)
    unsigned removedKey; ///< the cell key of a removed particle: past every cell's
    /// 1: a_i += (s_i . grad) v_i (FluidModel::shiftCorrection). Last, so that no field the other kernels read
    /// moved: placed after antiClumping it left their PTX the same but for the offsets, and the dam break measured
    /// 3.45e8 particle-steps/s against 3.59e8 (RESULTS.md, 2026-12-02); here their PTX is the measured build's.
    int shiftCorrection;
    /// 1: the Finite Particle Method's density rate and density gradient (FluidModel::finiteParticleMethod;
    /// launchFpm). After shiftCorrection for the same reason.
    int fpm;
    /// 1: density by summation (FluidModel::densitySummation; launchSummationDensity), each fluid particle's
    /// m_i sum_j W_ij times summationScale, and no density rate. After fpm for the same reason.
    int summation;
    float summationScale;
    /// 1 / tau of the continuity density's relaxation towards summation (FluidModel::densityRelaxationS; 1/s;
    /// 0: off).
    float relaxationRate;
};

/// The number of the row of cells (y, z): rows are numbered tile by tile (tile x tile rows, y fastest
/// within a tile, then the tiles along y, then along z), so that the rows a neighbour loop reads lie close
/// together in the sorted order, and those of the next rows too (the L2 cache keeps them); a cell's key is
/// x + dims[0] x its row, so the cells along x of one row stay consecutive.
__device__ inline unsigned rowOf(const SphParams& p, int y, int z)
{
    const unsigned t = unsigned(p.tile);
    const unsigned tileIndex = unsigned(z) / t * unsigned(p.tilesY) + unsigned(y) / t;
    return (tileIndex * t + unsigned(z) % t) * t + unsigned(y) % t;
}

/// Device pointers of the particle arrays in sorted order, packed so that a neighbour costs few 16-byte
/// loads: position (m) with w = the wall depth (m, >= 0) at a wall particle of known depth, -2 at one
/// without, -1 in the fluid and the open boundaries' buffers; velocity (m/s) with w = k + 1 at a particle in
/// the buffer of open boundary k, 0 in the fluid, at a wall particle with the backstop its guard depth (m, >= 0;
/// ParticleState::guardDepth, 0 where unknown) and kWallWithoutBackstop at one without; state = (density kg/m^3,
/// mass kg, void fraction, pressure Pa).
/// The position record's w besides a wall depth (>= 0); kRemoved at a particle an open boundary let out this
/// step (its key sorts it past the kept ones, and the step drops it).
constexpr float kFluid = -1.0f, kWallOfUnknownDepth = -2.0f, kRemoved = -3.0f;
constexpr float kWallWithoutBackstop = -1.0f;

struct SphArrays
{
    float4 *position, *velocity, *state;
    int* id;
};

/// Device pointers of the rates and the per-step work arrays.
struct SphRatesArrays
{
    float4* acceleration;
    float4* densityGradient; ///< (G_i kg/m^4, mu_i Pa s): the viscosity rides along, the rates read both per
                             ///< neighbour
    float4* derived; ///< (V_i = m_i / rho_i, m_i p_i / rho_i^2, m_i, rho_i / rho0_i), made with the pressures
    float *densityRate, *wallDistance;
    float4* shiftVelocity; ///< s_i (m/s) where particle shifting is on (SphRates.h)
    float* guardedWallDistance; ///< over the walls with the backstop where negative (infinite elsewhere): the
                                ///< through-the-wall guard's (SphRates.h)
    float* velocityDivergence;  ///< tr(grad v_i) by FPM (1/s; NaN where its system is singular); null without FPM
};

/// Maxima over a step (non-negative floats as their bit patterns, so that atomicMax on unsigned orders them),
/// flags.
struct SphReductions
{
    unsigned largestAcceleration, largestViscousRate, largestKinematicViscosity;
    /// The largest density variation over the fluid and where: its float bits in the upper 32 bits, the particle's
    /// index in the sorted order in the lower (atomicMax orders them by the variation first).
    unsigned long long largestDensityVariation;
    unsigned escaped, notFinite, throughWall;
    int escapedId, notFiniteId, throughWallId;
    int throughWallIndex; ///< the particle's index in the sorted order (its position and wall distance, read back)
};

/// Each particle's cell key (and the identity order for the sort), the fluid particles counted per cell
/// (cellFluid, zeroed by the caller), escapes flagged.
void launchCellKeys(const SphParams& p, const SphArrays& a, int n, unsigned* keys, int* order,
                    unsigned* cellFluid, SphReductions* r);
void launchGather(const SphArrays& from, const SphArrays& to, const int* order, int n);
void launchCellRanges(const unsigned* sortedKeys, int n, unsigned* cellStart, unsigned* cellEnd);
/// The particles' indices by kind, each list in the sorted order: fluid, buffers of the open boundaries, walls
/// (`counts` receives the fluid and the buffer counts; the walls are the rest): the passes that run over one kind
/// launch a thread (or a warp) per particle of it, so that no warp idles on another kind.
std::size_t partitionScratchBytes(int n);
void launchPartition(const SphArrays& a, int n, int* fluid, int* buffers, int* walls, int* counts, void* scratch,
                     std::size_t scratchBytes);
/// The walls' pressure (the `count` wall indices), and their rates zeroed (G's w: their viscosity).
void launchWallPressure(const SphParams& p, const SphArrays& a, const SphRatesArrays& rates,
                        const unsigned* cellStart, const unsigned* cellEnd, const unsigned* cellFluid,
                        const int* walls, int count);
/// Density by summation (SphRates.h, summationDensity): the `count` fluid particles' densities from their
/// neighbours' positions.
void launchSummationDensity(const SphParams& p, const SphArrays& a, const unsigned* cellStart,
                            const unsigned* cellEnd, const int* fluid, int count);
/// Every particle's pressure (state.w) and its derived record.
void launchPressures(const SphParams& p, const SphArrays& a, const SphRatesArrays& rates, int n);
void launchNeighbourhood(const SphParams& p, const SphArrays& a, const SphRatesArrays& rates,
                         const unsigned* cellStart, const unsigned* cellEnd, const int* fluid, int count);
/// With the Finite Particle Method (SphRates.h, after launchNeighbourhood, which then leaves G at 0): each fluid
/// particle's velocity divergence from the FPM system over itself and every neighbour, and G from the FPM system of
/// rho / rho0 over itself and its neighbours that are not walls (where that system is regular and the delta-SPH
/// term is on). Each system in units of h (test functions W and h grad W, offsets (x_j - x_i) / h), so that its
/// entries are of one order in single precision.
void launchFpm(const SphParams& p, const SphArrays& a, const SphRatesArrays& rates, const unsigned* cellStart,
               const unsigned* cellEnd, const int* fluid, int count);
void launchRates(const SphParams& p, const SphArrays& a, const SphRatesArrays& rates,
                 const unsigned* cellStart, const unsigned* cellEnd, const float external[3],
                 const int* fluid, int count, SphReductions* r);
void launchKickDrift(const SphParams& p, const SphArrays& a, const SphRatesArrays& rates, float dt, int n);
/// The second kick, then the guards: finite values, the density variation, through the wall (wallDistance
/// below -throughWallM).
void launchKick(const SphParams& p, const SphArrays& a, const SphRatesArrays& rates, float dt,
                float throughWallM, int n, SphReductions* r);

/// The open boundaries (OpenBoundary.h) as the kernels see them, at most kMaxOpenBoundaries.
constexpr int kMaxOpenBoundaries = 32;
struct OpenBoundaryParams
{
    float centre[3]; ///< m from the box's corner
    float normal[3]; ///< unit, into the domain
    float radius, equivalentRadius; ///< the disk's; R_k of the parabolic profile (m)
    int velocityPrescribed, parabolic;
    int joins;        ///< a fluid particle leaving through it joins its buffer (else it leaves the domain)
    float speedScale; ///< this step's Q(t) / C_k (m/s): velocity prescribed
    float pressure;   ///< this step's prescribed pressure (Pa): pressure prescribed
};
struct OpenBoundaryArgs
{
    int count = 0;
    float depth = 0.0f; ///< the buffers' depth (m)
    int capacity = 0;   ///< particles the arrays hold
    OpenBoundaryParams b[kMaxOpenBoundaries];
};
/// What the exchange and the imposition count in a step (zeroed by the caller each step).
struct OpenBoundaryTallies
{
    double inflowKg[kMaxOpenBoundaries], outflowKg[kMaxOpenBoundaries];
    double flux[kMaxOpenBoundaries];        ///< sum V v . n / depth over the buffer (m^3/s into the domain)
    double pressureSum[kMaxOpenBoundaries]; ///< Pa, over its members
    double members[kMaxOpenBoundaries];
    unsigned created, removed, overflow;
};

/// The exchange after the drift (OpenBoundaries::exchange): a buffer particle that crossed into the domain
/// becomes fluid and a copy of it, numbered firstId + its slot, is appended at n + slot a depth behind; one
/// past the buffer's far end is removed; a fluid particle that left through a disk joins that buffer or is
/// removed. Copies beyond the capacity set `overflow`.
void launchExchange(const SphArrays& a, const OpenBoundaryArgs& boundaries, int n, int firstId,
                    OpenBoundaryTallies* tallies);
/// The buffers' values (OpenBoundaries::impose) for the `count` buffer particles listed, their rates zeroed, and
/// the tallies of flux and pressure. A warp per particle: the buffers are a few thousand, too few threads to
/// hide the neighbour loop's latency one each (0.34 ms of a 1.7 ms step on the stenosis pipe, 2026-12-03).
void launchImpose(const SphParams& p, const SphArrays& a, const SphRatesArrays& rates,
                  const OpenBoundaryArgs& boundaries, const unsigned* cellStart, const unsigned* cellEnd,
                  const int* buffers, int count, OpenBoundaryTallies* tallies);

} // namespace vsim::cuda::sph
