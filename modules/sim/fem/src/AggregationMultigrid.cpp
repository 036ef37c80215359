#include "vsim/sim/fem/AggregationMultigrid.h"

#include "vsim/core/Error.h"

#include <Eigen/LU>
#include <Eigen/QR>

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <random>

namespace vsim::sim::fem {

namespace {

/// The masked finest matrix S A S + (I - S) as scalar compressed rows (the block rows' columns are sorted).
SparseRows maskedScalarMatrix(const BlockSparseMatrix& a, const Eigen::VectorXd& free)
{
    const int nodes = int(a.nodeCount());
    SparseRows m(3 * nodes, 3 * nodes);
    m.resizeNonZeros(Eigen::Index(9 * a.blockCount()));
    int* outer = m.outerIndexPtr();
    int* inner = m.innerIndexPtr();
    double* values = m.valuePtr();
#pragma omp parallel for schedule(static)
    for (int node = 0; node < nodes; ++node)
    {
        const std::uint32_t begin = a.rowStart()[std::size_t(node)], end = a.rowStart()[std::size_t(node) + 1];
        for (int r = 0; r < 3; ++r)
        {
            const int row = 3 * node + r;
            int k = int(9 * begin + 3 * std::uint32_t(r) * (end - begin)); // block row n's rows hold 3 entries a block
            outer[row] = k;
            for (std::uint32_t s = begin; s < end; ++s)
            {
                const int column = int(a.columns()[s]);
                for (int c = 0; c < 3; ++c, ++k)
                {
                    const int j = 3 * column + c;
                    inner[k] = j;
                    values[k] = row == j && free[row] == 0.0 ? 1.0 : free[row] * free[j] * a.block(s)(r, c);
                }
            }
        }
    }
    outer[3 * nodes] = int(9 * a.blockCount());
    return m;
}

/// a b, row by row on every thread (Gustavson's algorithm with a dense accumulator per thread; Eigen's sparse
/// product runs on one: 6.9 of the 18.8 s of a 1M-tet set-up went into A P alone).
SparseRows multiplyRows(const SparseRows& a, const SparseRows& b)
{
    const int rows = int(a.rows()), columns = int(b.cols()), chunks = std::max(1, omp_get_max_threads());
    std::vector<std::vector<int>> chunkColumns(static_cast<std::size_t>(chunks));
    std::vector<std::vector<double>> chunkValues(static_cast<std::size_t>(chunks));
    std::vector<int> rowStart(std::size_t(rows) + 1, 0);
#pragma omp parallel
    {
        std::vector<double> sum(std::size_t(columns), 0.0);
        std::vector<int> lastRow(std::size_t(columns), -1), touched;
#pragma omp for schedule(static, 1)
        for (int chunk = 0; chunk < chunks; ++chunk)
        {
            std::vector<int>& chunkColumn = chunkColumns[std::size_t(chunk)];
            std::vector<double>& chunkValue = chunkValues[std::size_t(chunk)];
            for (int row = int(std::int64_t(rows) * chunk / chunks); row < int(std::int64_t(rows) * (chunk + 1) / chunks); ++row)
            {
                touched.clear();
                for (SparseRows::InnerIterator left(a, row); left; ++left)
                    for (SparseRows::InnerIterator right(b, left.col()); right; ++right)
                    {
                        const std::size_t column = std::size_t(right.col());
                        if (lastRow[column] != row)
                            lastRow[column] = row, sum[column] = 0.0, touched.push_back(int(column));
                        sum[column] += left.value() * right.value();
                    }
                std::sort(touched.begin(), touched.end());
                for (int column : touched)
                    chunkColumn.push_back(column), chunkValue.push_back(sum[std::size_t(column)]);
                rowStart[std::size_t(row) + 1] = int(touched.size());
            }
        }
    }
    for (int row = 0; row < rows; ++row)
        rowStart[std::size_t(row) + 1] += rowStart[std::size_t(row)];
    SparseRows product(rows, columns);
    product.resizeNonZeros(rowStart.back());
    std::copy(rowStart.begin(), rowStart.end(), product.outerIndexPtr());
    std::size_t at = 0;
    for (int chunk = 0; chunk < chunks; ++chunk)
    {
        std::copy(chunkColumns[std::size_t(chunk)].begin(), chunkColumns[std::size_t(chunk)].end(), product.innerIndexPtr() + at);
        std::copy(chunkValues[std::size_t(chunk)].begin(), chunkValues[std::size_t(chunk)].end(), product.valuePtr() + at);
        at += chunkColumns[std::size_t(chunk)].size();
    }
    return product;
}

/// The inverses of the diagonal blocks of `m` given by `level.blockStart` (a zero row, which an unused coarse
/// unknown leaves, gets 1 on its diagonal: the unknown is then smoothed as an identity).
void invertDiagonalBlocks(const SparseRows& m, MultigridLevel& level)
{
    const std::size_t blocks = level.blockStart.size() - 1;
    level.inverseStart.assign(blocks + 1, 0);
    for (std::size_t k = 0; k < blocks; ++k)
    {
        const int size = level.blockStart[k + 1] - level.blockStart[k];
        level.inverseStart[k + 1] = level.inverseStart[k] + size * size;
    }
    level.inverseBlocks.assign(std::size_t(level.inverseStart.back()), 0.0);
#pragma omp parallel for schedule(static)
    for (std::ptrdiff_t k = 0; k < std::ptrdiff_t(blocks); ++k)
    {
        const int first = level.blockStart[std::size_t(k)], size = level.blockStart[std::size_t(k) + 1] - first;
        Eigen::MatrixXd block = Eigen::MatrixXd::Zero(size, size);
        for (int r = 0; r < size; ++r)
            for (SparseRows::InnerIterator it(m, first + r); it; ++it)
                if (it.col() >= first && it.col() < first + size)
                    block(r, it.col() - first) = it.value();
        for (int r = 0; r < size; ++r)
            if (block.row(r).isZero(0.0))
                block(r, r) = 1.0;
        const Eigen::MatrixXd inverse = block.inverse();
        for (int r = 0; r < size; ++r)
            for (int c = 0; c < size; ++c)
                level.inverseBlocks[std::size_t(level.inverseStart[std::size_t(k)] + r * size + c)] = inverse(r, c);
    }
}

/// z = D^-1 r with the level's inverse diagonal blocks.
void applyInverseDiagonal(const MultigridLevel& level, const Eigen::VectorXd& r, Eigen::VectorXd& z)
{
    z.resize(r.size());
    const std::size_t blocks = level.blockStart.size() - 1;
#pragma omp parallel for schedule(static)
    for (std::ptrdiff_t k = 0; k < std::ptrdiff_t(blocks); ++k)
    {
        const int first = level.blockStart[std::size_t(k)], size = level.blockStart[std::size_t(k) + 1] - first;
        const double* inverse = level.inverseBlocks.data() + level.inverseStart[std::size_t(k)];
        for (int i = 0; i < size; ++i)
        {
            double sum = 0.0;
            for (int j = 0; j < size; ++j)
                sum += inverse[i * size + j] * r[first + j];
            z[first + i] = sum;
        }
    }
}

/// The block (node or aggregate) of each unknown.
std::vector<int> blockOfUnknown(const std::vector<int>& blockStart)
{
    std::vector<int> owner(std::size_t(blockStart.back()));
    for (std::size_t k = 0; k + 1 < blockStart.size(); ++k)
        std::fill(owner.begin() + blockStart[k], owner.begin() + blockStart[k + 1], int(k));
    return owner;
}

/// The strong couplings between blocks: |A_kl|_F >= theta sqrt(|A_kk|_F |A_ll|_F), k != l (compressed rows).
void strongGraph(const SparseRows& m, const std::vector<int>& blockStart, double theta, std::vector<int>& start,
                 std::vector<int>& neighbours)
{
    const std::size_t blocks = blockStart.size() - 1;
    const std::vector<int> owner = blockOfUnknown(blockStart);
    std::vector<double> diagonal(blocks, 0.0);
    std::vector<std::vector<std::pair<int, double>>> rows(blocks);
#pragma omp parallel
    {
        std::vector<double> sum(blocks, 0.0);
        std::vector<int> touched;
#pragma omp for schedule(dynamic, 256)
        for (std::ptrdiff_t k = 0; k < std::ptrdiff_t(blocks); ++k)
        {
            touched.clear();
            for (int row = blockStart[std::size_t(k)]; row < blockStart[std::size_t(k) + 1]; ++row)
                for (SparseRows::InnerIterator it(m, row); it; ++it)
                {
                    const int l = owner[std::size_t(it.col())];
                    if (sum[std::size_t(l)] == 0.0)
                        touched.push_back(l);
                    sum[std::size_t(l)] += it.value() * it.value() + 1e-300; // marks a stored zero as touched
                }
            for (int l : touched)
            {
                rows[std::size_t(k)].emplace_back(l, std::sqrt(sum[std::size_t(l)]));
                sum[std::size_t(l)] = 0.0;
            }
        }
    }
    for (std::size_t k = 0; k < blocks; ++k)
        for (const auto& [l, norm] : rows[k])
            if (std::size_t(l) == k)
                diagonal[k] = norm;
    start.assign(blocks + 1, 0);
    neighbours.clear();
    for (std::size_t k = 0; k < blocks; ++k)
    {
        for (const auto& [l, norm] : rows[k])
            if (std::size_t(l) != k && norm > 1e-150 && norm >= theta * std::sqrt(diagonal[k] * diagonal[std::size_t(l)]))
                neighbours.push_back(l);
        start[k + 1] = int(neighbours.size());
    }
}

/// Greedy aggregation (Vanek et al. 1996): roots whose strong neighbourhood is still free take it whole; the rest
/// join a neighbouring aggregate; what is left alone forms its own. Blocks without strong links (held nodes) stay
/// out of every aggregate (-1). Returns the aggregate count.
int aggregate(const std::vector<int>& start, const std::vector<int>& neighbours, std::vector<int>& aggregateOf)
{
    const std::size_t blocks = start.size() - 1;
    aggregateOf.assign(blocks, -1);
    int count = 0;
    for (std::size_t k = 0; k < blocks; ++k)
    {
        if (aggregateOf[k] >= 0 || start[k + 1] == start[k])
            continue;
        bool free = true;
        for (int s = start[k]; s < start[k + 1] && free; ++s)
            free = aggregateOf[std::size_t(neighbours[std::size_t(s)])] < 0;
        if (!free)
            continue;
        aggregateOf[k] = count;
        for (int s = start[k]; s < start[k + 1]; ++s)
            aggregateOf[std::size_t(neighbours[std::size_t(s)])] = count;
        ++count;
    }
    const std::vector<int> firstPass = aggregateOf;
    for (std::size_t k = 0; k < blocks; ++k)
        if (aggregateOf[k] < 0)
            for (int s = start[k]; s < start[k + 1]; ++s)
                if (firstPass[std::size_t(neighbours[std::size_t(s)])] >= 0)
                {
                    aggregateOf[k] = firstPass[std::size_t(neighbours[std::size_t(s)])];
                    break;
                }
    for (std::size_t k = 0; k < blocks; ++k)
        if (aggregateOf[k] < 0 && start[k + 1] > start[k])
            aggregateOf[k] = count++;
    return count;
}

/// The largest eigenvalue of D^-1 A by power iteration (a fixed seed: the same hierarchy every time).
template <typename Multiply>
double largestEigenvalue(const MultigridLevel& level, int dofs, Multiply multiply)
{
    std::mt19937 generator(12345);
    std::uniform_real_distribution<double> uniform(-1.0, 1.0);
    Eigen::VectorXd x(dofs), ax, y;
    for (int i = 0; i < dofs; ++i)
        x[i] = uniform(generator);
    double estimate = 0.0;
    for (int k = 0; k < 30; ++k)
    {
        x /= x.norm();
        multiply(x, ax);
        applyInverseDiagonal(level, ax, y);
        estimate = y.norm();
        x = y;
    }
    return estimate;
}

} // namespace

AggregationMultigrid::AggregationMultigrid(const BlockSparseMatrix& a, const Eigen::VectorXd& positions,
                                           const std::vector<std::uint8_t>& constrained,
                                           AggregationMultigridSettings settings)
    : m_settings(settings)
{
    const int nodes = int(a.nodeCount());
    if (positions.size() != 3 * nodes || (!constrained.empty() && constrained.size() != std::size_t(3 * nodes)))
        throw Error("multigrid: the matrix, positions and constraints differ in size");
    m_free = Eigen::VectorXd::Ones(3 * nodes);
    for (std::size_t i = 0; i < constrained.size(); ++i)
        if (constrained[i])
            m_free[Eigen::Index(i)] = 0.0;

    // The near-null space: three translations and three rotations about the centroid, zero where held.
    Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
    for (int n = 0; n < nodes; ++n)
        centroid += positions.segment<3>(3 * n);
    centroid /= std::max(1, nodes);
    Eigen::MatrixXd modes = Eigen::MatrixXd::Zero(3 * nodes, 6);
    for (int n = 0; n < nodes; ++n)
    {
        const Eigen::Vector3d p = positions.segment<3>(3 * n) - centroid;
        modes.block<3, 3>(3 * n, 0).setIdentity();
        modes.block<3, 3>(3 * n, 3) << 0.0, p.z(), -p.y(), -p.z(), 0.0, p.x(), p.y(), -p.x(), 0.0;
        for (int c = 0; c < 3; ++c)
            modes.row(3 * n + c) *= m_free[3 * n + c];
    }

    SparseRows current = maskedScalarMatrix(a, m_free);
    const double finestEntries = double(current.nonZeros());
    double allEntries = finestEntries;
    m_levels.reserve(std::size_t(settings.maxLevels)); // no copies of the levels' matrices as the list grows
    std::vector<int> blockStart(std::size_t(nodes) + 1);
    for (int n = 0; n <= nodes; ++n)
        blockStart[std::size_t(n)] = 3 * n;
    for (int depth = 0;; ++depth)
    {
        MultigridLevel level;
        level.dofs = int(current.rows());
        level.blockStart = blockStart;
        invertDiagonalBlocks(current, level);
        level.largestEigenvalue =
            1.1 * largestEigenvalue(level, level.dofs, [&](const Eigen::VectorXd& x, Eigen::VectorXd& y) { y = current * x; });
        if (level.dofs <= settings.coarsestDofs || depth + 1 >= settings.maxLevels)
        {
            if (depth > 0)
                level.matrix = std::move(current);
            m_levels.push_back(std::move(level));
            break;
        }

        // Aggregates, then the tentative prolongator: per aggregate, an orthonormal basis of the modes on its
        // unknowns (rank-revealing QR; a rank-deficient aggregate, e.g. partly held, keeps fewer coarse unknowns).
        std::vector<int> graphStart, graphNeighbours, aggregateOf;
        strongGraph(current, blockStart, depth == 0 ? settings.strengthThreshold : 0.0, graphStart, graphNeighbours);
        const int aggregates = aggregate(graphStart, graphNeighbours, aggregateOf);
        if (aggregates == 0 || aggregates * 10 > int(blockStart.size() - 1) * 9) // coarsening stalled
        {
            if (depth > 0)
                level.matrix = std::move(current);
            m_levels.push_back(std::move(level));
            break;
        }
        std::vector<std::vector<int>> members(static_cast<std::size_t>(aggregates));
        for (std::size_t k = 0; k + 1 < blockStart.size(); ++k)
            if (aggregateOf[k] >= 0)
                for (int u = blockStart[k]; u < blockStart[k + 1]; ++u)
                    members[std::size_t(aggregateOf[k])].push_back(u);
        std::vector<Eigen::Triplet<double>> entries;
        std::vector<int> coarseStart{0};
        std::vector<Eigen::MatrixXd> coarseModes(static_cast<std::size_t>(aggregates));
        std::vector<Eigen::MatrixXd> bases(static_cast<std::size_t>(aggregates));
#pragma omp parallel for schedule(dynamic, 64)
        for (std::ptrdiff_t g = 0; g < std::ptrdiff_t(aggregates); ++g)
        {
            const std::vector<int>& unknowns = members[std::size_t(g)];
            Eigen::MatrixXd local(Eigen::Index(unknowns.size()), 6);
            for (std::size_t i = 0; i < unknowns.size(); ++i)
                local.row(Eigen::Index(i)) = modes.row(unknowns[i]);
            Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(local);
            qr.setThreshold(1e-10);
            const Eigen::Index rank = qr.rank();
            const Eigen::MatrixXd q = Eigen::MatrixXd(qr.householderQ()).leftCols(rank);
            const Eigen::MatrixXd r = qr.matrixR().topLeftCorner(rank, 6).triangularView<Eigen::Upper>();
            bases[std::size_t(g)] = q;
            coarseModes[std::size_t(g)] = r * qr.colsPermutation().transpose();
        }
        for (int g = 0; g < aggregates; ++g)
            coarseStart.push_back(coarseStart.back() + int(bases[std::size_t(g)].cols()));
        const int coarseDofs = coarseStart.back();
        Eigen::MatrixXd nextModes(coarseDofs, 6);
        for (int g = 0; g < aggregates; ++g)
        {
            const std::vector<int>& unknowns = members[std::size_t(g)];
            const Eigen::MatrixXd& q = bases[std::size_t(g)];
            for (std::size_t i = 0; i < unknowns.size(); ++i)
                for (Eigen::Index c = 0; c < q.cols(); ++c)
                    if (q(Eigen::Index(i), c) != 0.0)
                        entries.emplace_back(unknowns[i], coarseStart[std::size_t(g)] + int(c), q(Eigen::Index(i), c));
            nextModes.middleRows(coarseStart[std::size_t(g)], q.cols()) = coarseModes[std::size_t(g)];
        }
        SparseRows tentative(level.dofs, coarseDofs);
        tentative.setFromTriplets(entries.begin(), entries.end());

        // Smoothed prolongator P = (I - omega D^-1 A) T, omega = 4 / (3 lambda_max(D^-1 A)).
        const double omega = 4.0 / 3.0 / (level.largestEigenvalue / 1.1);
        std::vector<Eigen::Triplet<double>> inverseEntries;
        for (std::size_t k = 0; k + 1 < blockStart.size(); ++k)
        {
            const int first = blockStart[k], size = blockStart[k + 1] - first;
            for (int r = 0; r < size; ++r)
                for (int c = 0; c < size; ++c)
                    inverseEntries.emplace_back(first + r, first + c,
                                                level.inverseBlocks[std::size_t(level.inverseStart[k] + r * size + c)]);
        }
        SparseRows inverseDiagonal(level.dofs, level.dofs);
        inverseDiagonal.setFromTriplets(inverseEntries.begin(), inverseEntries.end());
        const SparseRows scaled = multiplyRows(inverseDiagonal, multiplyRows(current, tentative));
        level.prolongation = tentative - omega * scaled;
        level.prolongation.prune(0.0);
        level.restriction = level.prolongation.transpose();
        SparseRows coarse = multiplyRows(level.restriction, multiplyRows(current, level.prolongation));
        allEntries += double(coarse.nonZeros());
        if (depth > 0)
            level.matrix = std::move(current);
        current = std::move(coarse);
        m_levels.push_back(std::move(level));
        blockStart = coarseStart;
        modes = std::move(nextModes);
        if (settings.afterLevel)
            settings.afterLevel();
    }
    m_operatorComplexity = allEntries / finestEntries;
    const MultigridLevel& coarsest = m_levels.back();
    const Eigen::MatrixXd dense =
        m_levels.size() == 1 ? Eigen::MatrixXd(maskedScalarMatrix(a, m_free)) : Eigen::MatrixXd(coarsest.matrix);
    Eigen::MatrixXd regular = dense;
    for (Eigen::Index i = 0; i < regular.rows(); ++i)
        if (regular.row(i).isZero(0.0))
            regular(i, i) = 1.0; // an unused coarse unknown
    m_coarsest.compute(regular);
    if (m_coarsest.info() != Eigen::Success)
        throw Error("multigrid: the coarsest level is not positive definite");
    m_settings.afterLevel = nullptr; // a set-up's poll only (it may hold the caller's progress by reference)
}

void AggregationMultigrid::refreshFinest(const BlockSparseMatrix& a)
{
    MultigridLevel& finest = m_levels.front();
#pragma omp parallel for schedule(static)
    for (std::ptrdiff_t node = 0; node < std::ptrdiff_t(a.nodeCount()); ++node)
    {
        const Eigen::Vector3d mask = m_free.segment<3>(3 * node);
        Eigen::Matrix3d block = mask.asDiagonal() * a.diagonal(std::size_t(node)) * mask.asDiagonal();
        for (int c = 0; c < 3; ++c)
            if (mask[c] == 0.0)
                block(c, c) = 1.0;
        Eigen::Map<Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(finest.inverseBlocks.data() + 9 * node) = block.inverse();
    }
}

Eigen::MatrixXd AggregationMultigrid::coarsestInverse() const
{
    const Eigen::Index n = m_coarsest.rows();
    return m_coarsest.solve(Eigen::MatrixXd::Identity(n, n));
}

void AggregationMultigrid::multiply(const BlockSparseMatrix& a, std::size_t level, const Eigen::VectorXd& x,
                                    Eigen::VectorXd& y) const
{
    if (level > 0)
    {
        y = m_levels[level].matrix * x;
        return;
    }
    a.multiply(m_free.cwiseProduct(x), y);
    y = m_free.cwiseProduct(y) + (Eigen::VectorXd::Ones(x.size()) - m_free).cwiseProduct(x);
}

void AggregationMultigrid::smooth(const BlockSparseMatrix& a, std::size_t level, Eigen::VectorXd& x,
                                  const Eigen::VectorXd& b, bool fromZero) const
{
    // Chebyshev iteration on D^-1 A over [fraction, 1] x lambda_max (Saad, Iterative Methods, alg. 12.1).
    const MultigridLevel& l = m_levels[level];
    const double upper = l.largestEigenvalue, lower = upper * m_settings.chebyshevLowerFraction;
    const double centre = 0.5 * (upper + lower), halfWidth = 0.5 * (upper - lower), sigma = centre / halfWidth;
    double rho = 1.0 / sigma;
    Eigen::VectorXd residual, ad, r, d;
    if (fromZero)
        residual = b;
    else
    {
        multiply(a, level, x, residual);
        residual = b - residual;
    }
    applyInverseDiagonal(l, residual, r);
    d = r / centre;
    for (int k = 0; k < m_settings.chebyshevDegree; ++k)
    {
        x += d;
        if (k + 1 == m_settings.chebyshevDegree)
            break;
        multiply(a, level, d, ad);
        applyInverseDiagonal(l, ad, residual);
        r -= residual;
        const double rhoNext = 1.0 / (2.0 * sigma - rho);
        d = rhoNext * rho * d + (2.0 * rhoNext / halfWidth) * r;
        rho = rhoNext;
    }
}

void AggregationMultigrid::cycle(const BlockSparseMatrix& a, std::size_t level, const Eigen::VectorXd& b,
                                 Eigen::VectorXd& x) const
{
    if (level + 1 == m_levels.size())
    {
        x = m_coarsest.solve(b);
        return;
    }
    const MultigridLevel& l = m_levels[level];
    x = Eigen::VectorXd::Zero(b.size());
    smooth(a, level, x, b, true);
    Eigen::VectorXd residual;
    multiply(a, level, x, residual);
    const Eigen::VectorXd coarseRight = l.restriction * (b - residual);
    Eigen::VectorXd coarse;
    cycle(a, level + 1, coarseRight, coarse);
    x += l.prolongation * coarse;
    smooth(a, level, x, b, false);
}

void AggregationMultigrid::apply(const BlockSparseMatrix& a, const Eigen::VectorXd& r, Eigen::VectorXd& z) const
{
    cycle(a, 0, m_free.cwiseProduct(r), z);
    z = m_free.cwiseProduct(z);
}

} // namespace vsim::sim::fem
