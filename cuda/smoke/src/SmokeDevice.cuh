#pragma once

// The smoke grid in the device's memory and the device functions its kernels share. The layout is the host's
// (SmokeGrid.h): x fastest, u on (nx + 1) x ny x nz faces, v on nx x (ny + 1) x nz, w on nx x ny x (nz + 1), the
// cell fields on nx x ny x nz; the solids' velocity as three floats per cell. Positions inside kernels are in
// cells from the domain's corner; the vortex particles (a few thousand) stay in double precision, as on the CPU.

#include <cuda_runtime.h>

#include <cstdint>

namespace vsim::cuda::smoke {

inline constexpr std::uint8_t kFluid = 0, kSolid = 1, kVent = 2;
inline constexpr int kBlock = 256;

/// The grid's arrays on the device and its shape.
struct GridView
{
    int nx = 0, ny = 0, nz = 0;
    double h = 0.0;                    ///< m
    double ox = 0.0, oy = 0.0, oz = 0.0; ///< the domain's corner (m)
    std::uint8_t open[6] = {0, 0, 0, 0, 0, 0}; ///< 1: that domain face is open (x-, x+, y-, y+, z-, z+)
    float *u = nullptr, *v = nullptr, *w = nullptr, *density = nullptr, *temperature = nullptr;
    std::uint8_t* solid = nullptr;
    float* solidVelocity = nullptr;    ///< 3 per cell

    __host__ __device__ std::size_t cells() const { return std::size_t(nx) * ny * nz; }
    __host__ __device__ std::size_t cell(int i, int j, int k) const { return std::size_t(i) + std::size_t(nx) * (j + std::size_t(ny) * k); }
};

/// The shape of a lattice: sx x sy x sz nodes, node (0,0,0) `offset` cells from the domain's corner.
struct LatticeShape
{
    int sx, sy, sz;
    float ox, oy, oz;
};

/// The lattice of the u (axis 0), v (1) or w (2) faces, or of the cells (3).
__host__ __device__ inline LatticeShape latticeOf(const GridView& g, int kind)
{
    switch (kind)
    {
    case 0: return {g.nx + 1, g.ny, g.nz, 0.0f, 0.5f, 0.5f};
    case 1: return {g.nx, g.ny + 1, g.nz, 0.5f, 0.0f, 0.5f};
    case 2: return {g.nx, g.ny, g.nz + 1, 0.5f, 0.5f, 0.0f};
    default: return {g.nx, g.ny, g.nz, 0.5f, 0.5f, 0.5f};
    }
}

__host__ __device__ inline std::size_t nodes(const LatticeShape& s)
{
    return std::size_t(s.sx) * s.sy * s.sz;
}

/// Node (i, j, k)'s index on an sx x sy x ... lattice, in 32 bits (the backend refuses grids of 2^31 faces or more).
__host__ __device__ inline unsigned nodeIndex(int i, int j, int k, int sx, int sy)
{
    return unsigned(i) + unsigned(sx) * (unsigned(j) + unsigned(sy) * unsigned(k));
}

/// Trilinear sample of `data` on lattice `s` at p (cells), clamped to the lattice, as the CPU's Advection.cpp
/// (single precision); `low` / `high` take the range of the eight values when not null.
__device__ inline float sampleLattice(const float* data, const LatticeShape& s, float px, float py, float pz,
                                      float* low = nullptr, float* high = nullptr)
{
    const float fx = fminf(fmaxf(px - s.ox, 0.0f), float(s.sx - 1));
    const float fy = fminf(fmaxf(py - s.oy, 0.0f), float(s.sy - 1));
    const float fz = fminf(fmaxf(pz - s.oz, 0.0f), float(s.sz - 1));
    const int i = min(int(fx), s.sx - 2), j = min(int(fy), s.sy - 2), k = min(int(fz), s.sz - 2);
    const float a = fx - float(i), b = fy - float(j), c = fz - float(k);
    const unsigned row = unsigned(s.sx), slab = unsigned(s.sx) * unsigned(s.sy);
    const float* base = data + nodeIndex(i, j, k, s.sx, s.sy);
    // Through the read-only cache: no kernel writes the lattice it samples.
    const float v000 = __ldg(base), v100 = __ldg(base + 1), v010 = __ldg(base + row), v110 = __ldg(base + row + 1);
    const float v001 = __ldg(base + slab), v101 = __ldg(base + slab + 1), v011 = __ldg(base + slab + row);
    const float v111 = __ldg(base + slab + row + 1);
    if (low)
    {
        *low = fminf(fminf(fminf(v000, v100), fminf(v010, v110)), fminf(fminf(v001, v101), fminf(v011, v111)));
        *high = fmaxf(fmaxf(fmaxf(v000, v100), fmaxf(v010, v110)), fmaxf(fmaxf(v001, v101), fmaxf(v011, v111)));
    }
    const float c00 = v000 + a * (v100 - v000), c10 = v010 + a * (v110 - v010);
    const float c01 = v001 + a * (v101 - v001), c11 = v011 + a * (v111 - v011);
    const float c0 = c00 + b * (c10 - c00), c1 = c01 + b * (c11 - c01);
    return c0 + c * (c1 - c0);
}

/// Trilinear sample in double precision at p (cells), as SmokeGrid::sampleCells / velocityAt (the particles').
__device__ inline double sampleLatticeDouble(const float* data, const LatticeShape& s, double px, double py, double pz)
{
    const double fx = fmin(fmax(px - s.ox, 0.0), double(s.sx - 1));
    const double fy = fmin(fmax(py - s.oy, 0.0), double(s.sy - 1));
    const double fz = fmin(fmax(pz - s.oz, 0.0), double(s.sz - 1));
    const int i = min(int(fx), max(s.sx - 2, 0)), j = min(int(fy), max(s.sy - 2, 0)), k = min(int(fz), max(s.sz - 2, 0));
    const double a = fx - i, b = fy - j, c = fz - k;
    const int i1 = min(i + 1, s.sx - 1), j1 = min(j + 1, s.sy - 1), k1 = min(k + 1, s.sz - 1);
    auto at = [&](int x, int y, int z) { return double(data[std::size_t(x) + std::size_t(s.sx) * (y + std::size_t(s.sy) * z)]); };
    const double c00 = at(i, j, k) * (1 - a) + at(i1, j, k) * a, c10 = at(i, j1, k) * (1 - a) + at(i1, j1, k) * a;
    const double c01 = at(i, j, k1) * (1 - a) + at(i1, j, k1) * a, c11 = at(i, j1, k1) * (1 - a) + at(i1, j1, k1) * a;
    return (c00 * (1 - b) + c10 * b) * (1 - c) + (c01 * (1 - b) + c11 * b) * c;
}

/// The velocity at x (m), as SmokeGrid::velocityAt.
__device__ inline double3 velocityAt(const GridView& g, double3 x)
{
    const double px = (x.x - g.ox) / g.h, py = (x.y - g.oy) / g.h, pz = (x.z - g.oz) / g.h;
    return make_double3(sampleLatticeDouble(g.u, latticeOf(g, 0), px, py, pz),
                        sampleLatticeDouble(g.v, latticeOf(g, 1), px, py, pz),
                        sampleLatticeDouble(g.w, latticeOf(g, 2), px, py, pz));
}

/// 1 when x (m) lies in a fluid cell of the domain.
__device__ inline bool insideFluid(const GridView& g, double3 x)
{
    const int i = int(floor((x.x - g.ox) / g.h)), j = int(floor((x.y - g.oy) / g.h)), k = int(floor((x.z - g.oz) / g.h));
    return i >= 0 && j >= 0 && k >= 0 && i < g.nx && j < g.ny && k < g.nz && g.solid[g.cell(i, j, k)] == kFluid;
}

/// One thread per node of an sx x sy x sz lattice, in blocks of 32 x 4 x 2 threads (kBlock; a warp along a row
/// of x): each thread has its (i, j, k) from its block's place, without dividing (threadNode).
struct LatticeLaunch
{
    dim3 blocks, threads;
};

inline LatticeLaunch launchOver(int sx, int sy, int sz)
{
    return {dim3(unsigned(sx + 31) / 32, unsigned(sy + 3) / 4, unsigned(sz + 1) / 2), dim3(32, 4, 2)};
}

inline LatticeLaunch launchOver(const LatticeShape& s)
{
    return launchOver(s.sx, s.sy, s.sz);
}

/// This thread's node (i, j, k) of the lattice launched by launchOver; false past its end.
__device__ inline bool threadNode(int sx, int sy, int sz, int& i, int& j, int& k)
{
    i = int(blockIdx.x * blockDim.x + threadIdx.x), j = int(blockIdx.y * blockDim.y + threadIdx.y);
    k = int(blockIdx.z * blockDim.z + threadIdx.z);
    return i < sx && j < sy && k < sz;
}

/// The thread's place in its block, 0 ... kBlock - 1 (x fastest: a warp is 32 consecutive places).
__device__ inline unsigned threadInBlock()
{
    return threadIdx.x + blockDim.x * (threadIdx.y + blockDim.y * threadIdx.z);
}

inline unsigned blocksFor(std::size_t n, int block = kBlock)
{
    return unsigned((n + std::size_t(block) - 1) / std::size_t(block));
}

} // namespace vsim::cuda::smoke
