#include "vsim/sim/fem/SparseDirect.h"

#include <Eigen/CholmodSupport>
#include <Eigen/UmfPackSupport>

namespace vsim::sim::fem {

struct SparseDirect::Factors
{
    Eigen::CholmodSupernodalLLT<Eigen::SparseMatrix<double>, Eigen::Lower> cholesky;
    Eigen::UmfPackLU<Eigen::SparseMatrix<double>> lu;
};

SparseDirect::~SparseDirect() = default;

SparseDirect::SparseDirect(const BlockSparseMatrix& pattern, const std::vector<std::uint8_t>& constrained, Kind kind)
    : m_kind(kind), m_factors(std::make_unique<Factors>())
{
    const std::size_t dofs = 3 * pattern.nodeCount();
    m_freeIndex.assign(dofs, -1);
    for (std::size_t d = 0; d < dofs; ++d)
        if (constrained.empty() || !constrained[d])
            m_freeIndex[d] = std::int64_t(m_freeDofs.size()), m_freeDofs.push_back(std::int64_t(d));
}

Eigen::SparseMatrix<double> SparseDirect::copy(const BlockSparseMatrix& matrix) const
{
    const bool lowerOnly = m_kind == Kind::SymmetricCholesky;
    std::vector<Eigen::Triplet<double>> entries;
    entries.reserve(matrix.blockCount() * (lowerOnly ? 5 : 9));
    const auto& rowStart = matrix.rowStart();
    const auto& columns = matrix.columns();
    for (std::size_t row = 0; row + 1 < rowStart.size(); ++row)
        for (std::uint32_t s = rowStart[row]; s < rowStart[row + 1]; ++s)
        {
            const std::size_t column = columns[s];
            if (lowerOnly && column > row)
                continue;
            // The Cholesky kind factorises the symmetric part (A + A^T) / 2 (A itself when A is symmetric).
            const Eigen::Matrix3d block =
                lowerOnly ? Eigen::Matrix3d(0.5 * (matrix.blocks()[s] + matrix.block(matrix.slotOf(column, row)).transpose()))
                          : matrix.blocks()[s];
            for (int a = 0; a < 3; ++a)
                for (int b = 0; b < 3; ++b)
                {
                    const std::int64_t r = m_freeIndex[3 * row + std::size_t(a)], c = m_freeIndex[3 * column + std::size_t(b)];
                    if (r >= 0 && c >= 0 && (!lowerOnly || r >= c))
                        entries.emplace_back(Eigen::Index(r), Eigen::Index(c), block(a, b));
                }
        }
    Eigen::SparseMatrix<double> out(Eigen::Index(m_freeDofs.size()), Eigen::Index(m_freeDofs.size()));
    out.setFromTriplets(entries.begin(), entries.end());
    return out;
}

bool SparseDirect::factorize(const BlockSparseMatrix& matrix)
{
    m_matrix = copy(matrix);
    m_matrix.makeCompressed();
    if (m_kind == Kind::SymmetricCholesky)
    {
        if (!m_analysed)
            m_factors->cholesky.analyzePattern(m_matrix), m_analysed = true;
        m_factors->cholesky.factorize(m_matrix);
        return m_factors->cholesky.info() == Eigen::Success;
    }
    if (!m_analysed)
        m_factors->lu.analyzePattern(m_matrix), m_analysed = true;
    m_factors->lu.factorize(m_matrix);
    return m_factors->lu.info() == Eigen::Success;
}

double SparseDirect::solve(const Eigen::VectorXd& b, Eigen::VectorXd& x) const
{
    Eigen::VectorXd freeB(Eigen::Index(m_freeDofs.size()));
    for (std::size_t f = 0; f < m_freeDofs.size(); ++f)
        freeB[Eigen::Index(f)] = b[Eigen::Index(m_freeDofs[f])];
    Eigen::VectorXd freeX, check;
    if (m_kind == Kind::SymmetricCholesky)
    {
        freeX = m_factors->cholesky.solve(freeB);
        check = m_matrix.selfadjointView<Eigen::Lower>() * freeX - freeB;
    }
    else
    {
        freeX = m_factors->lu.solve(freeB);
        check = m_matrix * freeX - freeB;
    }
    x = Eigen::VectorXd::Zero(b.size());
    for (std::size_t f = 0; f < m_freeDofs.size(); ++f)
        x[Eigen::Index(m_freeDofs[f])] = freeX[Eigen::Index(f)];
    const double norm = freeB.norm();
    return norm > 0.0 ? check.norm() / norm : check.norm();
}

} // namespace vsim::sim::fem
