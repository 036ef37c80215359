#pragma once

// A sparse matrix of 3x3 blocks (block compressed rows) with the pattern of a finite-element mesh: node i couples to
// itself and to every node sharing an element with it (4-node linear or 10-node quadratic tetrahedra). Elements add
// their blocks through precomputed slots, so a time step or a Newton update re-assembles without searching.

#include <Eigen/Core>

#include <array>
#include <cstdint>
#include <vector>

namespace vsim::sim::fem {

class BlockSparseMatrix
{
public:
    BlockSparseMatrix() = default;
    /// The pattern of `tets` over `nodeCount` nodes; all blocks zero.
    BlockSparseMatrix(std::size_t nodeCount, const std::vector<std::array<int, 4>>& tets);
    /// The pattern of 10-node (quadratic) tetrahedra.
    BlockSparseMatrix(std::size_t nodeCount, const std::vector<std::array<int, 10>>& tets);

    std::size_t nodeCount() const { return m_rowStart.empty() ? 0 : m_rowStart.size() - 1; }
    std::size_t blockCount() const { return m_columns.size(); }
    void setZero();
    /// The slot of block (row, column) for element `tet`'s local nodes (a, b) (0..3, or 0..9 for quadratic ones).
    std::uint32_t slot(std::size_t tet, int a, int b) const
    {
        return m_elementSlots[(tet * m_nodesPerElement + std::size_t(a)) * m_nodesPerElement + std::size_t(b)];
    }
    /// The slot of block (row, column), which must be in the pattern (two nodes of one element).
    std::uint32_t slotOf(std::size_t row, std::size_t column) const;
    Eigen::Matrix3d& block(std::uint32_t slot) { return m_blocks[slot]; }
    const Eigen::Matrix3d& block(std::uint32_t slot) const { return m_blocks[slot]; }
    /// The diagonal block of node `node`.
    const Eigen::Matrix3d& diagonal(std::size_t node) const { return m_blocks[m_diagonalSlot[node]]; }
    Eigen::Matrix3d& diagonal(std::size_t node) { return m_blocks[m_diagonalSlot[node]]; }
    /// y = A x (3 entries per node), rows in parallel.
    void multiply(const Eigen::VectorXd& x, Eigen::VectorXd& y) const;
    /// Row starts, column indices and blocks, for backends that copy the matrix (CUDA).
    const std::vector<std::uint32_t>& rowStart() const { return m_rowStart; }
    const std::vector<std::uint32_t>& columns() const { return m_columns; }
    const std::vector<Eigen::Matrix3d>& blocks() const { return m_blocks; }

private:
    template <std::size_t N>
    void build(std::size_t nodeCount, const std::vector<std::array<int, N>>& elements);

    std::size_t m_nodesPerElement = 4;
    std::vector<std::uint32_t> m_rowStart;
    std::vector<std::uint32_t> m_columns;
    std::vector<Eigen::Matrix3d> m_blocks;
    std::vector<std::uint32_t> m_diagonalSlot;
    std::vector<std::uint32_t> m_elementSlots; // per element, nodes-per-element squared, row-major
};

} // namespace vsim::sim::fem
