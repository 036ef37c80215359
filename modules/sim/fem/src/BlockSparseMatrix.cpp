#include "vsim/sim/fem/BlockSparseMatrix.h"

#include <algorithm>

namespace vsim::sim::fem {

std::uint32_t BlockSparseMatrix::slotOf(std::size_t row, std::size_t column) const
{
    const auto begin = m_columns.begin() + m_rowStart[row], end = m_columns.begin() + m_rowStart[row + 1];
    return std::uint32_t(std::lower_bound(begin, end, std::uint32_t(column)) - m_columns.begin());
}

BlockSparseMatrix::BlockSparseMatrix(std::size_t nodeCount, const std::vector<std::array<int, 4>>& tets)
{
    build(nodeCount, tets);
}

BlockSparseMatrix::BlockSparseMatrix(std::size_t nodeCount, const std::vector<std::array<int, 10>>& tets)
{
    build(nodeCount, tets);
}

template <std::size_t N>
void BlockSparseMatrix::build(std::size_t nodeCount, const std::vector<std::array<int, N>>& tets)
{
    m_nodesPerElement = N;
    std::vector<std::vector<std::uint32_t>> neighbours(nodeCount);
    for (std::size_t n = 0; n < nodeCount; ++n)
        neighbours[n].push_back(std::uint32_t(n));
    for (const auto& tet : tets)
        for (int a : tet)
            for (int b : tet)
                neighbours[std::size_t(a)].push_back(std::uint32_t(b));
    m_rowStart.assign(nodeCount + 1, 0);
    for (std::size_t n = 0; n < nodeCount; ++n)
    {
        auto& row = neighbours[n];
        std::sort(row.begin(), row.end());
        row.erase(std::unique(row.begin(), row.end()), row.end());
        m_rowStart[n + 1] = m_rowStart[n] + std::uint32_t(row.size());
    }
    m_columns.reserve(m_rowStart.back());
    for (const auto& row : neighbours)
        m_columns.insert(m_columns.end(), row.begin(), row.end());
    m_blocks.assign(m_columns.size(), Eigen::Matrix3d::Zero());
    auto find = [&](std::size_t row, std::uint32_t column) { return slotOf(row, column); };
    m_diagonalSlot.resize(nodeCount);
    for (std::size_t n = 0; n < nodeCount; ++n)
        m_diagonalSlot[n] = find(n, std::uint32_t(n));
    m_elementSlots.resize(tets.size() * N * N);
    for (std::size_t t = 0; t < tets.size(); ++t)
        for (std::size_t a = 0; a < N; ++a)
            for (std::size_t b = 0; b < N; ++b)
                m_elementSlots[(t * N + a) * N + b] = find(std::size_t(tets[t][a]), std::uint32_t(tets[t][b]));
}

void BlockSparseMatrix::setZero()
{
    std::fill(m_blocks.begin(), m_blocks.end(), Eigen::Matrix3d::Zero());
}

void BlockSparseMatrix::multiply(const Eigen::VectorXd& x, Eigen::VectorXd& y) const
{
    const std::size_t rows = nodeCount();
    y.resize(Eigen::Index(3 * rows));
    // OpenMP: a persistent thread team; a conjugate-gradient solve calls this a hundred times per time step.
#pragma omp parallel for schedule(static)
    for (std::ptrdiff_t row = 0; row < std::ptrdiff_t(rows); ++row)
    {
        Eigen::Vector3d sum = Eigen::Vector3d::Zero();
        for (std::uint32_t s = m_rowStart[std::size_t(row)]; s < m_rowStart[std::size_t(row) + 1]; ++s)
            sum.noalias() += m_blocks[s] * x.segment<3>(Eigen::Index(3 * m_columns[s]));
        y.segment<3>(Eigen::Index(3 * row)) = sum;
    }
}

} // namespace vsim::sim::fem
