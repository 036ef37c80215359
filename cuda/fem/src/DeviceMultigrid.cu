#include "DeviceMultigrid.cuh"

#include <utility>

namespace vsim::cuda {

namespace {

constexpr int kThreads = 256;

int blocksFor(std::size_t count) { return int((count + kThreads - 1) / kThreads); }

/// The Chebyshev recurrence's coefficients of the further steps (AggregationMultigrid::smooth): step k takes
/// d = c1[k] d + c2[k] r.
void chebyshevCoefficients(double upper, double lower, int degree, std::vector<double>& c1, std::vector<double>& c2)
{
    const double centre = 0.5 * (upper + lower), halfWidth = 0.5 * (upper - lower), sigma = centre / halfWidth;
    double rho = 1.0 / sigma;
    c1.clear(), c2.clear();
    for (int k = 1; k < degree; ++k)
    {
        const double rhoNext = 1.0 / (2.0 * sigma - rho);
        c1.push_back(rhoNext * rho);
        c2.push_back(2.0 * rhoNext / halfWidth);
        rho = rhoNext;
    }
}

} // namespace

void DeviceMultigrid::upload(Csr& csr, const sim::fem::SparseRows& m)
{
    sim::fem::SparseRows compressed = m;
    compressed.makeCompressed();
    csr.start.upload(compressed.outerIndexPtr(), std::size_t(compressed.rows()) + 1);
    csr.columns.upload(compressed.innerIndexPtr(), std::size_t(compressed.nonZeros()));
    csr.values.upload(compressed.valuePtr(), std::size_t(compressed.nonZeros()));
    csr.view = fem::DeviceCsr{int(compressed.rows()), csr.start.data, csr.columns.data, csr.values.data};
    m_bytes += csr.start.bytes() + csr.columns.bytes() + csr.values.bytes();
}

DeviceMultigrid::DeviceMultigrid(const sim::fem::AggregationMultigrid& host)
    : m_degree(host.settings().chebyshevDegree)
{
    const auto& levels = host.levels();
    m_levels.resize(levels.size());
    for (std::size_t l = 0; l < levels.size(); ++l)
    {
        const sim::fem::MultigridLevel& h = levels[l];
        Level& d = m_levels[l];
        d.dofs = h.dofs;
        d.upper = h.largestEigenvalue;
        d.lower = h.largestEigenvalue * host.settings().chebyshevLowerFraction;
        for (Buffer<double>* v : {&d.b, &d.xA, &d.xB, &d.r, &d.dA, &d.dB, &d.w})
        {
            v->zero(std::size_t(d.dofs));
            m_bytes += v->bytes();
        }
        if (l + 1 < levels.size())
        {
            upload(d.prolongation, h.prolongation);
            upload(d.restriction, h.restriction);
        }
        if (l == 0 || l + 1 == levels.size())
            continue; // the finest takes the PCG's own inverse diagonal; the coarsest is solved
        upload(d.matrix, h.matrix);
        std::vector<int> first(std::size_t(d.dofs)), size(std::size_t(d.dofs)), row(std::size_t(d.dofs));
        for (std::size_t k = 0; k + 1 < h.blockStart.size(); ++k)
        {
            const int begin = h.blockStart[k], n = h.blockStart[k + 1] - begin;
            for (int i = 0; i < n; ++i)
                first[std::size_t(begin + i)] = begin, size[std::size_t(begin + i)] = n,
                                         row[std::size_t(begin + i)] = h.inverseStart[k] + i * n;
        }
        d.blockFirst.upload(first);
        d.blockSize.upload(size);
        d.inverseRow.upload(row);
        d.inverses.upload(h.inverseBlocks);
        d.inverse = fem::DeviceBlockInverse{d.dofs, d.blockFirst.data, d.blockSize.data, d.inverseRow.data, d.inverses.data};
        m_bytes += d.blockFirst.bytes() + d.blockSize.bytes() + d.inverseRow.bytes() + d.inverses.bytes();
    }
    const Eigen::MatrixXd inverse = host.coarsestInverse();
    std::vector<double> rowMajor(std::size_t(inverse.size()));
    for (Eigen::Index i = 0; i < inverse.rows(); ++i)
        for (Eigen::Index j = 0; j < inverse.cols(); ++j)
            rowMajor[std::size_t(i * inverse.cols() + j)] = inverse(i, j);
    m_coarsestInverse.upload(rowMajor);
    m_bytes += m_coarsestInverse.bytes();
}

void DeviceMultigrid::record(cudaStream_t stream, const fem::DeviceModel& model, const double* inverseDiagonal,
                             const double* r, double* z, fem::CycleGuard guard) const
{
    cycle(stream, 0, model, inverseDiagonal, r, z, guard);
}

void DeviceMultigrid::cycle(cudaStream_t stream, std::size_t level, const fem::DeviceModel& model,
                            const double* inverseDiagonal, const double* b, double* x, const fem::CycleGuard& g) const
{
    const Level& l = m_levels[level];
    if (level + 1 == m_levels.size())
    {
        fem::denseProductKernel<<<blocksFor(32 * std::size_t(l.dofs)), kThreads, 0, stream>>>(
            l.dofs, m_coarsestInverse.data, b, x, g);
        return;
    }
    std::vector<double> c1, c2;
    chebyshevCoefficients(l.upper, l.lower, m_degree, c1, c2);
    const double inverseCentre = 2.0 / (l.upper + l.lower);
    const Level& next = m_levels[level + 1];
    const bool finest = level == 0;
    const int rowGrid = blocksFor(std::size_t(model.nodes) * fem::kRowLanes), nodeGrid = blocksFor(std::size_t(model.nodes));
    const int csrGrid = blocksFor(std::size_t(l.dofs) * fem::kCsrLanes), dofGrid = blocksFor(std::size_t(l.dofs));
    // The further Chebyshev steps on x from the directions in dA (alternating with dB).
    auto chebyshev = [&](double* target) {
        double *dIn = l.dA.data, *dOut = l.dB.data;
        for (std::size_t k = 0; k < c1.size(); ++k, std::swap(dIn, dOut))
            if (finest)
                fem::fineChebyshevKernel<<<rowGrid, kThreads, 0, stream>>>(model, inverseDiagonal, dIn, dOut, l.r.data,
                                                                           target, c1[k], c2[k], g);
            else
            {
                fem::csrResidualKernel<<<csrGrid, kThreads, 0, stream>>>(l.matrix.view, nullptr, dIn, l.w.data, g);
                fem::blockChebyshevKernel<<<dofGrid, kThreads, 0, stream>>>(l.inverse, l.w.data, l.r.data, dIn, dOut,
                                                                            target, c1[k], c2[k], g);
            }
    };
    // Pre-smoothing from zero, the residual restricted, the coarse correction, post-smoothing into x.
    if (finest)
        fem::fineStartKernel<<<nodeGrid, kThreads, 0, stream>>>(model, inverseDiagonal, b, l.r.data, l.dA.data,
                                                                l.xA.data, inverseCentre, g);
    else
        fem::blockStartKernel<<<dofGrid, kThreads, 0, stream>>>(l.inverse, b, l.r.data, l.dA.data, l.xA.data,
                                                                inverseCentre, g);
    chebyshev(l.xA.data);
    if (finest)
        fem::fineResidualKernel<<<rowGrid, kThreads, 0, stream>>>(model, b, l.xA.data, l.w.data, g);
    else
        fem::csrResidualKernel<<<csrGrid, kThreads, 0, stream>>>(l.matrix.view, b, l.xA.data, l.w.data, g);
    fem::csrProductKernel<<<blocksFor(std::size_t(next.dofs) * fem::kCsrLanes), kThreads, 0, stream>>>(
        l.restriction.view, l.w.data, next.b.data, false, g);
    cycle(stream, level + 1, model, inverseDiagonal, next.b.data, next.xB.data, g);
    fem::csrProductKernel<<<csrGrid, kThreads, 0, stream>>>(l.prolongation.view, next.xB.data, l.xA.data, true, g);
    if (finest)
        fem::fineRestartKernel<<<rowGrid, kThreads, 0, stream>>>(model, inverseDiagonal, b, l.xA.data, x, l.r.data,
                                                                 l.dA.data, inverseCentre, g);
    else
    {
        fem::csrResidualKernel<<<csrGrid, kThreads, 0, stream>>>(l.matrix.view, b, l.xA.data, l.w.data, g);
        fem::blockRestartKernel<<<dofGrid, kThreads, 0, stream>>>(l.inverse, l.w.data, l.r.data, l.dA.data,
                                                                  l.xA.data, x, inverseCentre, g);
    }
    chebyshev(x);
}

} // namespace vsim::cuda
