// SmokeForces.cpp, the sources, the solids and VortexParticles.cpp on the device.

#include "SmokeKernels.cuh"

#include "vsim/cuda_common/CudaCheck.h"

namespace vsim::cuda::smoke {
namespace {

/// |centre of cell (i, j, k) - (cx, cy, cz)| in metres, in double precision as on the CPU.
__device__ double distanceToCentre(const GridView& g, int i, int j, int k, double cx, double cy, double cz)
{
    const double dx = g.ox + g.h * (i + 0.5) - cx, dy = g.oy + g.h * (j + 0.5) - cy, dz = g.oz + g.h * (k + 0.5) - cz;
    return sqrt(dx * dx + dy * dy + dz * dz);
}

__global__ void sourceKernel(GridView g, int3 lo, int3 extent, double cx, double cy, double cz, double radius,
                             float densityAdded, float temperature, float vx, float vy, float vz, bool setVelocity)
{
    const int t = int(blockIdx.x * blockDim.x + threadIdx.x);
    if (t >= extent.x * extent.y * extent.z)
        return;
    const int i = lo.x + t % extent.x, j = lo.y + (t / extent.x) % extent.y, k = lo.z + t / (extent.x * extent.y);
    const std::size_t c = g.cell(i, j, k);
    if (g.solid[c] || distanceToCentre(g, i, j, k, cx, cy, cz) > radius)
        return;
    if (setVelocity)
    {
        // Neighbouring source cells write the same value to the face they share.
        const std::size_t row = std::size_t(g.nx + 1);
        g.u[std::size_t(i) + row * (j + std::size_t(g.ny) * k)] = vx;
        g.u[std::size_t(i + 1) + row * (j + std::size_t(g.ny) * k)] = vx;
        g.v[std::size_t(i) + std::size_t(g.nx) * (j + std::size_t(g.ny + 1) * k)] = vy;
        g.v[std::size_t(i) + std::size_t(g.nx) * (j + 1 + std::size_t(g.ny + 1) * k)] = vy;
        g.w[c] = vz;
        g.w[c + std::size_t(g.nx) * g.ny] = vz;
        return;
    }
    g.density[c] += densityAdded;
    g.temperature[c] = fmaxf(g.temperature[c], temperature);
}

__global__ void coolKernel(GridView g, float keep)
{
    const std::size_t c = blockIdx.x * std::size_t(blockDim.x) + threadIdx.x;
    if (c < g.cells())
        g.temperature[c] *= keep;
}

/// Buoyancy on the faces of `axis` between two cells that are not solid (addBuoyancy).
__global__ void buoyancyKernel(GridView g, int axis, double scale, double alpha, double beta)
{
    const LatticeShape shape = latticeOf(g, axis);
    int i, j, k;
    if (!threadNode(shape.sx, shape.sy, shape.sz, i, j, k))
        return;
    const unsigned f = nodeIndex(i, j, k, shape.sx, shape.sy);
    const int at = axis == 0 ? i : axis == 1 ? j : k, n = axis == 0 ? g.nx : axis == 1 ? g.ny : g.nz;
    if (at == 0 || at == n)
        return;
    const std::size_t above = g.cell(i, j, k), below = g.cell(i - (axis == 0), j - (axis == 1), k - (axis == 2));
    if (g.solid[below] || g.solid[above])
        return;
    const double t = 0.5 * (double(g.temperature[below]) + double(g.temperature[above]));
    const double rho = 0.5 * (double(g.density[below]) + double(g.density[above]));
    float* face = axis == 0 ? g.u : axis == 1 ? g.v : g.w;
    face[f] += float(scale * (beta * t - alpha * rho));
}

/// The velocity at cell (i, j, k)'s centre: the means of its opposite faces (32-bit indices: the backend refuses
/// grids of 2^31 faces or more).
__device__ float3 centreVelocity(const GridView& g, int i, int j, int k)
{
    const unsigned c = nodeIndex(i, j, k, g.nx, g.ny), slab = unsigned(g.nx) * unsigned(g.ny);
    const unsigned uFace = nodeIndex(i, j, k, g.nx + 1, g.ny), vFace = nodeIndex(i, j, k, g.nx, g.ny + 1);
    const float u0 = __ldg(g.u + uFace), u1 = __ldg(g.u + uFace + 1);
    const float v0 = __ldg(g.v + vFace), v1 = __ldg(g.v + vFace + unsigned(g.nx));
    const float w0 = __ldg(g.w + c), w1 = __ldg(g.w + c + slab);
    return make_float3(0.5f * (u0 + u1), 0.5f * (v0 + v1), 0.5f * (w0 + w1));
}

/// cellVorticity: central differences of the cell velocities (one-sided at the domain's edge), 0 in solids;
/// and its magnitude.
__global__ void vorticityKernel(GridView g, float* omega, float* magnitude)
{
    int i, j, k;
    if (!threadNode(g.nx, g.ny, g.nz, i, j, k))
        return;
    const unsigned c = nodeIndex(i, j, k, g.nx, g.ny);
    float3 w = make_float3(0.0f, 0.0f, 0.0f);
    if (!g.solid[c])
    {
        const float inverse = float(1.0 / g.h);
        float3 d[3];
        const int at[3] = {i, j, k}, n[3] = {g.nx, g.ny, g.nz};
#pragma unroll
        for (int a = 0; a < 3; ++a)
        {
            const int lo = at[a] > 0 ? at[a] - 1 : at[a], hi = at[a] + 1 < n[a] ? at[a] + 1 : at[a];
            const int span = (at[a] > 0) + (at[a] + 1 < n[a]);
            if (!span)
            {
                d[a] = make_float3(0.0f, 0.0f, 0.0f);
                continue;
            }
            const float3 high = centreVelocity(g, a == 0 ? hi : i, a == 1 ? hi : j, a == 2 ? hi : k);
            const float3 low = centreVelocity(g, a == 0 ? lo : i, a == 1 ? lo : j, a == 2 ? lo : k);
            const float scale = inverse / float(span);
            d[a] = make_float3((high.x - low.x) * scale, (high.y - low.y) * scale, (high.z - low.z) * scale);
        }
        w = make_float3(d[1].z - d[2].y, d[2].x - d[0].z, d[0].y - d[1].x);
    }
    float* cellOmega = omega + 3 * std::size_t(c);
    cellOmega[0] = w.x, cellOmega[1] = w.y, cellOmega[2] = w.z;
    magnitude[c] = sqrtf(w.x * w.x + w.y * w.y + w.z * w.z);
}

/// f = epsilon h (N x w), N the unit gradient of |w|, at the fluid cells off the domain's edge.
__global__ void confinementKernel(GridView g, float strength, const float* omega, const float* magnitude, float* force)
{
    int i, j, k;
    if (!threadNode(g.nx, g.ny, g.nz, i, j, k))
        return;
    const std::size_t c = nodeIndex(i, j, k, g.nx, g.ny);
    force[3 * c] = force[3 * c + 1] = force[3 * c + 2] = 0.0f;
    if (i < 1 || j < 1 || k < 1 || i > g.nx - 2 || j > g.ny - 2 || k > g.nz - 2 || g.solid[c])
        return;
    const std::size_t row = std::size_t(g.nx), slab = row * g.ny;
    const float gx = magnitude[c + 1] - magnitude[c - 1], gy = magnitude[c + row] - magnitude[c - row],
                gz = magnitude[c + slab] - magnitude[c - slab];
    const float length = sqrtf(gx * gx + gy * gy + gz * gz);
    if (length <= 1e-12f)
        return;
    const float nx = gx / length, ny = gy / length, nz = gz / length;
    const float wx = omega[3 * c], wy = omega[3 * c + 1], wz = omega[3 * c + 2];
    force[3 * c] = strength * (ny * wz - nz * wy);
    force[3 * c + 1] = strength * (nz * wx - nx * wz);
    force[3 * c + 2] = strength * (nx * wy - ny * wx);
}

/// One block per particle: its clamped Gaussian forcing on the cells within the radius (VortexParticles.cpp).
__global__ void particleForcingKernel(GridView g, const double* particles, double strength, double radius, int reach,
                                      float* force)
{
    const double* particle = particles + 6 * std::size_t(blockIdx.x);
    const double x = particle[0], y = particle[1], z = particle[2];
    const double px = (x - g.ox) / g.h - 0.5, py = (y - g.oy) / g.h - 0.5, pz = (z - g.oz) / g.h - 0.5;
    const int ci = int(llround(px)), cj = int(llround(py)), ck = int(llround(pz));
    const int side = 2 * reach + 1, count = side * side * side;
    for (int t = int(threadIdx.x); t < count; t += int(blockDim.x))
    {
        const int i = ci - reach + t % side, j = cj - reach + (t / side) % side, k = ck - reach + t / (side * side);
        if (i < 0 || j < 0 || k < 0 || i >= g.nx || j >= g.ny || k >= g.nz)
            continue;
        const std::size_t c = g.cell(i, j, k);
        if (g.solid[c] == kSolid)
            continue;
        const double tx = x - (g.ox + g.h * (i + 0.5)), ty = y - (g.oy + g.h * (j + 0.5)), tz = z - (g.oz + g.h * (k + 0.5));
        const double distance = sqrt(tx * tx + ty * ty + tz * tz);
        if (distance > radius || distance < 1e-9 * g.h)
            continue;
        const double weight = exp(-distance * distance / (2.0 * radius * radius));
        const double wx = weight * particle[3], wy = weight * particle[4], wz = weight * particle[5];
        const double nx = tx / distance, ny = ty / distance, nz = tz / distance;
        atomicAdd(force + 3 * c, float(strength * (ny * wz - nz * wy)));
        atomicAdd(force + 3 * c + 1, float(strength * (nz * wx - nx * wz)));
        atomicAdd(force + 3 * c + 2, float(strength * (nx * wy - ny * wx)));
    }
}

/// Each cell adds half its force and half its upper neighbour's to the face between them (addCellForces).
__global__ void cellForcesKernel(GridView g, const float* force, float dt)
{
    int i, j, k;
    if (!threadNode(g.nx, g.ny, g.nz, i, j, k))
        return;
    const std::size_t c = nodeIndex(i, j, k, g.nx, g.ny);
    if (g.solid[c] == kSolid)
        return;
    const std::size_t row = std::size_t(g.nx), slab = row * g.ny;
    if (i + 1 < g.nx && g.solid[c + 1] != kSolid)
        g.u[std::size_t(i + 1) + std::size_t(g.nx + 1) * (j + std::size_t(g.ny) * k)] += 0.5f * dt * (force[3 * c] + force[3 * (c + 1)]);
    if (j + 1 < g.ny && g.solid[c + row] != kSolid)
        g.v[std::size_t(i) + std::size_t(g.nx) * (j + 1 + std::size_t(g.ny + 1) * k)] += 0.5f * dt * (force[3 * c + 1] + force[3 * (c + row) + 1]);
    if (k + 1 < g.nz && g.solid[c + slab] != kSolid)
        g.w[c + slab] += 0.5f * dt * (force[3 * c + 2] + force[3 * (c + slab) + 2]);
}

__global__ void solidsKernel(GridView g, const std::uint8_t* staticSolid, double cx, double cy, double cz, double radius,
                             float vx, float vy, float vz, int* changed)
{
    int i, j, k;
    if (!threadNode(g.nx, g.ny, g.nz, i, j, k))
        return;
    const std::size_t c = nodeIndex(i, j, k, g.nx, g.ny);
    std::uint8_t kind = staticSolid[c];
    float3 velocity = make_float3(0.0f, 0.0f, 0.0f);
    if (radius > 0.0 && distanceToCentre(g, i, j, k, cx, cy, cz) <= radius)
        kind = kSolid, velocity = make_float3(vx, vy, vz);
    if (kind != g.solid[c])
        *changed = 1;
    g.solid[c] = kind;
    g.solidVelocity[3 * c] = velocity.x, g.solidVelocity[3 * c + 1] = velocity.y, g.solidVelocity[3 * c + 2] = velocity.z;
    if (kind)
        g.density[c] = g.temperature[c] = 0.0f;
}

/// The grid's vorticity at x (m): central differences of the interpolated velocity h / 2 apart; and the
/// stretching (w . grad) u of vorticity `w` there.
__device__ void vorticityAndStretch(const GridView& g, double3 x, const double* w, double3& omega, double3& stretch)
{
    const double delta = 0.5 * g.h;
    double3 d[3];
    stretch = make_double3(0.0, 0.0, 0.0);
#pragma unroll
    for (int a = 0; a < 3; ++a)
    {
        const double3 plus = velocityAt(g, make_double3(x.x + (a == 0) * delta, x.y + (a == 1) * delta, x.z + (a == 2) * delta));
        const double3 minus = velocityAt(g, make_double3(x.x - (a == 0) * delta, x.y - (a == 1) * delta, x.z - (a == 2) * delta));
        d[a] = make_double3((plus.x - minus.x) / (2.0 * delta), (plus.y - minus.y) / (2.0 * delta), (plus.z - minus.z) / (2.0 * delta));
        if (w)
            stretch.x += w[a] * d[a].x, stretch.y += w[a] * d[a].y, stretch.z += w[a] * d[a].z;
    }
    omega = make_double3(d[1].z - d[2].y, d[2].x - d[0].z, d[0].y - d[1].x);
}

__global__ void advanceParticlesKernel(GridView g, double* particles, int count, double dt, int* keep)
{
    const int n = int(blockIdx.x * blockDim.x + threadIdx.x);
    if (n >= count)
        return;
    double* p = particles + 6 * std::size_t(n);
    const double3 x = make_double3(p[0], p[1], p[2]);
    double3 omega, stretch;
    vorticityAndStretch(g, x, p + 3, omega, stretch);
    p[3] = omega.x + dt * stretch.x, p[4] = omega.y + dt * stretch.y, p[5] = omega.z + dt * stretch.z;
    const double3 u0 = velocityAt(g, x);
    const double3 middle = make_double3(x.x + 0.5 * dt * u0.x, x.y + 0.5 * dt * u0.y, x.z + 0.5 * dt * u0.z);
    const double3 u1 = velocityAt(g, middle);
    p[0] = x.x + dt * u1.x, p[1] = x.y + dt * u1.y, p[2] = x.z + dt * u1.z;
    keep[n] = isfinite(p[3]) && isfinite(p[4]) && isfinite(p[5]) && insideFluid(g, make_double3(p[0], p[1], p[2]));
}

__global__ void seedParticlesKernel(GridView g, const double* places, int count, double* particles, int* keep)
{
    const int n = int(blockIdx.x * blockDim.x + threadIdx.x);
    if (n >= count)
        return;
    const double3 x = make_double3(places[3 * n], places[3 * n + 1], places[3 * n + 2]);
    keep[n] = insideFluid(g, x);
    double3 omega, stretch;
    if (keep[n])
        vorticityAndStretch(g, x, nullptr, omega, stretch);
    else
        omega = make_double3(0.0, 0.0, 0.0);
    double* p = particles + 6 * std::size_t(n);
    p[0] = x.x, p[1] = x.y, p[2] = x.z, p[3] = omega.x, p[4] = omega.y, p[5] = omega.z;
}

} // namespace

void applySource(const GridView& g, const int lo[3], const int hi[3], double cx, double cy, double cz, double radius,
                 float densityAdded, float temperature, float vx, float vy, float vz, bool setVelocity)
{
    const int3 extent = make_int3(hi[0] - lo[0] + 1, hi[1] - lo[1] + 1, hi[2] - lo[2] + 1);
    if (extent.x <= 0 || extent.y <= 0 || extent.z <= 0)
        return;
    sourceKernel<<<blocksFor(std::size_t(extent.x) * extent.y * extent.z), kBlock>>>(
        g, make_int3(lo[0], lo[1], lo[2]), extent, cx, cy, cz, radius, densityAdded, temperature, vx, vy, vz, setVelocity);
}

void addHeatForces(const GridView& g, float keep, double dt, double alpha, double beta, const double up[3])
{
    if (keep != 1.0f)
        coolKernel<<<blocksFor(g.cells()), kBlock>>>(g, keep);
    for (int axis = 0; axis < 3; ++axis)
    {
        const LatticeLaunch faces = launchOver(latticeOf(g, axis));
        if (up[axis] != 0.0)
            buoyancyKernel<<<faces.blocks, faces.threads>>>(g, axis, dt * up[axis], alpha, beta);
    }
}

void vorticityConfinement(const GridView& g, double epsilon, float* force, float* omega, float* magnitude)
{
    if (epsilon <= 0.0)
    {
        VSIM_CUDA_CHECK(cudaMemsetAsync(force, 0, 3 * g.cells() * sizeof(float)));
        return;
    }
    const LatticeLaunch cells = launchOver(g.nx, g.ny, g.nz);
    vorticityKernel<<<cells.blocks, cells.threads>>>(g, omega, magnitude);
    confinementKernel<<<cells.blocks, cells.threads>>>(g, float(epsilon * g.h), omega, magnitude, force);
}

void particleForcing(const GridView& g, const double* particles, int count, double epsilon, double radius, float* force)
{
    if (count <= 0 || epsilon <= 0.0 || radius <= 0.0)
        return;
    const int reach = int(ceil(radius / g.h));
    particleForcingKernel<<<unsigned(count), 128>>>(g, particles, epsilon * g.h, radius, reach, force);
}

void addCellForces(const GridView& g, const float* force, float dt)
{
    const LatticeLaunch cells = launchOver(g.nx, g.ny, g.nz);
    cellForcesKernel<<<cells.blocks, cells.threads>>>(g, force, dt);
}

void placeSolids(const GridView& g, const std::uint8_t* staticSolid, double cx, double cy, double cz, double radius,
                 float vx, float vy, float vz, int* changed)
{
    const LatticeLaunch cells = launchOver(g.nx, g.ny, g.nz);
    solidsKernel<<<cells.blocks, cells.threads>>>(g, staticSolid, cx, cy, cz, radius, vx, vy, vz, changed);
}

void advanceParticles(const GridView& g, double* particles, int count, double dt, int* keep)
{
    if (count > 0)
        advanceParticlesKernel<<<blocksFor(std::size_t(count), 128), 128>>>(g, particles, count, dt, keep);
}

void seedParticles(const GridView& g, const double* places, int count, double* particles, int* keep)
{
    if (count > 0)
        seedParticlesKernel<<<blocksFor(std::size_t(count), 128), 128>>>(g, places, count, particles, keep);
}

} // namespace vsim::cuda::smoke
