#include "vsim/sim/smoke/PressureProjection.h"

#include <algorithm>
#include <cmath>

namespace vsim::sim::smoke {
namespace {

constexpr int kCgAttempts = 3;       // the first solve and up to two restarts
constexpr int kStallIterations = 10; // iterations without halving the residual: stalled

double dot(const std::vector<float>& a, const std::vector<float>& b)
{
    double sum = 0.0;
    const long n = long(a.size());
#pragma omp parallel for reduction(+ : sum) schedule(static)
    for (long c = 0; c < n; ++c)
        sum += double(a[std::size_t(c)]) * double(b[std::size_t(c)]);
    return sum;
}

} // namespace

void applySolidBoundaries(SmokeGrid& grid)
{
    const int nx = grid.nx, ny = grid.ny, nz = grid.nz;
    const auto wallAt = [&](int face) { return grid.boundaries[std::size_t(face)] == DomainBoundary::Wall; };
    if (std::none_of(grid.solid.begin(), grid.solid.end(), [](std::uint8_t s) { return s != 0; }))
    {
        // No solid cell: only the domain's walls, plane by plane.
        for (int k = 0; k < nz; ++k)
            for (int j = 0; j < ny; ++j)
            {
                if (wallAt(0))
                    grid.u[grid.uFace(0, j, k)] = 0.0f;
                if (wallAt(1))
                    grid.u[grid.uFace(nx, j, k)] = 0.0f;
            }
        for (int k = 0; k < nz; ++k)
            for (int i = 0; i < nx; ++i)
            {
                if (wallAt(2))
                    grid.v[grid.vFace(i, 0, k)] = 0.0f;
                if (wallAt(3))
                    grid.v[grid.vFace(i, ny, k)] = 0.0f;
            }
        for (int j = 0; j < ny; ++j)
            for (int i = 0; i < nx; ++i)
            {
                if (wallAt(4))
                    grid.w[grid.wFace(i, j, 0)] = 0.0f;
                if (wallAt(5))
                    grid.w[grid.wFace(i, j, nz)] = 0.0f;
            }
        return;
    }
    // A face between a solid cell and another cell takes the solid's normal velocity (two solids: their mean).
    const auto solidNormal = [&](int ia, int ja, int ka, int ib, int jb, int kb, int axis, float& face) {
        const bool a = grid.inside(ia, ja, ka) && grid.isSolid(ia, ja, ka);
        const bool b = grid.inside(ib, jb, kb) && grid.isSolid(ib, jb, kb);
        if (!a && !b)
            return;
        float sum = 0.0f;
        if (a)
            sum += grid.solidVelocity[grid.cell(ia, ja, ka)][axis];
        if (b)
            sum += grid.solidVelocity[grid.cell(ib, jb, kb)][axis];
        face = sum / float(int(a) + int(b));
    };
#pragma omp parallel for schedule(static)
    for (int k = 0; k < nz; ++k)
        for (int j = 0; j < ny; ++j)
        {
            for (int i = 0; i <= nx; ++i)
            {
                float& face = grid.u[grid.uFace(i, j, k)];
                if ((i == 0 && wallAt(0)) || (i == nx && wallAt(1)))
                    face = 0.0f;
                else
                    solidNormal(i - 1, j, k, i, j, k, 0, face);
            }
        }
#pragma omp parallel for schedule(static)
    for (int k = 0; k < nz; ++k)
        for (int j = 0; j <= ny; ++j)
            for (int i = 0; i < nx; ++i)
            {
                float& face = grid.v[grid.vFace(i, j, k)];
                if ((j == 0 && wallAt(2)) || (j == ny && wallAt(3)))
                    face = 0.0f;
                else
                    solidNormal(i, j - 1, k, i, j, k, 1, face);
            }
#pragma omp parallel for schedule(static)
    for (int k = 0; k <= nz; ++k)
        for (int j = 0; j < ny; ++j)
            for (int i = 0; i < nx; ++i)
            {
                float& face = grid.w[grid.wFace(i, j, k)];
                if ((k == 0 && wallAt(4)) || (k == nz && wallAt(5)))
                    face = 0.0f;
                else
                    solidNormal(i, j, k - 1, i, j, k, 2, face);
            }
}

std::vector<float> divergence(const SmokeGrid& grid)
{
    std::vector<float> div(grid.cells(), 0.0f);
    const float inverse = float(1.0 / grid.h);
#pragma omp parallel for schedule(static)
    for (int k = 0; k < grid.nz; ++k)
        for (int j = 0; j < grid.ny; ++j)
            for (int i = 0; i < grid.nx; ++i)
            {
                const std::size_t c = grid.cell(i, j, k);
                if (grid.solid[c])
                    continue;
                div[c] = inverse * (grid.u[grid.uFace(i + 1, j, k)] - grid.u[grid.uFace(i, j, k)] +
                                    grid.v[grid.vFace(i, j + 1, k)] - grid.v[grid.vFace(i, j, k)] +
                                    grid.w[grid.wFace(i, j, k + 1)] - grid.w[grid.wFace(i, j, k)]);
            }
    return div;
}

void PressureProjection::prepare(const SmokeGrid& grid)
{
    m_multigrid.prepare(grid);
    m_sides.resize(grid.cells());
    for (std::size_t c = 0; c < grid.cells(); ++c)
        m_sides[c] = grid.solid[c] == kFluid ? 1 : grid.solid[c] == kVent ? 2 : 0;
    for (std::vector<float>* work : {&m_psi, &m_previousPsi, &m_b, &m_r, &m_z, &m_p, &m_q})
        work->resize(grid.cells(), 0.0f); // psi and its history kept (a moving ball changes the solids every few steps)
}

ProjectionReport PressureProjection::project(SmokeGrid& grid, double tolerance, int maxIterations,
                                             const std::vector<float>* sourceDivergence, double stepS)
{
    if (m_psi.size() != grid.cells())
        prepare(grid);
    applySolidBoundaries(grid);
    ProjectionReport report;
    // The first guess from the last two psi; 0 outside the fluid, where the operator counts on it (a body that moved
    // leaves old values).
    const std::vector<std::uint8_t>& fluidCells = m_multigrid.fluid();
    const PressureWarmStart::Weights start = m_warmStart.weights(stepS);
    for (std::size_t c = 0; c < m_psi.size(); ++c)
    {
        const float last = fluidCells[c] ? m_psi[c] : 0.0f;
        m_psi[c] = fluidCells[c] ? start.current * last + start.previous * m_previousPsi[c] : 0.0f;
        m_previousPsi[c] = last;
    }
    // b = -h^2 div u' on the fluid cells: A psi = b makes the corrected velocity divergence-free.
    const std::vector<float> div = divergence(grid);
    const float scale = float(-grid.h * grid.h);
    for (std::size_t c = 0; c < div.size(); ++c)
        m_b[c] = scale * (div[c] - (sourceDivergence ? (*sourceDivergence)[c] : 0.0f));
    m_multigrid.removeNullSpace(m_b);
    const double bNorm = std::sqrt(dot(m_b, m_b));
    // Preconditioned conjugate gradients from the last psi. In single precision the recurrence's residual drifts
    // from the true one, so the solve can stop on a recurrence below the tolerance with the true residual above
    // it: CG then restarts from its psi with the true residual (at most twice); one that stalls (its residual not
    // halved in 10 iterations: the rounding of b - A psi for a large warm start, near 1e-7 |A psi|, can exceed a
    // nearly divergence-free flow's small b) restarts from psi = 0. All within maxIterations.
    bool stalled = false;
    for (int attempt = 0; attempt < kCgAttempts && bNorm > 0.0 && report.iterations < maxIterations; ++attempt)
    {
        if (attempt > 0 && report.relativeResidual <= tolerance)
            break;
        if (stalled)
            std::fill(m_psi.begin(), m_psi.end(), 0.0f);
        m_multigrid.apply(m_psi, m_q);
        for (std::size_t c = 0; c < m_r.size(); ++c)
            m_r[c] = m_b[c] - m_q[c];
        m_multigrid.removeNullSpace(m_r);
        double residual = std::sqrt(dot(m_r, m_r)) / bNorm;
        m_multigrid.precondition(m_r, m_z);
        m_p = m_z;
        double rz = dot(m_r, m_z);
        int iteration = 0, sinceProgress = 0;
        double best = residual;
        stalled = false;
        while (residual > tolerance && report.iterations + iteration < maxIterations && rz > 0.0)
        {
            m_multigrid.apply(m_p, m_q);
            const double pq = dot(m_p, m_q);
            if (!(pq > 0.0))
                break;
            const float alpha = float(rz / pq);
            const long n = long(m_psi.size());
            double rr = 0.0;
#pragma omp parallel for reduction(+ : rr) schedule(static)
            for (long c = 0; c < n; ++c)
            {
                m_psi[std::size_t(c)] += alpha * m_p[std::size_t(c)];
                const float next = m_r[std::size_t(c)] - alpha * m_q[std::size_t(c)];
                m_r[std::size_t(c)] = next;
                rr += double(next) * next;
            }
            ++iteration;
            residual = std::sqrt(rr) / bNorm;
            if (residual <= tolerance)
                break;
            if (residual < 0.5 * best)
                best = residual, sinceProgress = 0;
            else if (++sinceProgress >= kStallIterations)
            {
                stalled = true;
                break;
            }
            m_multigrid.precondition(m_r, m_z);
            const double rzNext = dot(m_r, m_z);
            const float beta = float(rzNext / rz);
            rz = rzNext;
#pragma omp parallel for schedule(static)
            for (long c = 0; c < n; ++c)
                m_p[std::size_t(c)] = m_z[std::size_t(c)] + beta * m_p[std::size_t(c)];
        }
        // The true residual of the final psi (the recurrence drifts in single precision).
        m_multigrid.apply(m_psi, m_q);
        for (std::size_t c = 0; c < m_r.size(); ++c)
            m_r[c] = m_b[c] - m_q[c];
        m_multigrid.removeNullSpace(m_r);
        report.iterations += iteration;
        report.relativeResidual = std::sqrt(dot(m_r, m_r)) / bNorm;
    }
    report.converged = report.relativeResidual <= tolerance;
    m_warmStart.record(stepS);

    // u = u' - grad psi on the faces between fluid cells, and between a fluid cell and the ambient (an open domain
    // face or a vent cell, psi = 0 there).
    const float inverse = float(1.0 / grid.h);
    const int nx = grid.nx, ny = grid.ny, nz = grid.nz;
    const auto open = [&](int face) { return grid.boundaries[std::size_t(face)] == DomainBoundary::Open; };
    // Each side of a face: 1 fluid (psi of the cell), 2 ambient (psi 0), 0 a wall or a solid (no correction).
    const std::uint8_t openSide[6] = {std::uint8_t(open(0) ? 2 : 0), std::uint8_t(open(1) ? 2 : 0), std::uint8_t(open(2) ? 2 : 0),
                                      std::uint8_t(open(3) ? 2 : 0), std::uint8_t(open(4) ? 2 : 0), std::uint8_t(open(5) ? 2 : 0)};
    const std::vector<std::uint8_t>& kind = m_sides;
    const auto correct = [&](float& face, std::uint8_t low, std::uint8_t high, std::size_t lowCell, std::size_t highCell) {
        if ((low == 1 && high != 0) || (high == 1 && low != 0))
            face -= inverse * ((high == 1 ? m_psi[highCell] : 0.0f) - (low == 1 ? m_psi[lowCell] : 0.0f));
    };
    const std::size_t row = std::size_t(nx), slab = std::size_t(nx) * ny;
#pragma omp parallel for schedule(static)
    for (int k = 0; k < nz; ++k)
        for (int j = 0; j < ny; ++j)
            for (int i = 0; i <= nx; ++i)
            {
                const std::size_t c = grid.cell(std::min(i, nx - 1), j, k) + (i == nx ? 1 : 0);
                correct(grid.u[grid.uFace(i, j, k)], i > 0 ? kind[c - 1] : openSide[0], i < nx ? kind[c] : openSide[1], c - (i > 0), c);
            }
#pragma omp parallel for schedule(static)
    for (int k = 0; k < nz; ++k)
        for (int j = 0; j <= ny; ++j)
            for (int i = 0; i < nx; ++i)
            {
                const std::size_t c = std::size_t(i) + row * std::size_t(j) + slab * std::size_t(k); // linear in j
                correct(grid.v[grid.vFace(i, j, k)], j > 0 ? kind[c - row] : openSide[2], j < ny ? kind[c] : openSide[3],
                        j > 0 ? c - row : c, c);
            }
#pragma omp parallel for schedule(static)
    for (int k = 0; k <= nz; ++k)
        for (int j = 0; j < ny; ++j)
            for (int i = 0; i < nx; ++i)
            {
                const std::size_t c = std::size_t(i) + row * std::size_t(j) + slab * std::size_t(k); // linear in k
                correct(grid.w[grid.wFace(i, j, k)], k > 0 ? kind[c - slab] : openSide[4], k < nz ? kind[c] : openSide[5],
                        k > 0 ? c - slab : c, c);
            }

    const std::vector<float> after = divergence(grid);
    for (std::size_t c = 0; c < after.size(); ++c)
        report.maxDivergence = std::max(report.maxDivergence,
                                        double(std::abs(after[c] - (sourceDivergence ? (*sourceDivergence)[c] : 0.0f))));
    const double speed = grid.maxSpeed();
    report.divergenceRatio = speed > 0.0 ? report.maxDivergence * grid.h / speed : 0.0;
    return report;
}

} // namespace vsim::sim::smoke
