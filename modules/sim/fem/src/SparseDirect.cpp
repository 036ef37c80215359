#include "vsim/sim/fem/SparseDirect.h"

#include "BlasThreads.h"

#include <Eigen/CholmodSupport>
#include <Eigen/UmfPackSupport>

#include <algorithm>
#include <chrono>
#include <condition_variable>
#include <mutex>
#include <numeric>
#include <thread>

namespace vsim::sim::fem {
namespace {

/// METIS's nested dissection (cholmod_metis, postordered) of the matrix's node graph: the fill-reducing order of
/// the nodes, each node's 3 components then kept together. On cli_sac's quadratic thrombus wall the first
/// factorisation (ordering, analysis and factorisation) took 5.7 s against 8.4-8.5 s with CHOLMOD's own choice
/// (AMD, then METIS on the 9x larger scalar graph), for 8.2e10 flops against 7.65e10 (RESULTS.md, 2026-12-01).
/// Empty when METIS fails (CHOLMOD then orders as it would).
std::vector<int> nestedDissectionOfNodes(const BlockSparseMatrix& pattern, cholmod_common& common)
{
    const std::size_t nodes = pattern.nodeCount();
    std::vector<int> start(pattern.rowStart().begin(), pattern.rowStart().end());
    std::vector<int> neighbours(pattern.columns().begin(), pattern.columns().end());
    cholmod_sparse graph{};
    graph.nrow = graph.ncol = nodes;
    graph.nzmax = neighbours.size();
    graph.p = start.data();
    graph.i = neighbours.data();
    graph.stype = 1; // symmetric: the pattern is, and CHOLMOD reads its upper triangle
    graph.itype = CHOLMOD_INT;
    graph.xtype = CHOLMOD_PATTERN;
    graph.dtype = CHOLMOD_DOUBLE;
    graph.sorted = 1;
    graph.packed = 1;
    std::vector<int> order(nodes);
    if (nodes == 0 || !cholmod_metis(&graph, nullptr, 0, 1, order.data(), &common))
        return {};
    return order;
}

} // namespace

struct SparseDirect::Factors
{
    Eigen::CholmodSupernodalLLT<Eigen::SparseMatrix<double>, Eigen::Lower> cholesky;
    Eigen::UmfPackLU<Eigen::SparseMatrix<double>> lu;
};

SparseDirect::~SparseDirect() = default;

SparseDirect::SparseDirect(const BlockSparseMatrix& pattern, const std::vector<std::uint8_t>& constrained, Kind kind)
    : m_kind(kind), m_factors(std::make_shared<Factors>())
{
    detail::capBlasThreads();
    const std::size_t dofs = 3 * pattern.nodeCount();
    // The free degrees of freedom node by node, for the Cholesky in the fill-reducing order of the nodes (CHOLMOD
    // then keeps it: a natural ordering, postordered).
    std::vector<int> nodeOrder;
    if (m_kind == Kind::SymmetricCholesky)
        nodeOrder = nestedDissectionOfNodes(pattern, m_factors->cholesky.cholmod());
    if (nodeOrder.empty())
        nodeOrder.resize(pattern.nodeCount()), std::iota(nodeOrder.begin(), nodeOrder.end(), 0);
    else
        m_naturalOrdering = true;
    configure(*m_factors);
    m_freeIndex.assign(dofs, -1);
    for (int node : nodeOrder)
        for (std::size_t d = 3 * std::size_t(node); d < 3 * std::size_t(node) + 3; ++d)
            if (constrained.empty() || !constrained[d])
                m_freeIndex[d] = std::int64_t(m_freeDofs.size()), m_freeDofs.push_back(std::int64_t(d));
    // The copy's pattern, column by column: the mesh pattern is symmetric, so column (n, b)'s blocks are (m, n) for
    // the neighbours m of block row n; each column's rows sorted. The Cholesky kind keeps the lower triangle.
    const bool lowerOnly = m_kind == Kind::SymmetricCholesky;
    const auto& rowStart = pattern.rowStart();
    const auto& columns = pattern.columns();
    using Index = Eigen::SparseMatrix<double>::StorageIndex;
    std::vector<Index> outer(1, 0), inner;
    std::vector<std::pair<Index, Source>> column;
    for (std::int64_t dof : m_freeDofs)
    {
        const std::size_t n = std::size_t(dof) / 3;
        const std::uint8_t b = std::uint8_t(dof % 3);
        column.clear();
        for (std::uint32_t s = rowStart[n]; s < rowStart[n + 1]; ++s)
        {
            const std::size_t m = columns[s];
            for (std::uint8_t a = 0; a < 3; ++a)
            {
                const std::int64_t row = m_freeIndex[3 * m + a];
                if (row < 0 || (lowerOnly && row < m_freeIndex[std::size_t(dof)]))
                    continue;
                column.push_back({Index(row), Source{pattern.slotOf(m, n), s, a, b}});
            }
        }
        std::sort(column.begin(), column.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
        for (const auto& [row, source] : column)
            inner.push_back(row), m_sources.push_back(source);
        outer.push_back(Index(inner.size()));
    }
    const Eigen::Index free = Eigen::Index(m_freeDofs.size());
    m_matrix.resize(free, free);
    m_matrix.resizeNonZeros(Eigen::Index(inner.size()));
    std::copy(outer.begin(), outer.end(), m_matrix.outerIndexPtr());
    std::copy(inner.begin(), inner.end(), m_matrix.innerIndexPtr());
}

void SparseDirect::configure(Factors& factors) const
{
    if (m_naturalOrdering) // the rows come in the nodes' nested dissection already
    {
        factors.cholesky.cholmod().nmethods = 1;
        factors.cholesky.cholmod().method[0].ordering = CHOLMOD_NATURAL;
    }
    // GMRES refines the solves it is preconditioned with, and a direct solve checks its own residual: no
    // iterative refinement inside UMFPACK (by default up to two, each a solve and a product more).
    factors.lu.umfpackControl()(UMFPACK_IRSTEP) = 0;
    factors.cholesky.cholmod().print = 0; // a matrix that is not positive definite is reported by the return value
}

void SparseDirect::copyValues(const BlockSparseMatrix& matrix)
{
    const auto& blocks = matrix.blocks();
    double* values = m_matrix.valuePtr();
    const std::ptrdiff_t count = std::ptrdiff_t(m_sources.size());
    // The Cholesky kind factorises the symmetric part (A + A^T) / 2 (A itself when A is symmetric).
    if (m_kind == Kind::SymmetricCholesky)
    {
#pragma omp parallel for schedule(static)
        for (std::ptrdiff_t k = 0; k < count; ++k)
        {
            const Source& s = m_sources[std::size_t(k)];
            values[k] = 0.5 * (blocks[s.slot](s.row, s.column) + blocks[s.transposedSlot](s.column, s.row));
        }
        return;
    }
#pragma omp parallel for schedule(static)
    for (std::ptrdiff_t k = 0; k < count; ++k)
    {
        const Source& s = m_sources[std::size_t(k)];
        values[k] = blocks[s.slot](s.row, s.column);
    }
}

namespace {

/// Analyses the pattern (the first time) and factorises `matrix` into `factors`.
template <class Factors>
bool factorizeInto(Factors& factors, const Eigen::SparseMatrix<double>& matrix, bool cholesky, bool analyse)
{
    if (cholesky)
    {
        if (analyse)
            factors.cholesky.analyzePattern(matrix);
        factors.cholesky.factorize(matrix);
        return factors.cholesky.info() == Eigen::Success;
    }
    if (analyse)
        factors.lu.analyzePattern(matrix);
    factors.lu.factorize(matrix);
    return factors.lu.info() == Eigen::Success;
}

} // namespace

bool SparseDirect::factorize(const BlockSparseMatrix& matrix, const std::function<void()>& whileWaiting)
{
    copyValues(matrix);
    const bool cholesky = m_kind == Kind::SymmetricCholesky, analyse = !m_analysed;
    if (!whileWaiting)
    {
        m_analysed = true;
        return factorizeInto(*m_factors, m_matrix, cholesky, analyse);
    }
    // On a thread of its own, which holds the factors and the matrix until it ends, so that the caller can leave
    // meanwhile (whileWaiting throws vsim::Cancelled): the factorisation then finishes unseen and is dropped, and
    // this object starts again from fresh factors.
    struct Job
    {
        std::shared_ptr<Factors> factors;
        Eigen::SparseMatrix<double> matrix;
        std::mutex mutex;
        std::condition_variable ended;
        bool finished = false, succeeded = false;
    };
    auto job = std::make_shared<Job>();
    job->factors = m_factors;
    job->matrix.swap(m_matrix);
    std::thread([job, cholesky, analyse] {
        bool succeeded = false;
        try
        {
            succeeded = factorizeInto(*job->factors, job->matrix, cholesky, analyse);
        }
        catch (...) // out of memory: a failed factorisation (an exception cannot leave a thread)
        {
        }
        const std::lock_guard lock(job->mutex);
        job->succeeded = succeeded, job->finished = true;
        job->ended.notify_all();
    }).detach();
    std::unique_lock lock(job->mutex);
    while (!job->ended.wait_for(lock, std::chrono::milliseconds(50), [&job] { return job->finished; }))
    {
        lock.unlock();
        try
        {
            whileWaiting();
        }
        catch (...)
        {
            m_matrix = job->matrix; // its values and pattern, which the factorisation only reads
            m_factors = std::make_shared<Factors>();
            configure(*m_factors);
            m_analysed = false;
            throw;
        }
        lock.lock();
    }
    m_matrix.swap(job->matrix);
    m_analysed = true;
    return job->succeeded;
}

void SparseDirect::solveOnly(const Eigen::VectorXd& b, Eigen::VectorXd& x) const
{
    Eigen::VectorXd freeB(Eigen::Index(m_freeDofs.size()));
    for (std::size_t f = 0; f < m_freeDofs.size(); ++f)
        freeB[Eigen::Index(f)] = b[Eigen::Index(m_freeDofs[f])];
    const Eigen::VectorXd freeX = m_kind == Kind::SymmetricCholesky ? Eigen::VectorXd(m_factors->cholesky.solve(freeB))
                                                                    : Eigen::VectorXd(m_factors->lu.solve(freeB));
    x = Eigen::VectorXd::Zero(b.size());
    for (std::size_t f = 0; f < m_freeDofs.size(); ++f)
        x[Eigen::Index(m_freeDofs[f])] = freeX[Eigen::Index(f)];
}

double SparseDirect::solve(const Eigen::VectorXd& b, Eigen::VectorXd& x) const
{
    solveOnly(b, x);
    Eigen::VectorXd freeB(Eigen::Index(m_freeDofs.size())), freeX(Eigen::Index(m_freeDofs.size()));
    for (std::size_t f = 0; f < m_freeDofs.size(); ++f)
    {
        freeB[Eigen::Index(f)] = b[Eigen::Index(m_freeDofs[f])];
        freeX[Eigen::Index(f)] = x[Eigen::Index(m_freeDofs[f])];
    }
    const Eigen::VectorXd check = (m_kind == Kind::SymmetricCholesky
                                       ? Eigen::VectorXd(m_matrix.selfadjointView<Eigen::Lower>() * freeX)
                                       : Eigen::VectorXd(m_matrix * freeX)) - freeB;
    const double norm = freeB.norm();
    return norm > 0.0 ? check.norm() / norm : check.norm();
}

} // namespace vsim::sim::fem
