#include "vsim/sim/fem/QuadraticFem.h"

#include "vsim/core/Error.h"

#include <Eigen/Eigenvalues>
#include <Eigen/LU>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace vsim::sim::fem {
namespace {

/// Greedy colouring: each element takes the lowest colour none of its nodes' earlier elements has.
std::vector<std::vector<std::uint32_t>> colourElements(const std::vector<std::array<int, 10>>& elements,
                                                       std::size_t nodeCount)
{
    std::vector<std::vector<std::uint32_t>> colours;
    std::vector<std::vector<std::uint16_t>> nodeColours(nodeCount);
    std::vector<std::uint8_t> taken;
    for (std::size_t e = 0; e < elements.size(); ++e)
    {
        taken.assign(colours.size() + 1, 0);
        for (int node : elements[e])
            for (std::uint16_t c : nodeColours[std::size_t(node)])
                taken[c] = 1;
        const std::size_t colour = std::size_t(std::find(taken.begin(), taken.end(), 0) - taken.begin());
        if (colour == colours.size())
            colours.emplace_back();
        colours[colour].push_back(std::uint32_t(e));
        for (int node : elements[e])
            nodeColours[std::size_t(node)].push_back(std::uint16_t(colour));
    }
    return colours;
}

/// The positive semi-definite part of a symmetric matrix: its negative eigenvalues set to zero.
template <int N>
Eigen::Matrix<double, N, N> positivePart(const Eigen::Matrix<double, N, N>& m)
{
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, N, N>> eigen(m);
    if (eigen.eigenvalues().minCoeff() >= 0.0)
        return m;
    return eigen.eigenvectors() * eigen.eigenvalues().cwiseMax(0.0).asDiagonal() * eigen.eigenvectors().transpose();
}

/// B_a (6x3): the Green strain's variation (Voigt, engineering shear) by node a's displacement.
Eigen::Matrix<double, 6, 3> strainVariation(const Eigen::Matrix3d& f, const Eigen::RowVector3d& g)
{
    Eigen::Matrix<double, 6, 3> b;
    b.row(0) = g[0] * f.col(0).transpose();
    b.row(1) = g[1] * f.col(1).transpose();
    b.row(2) = g[2] * f.col(2).transpose();
    b.row(3) = g[1] * f.col(0).transpose() + g[0] * f.col(1).transpose();
    b.row(4) = g[2] * f.col(1).transpose() + g[1] * f.col(2).transpose();
    b.row(5) = g[0] * f.col(2).transpose() + g[2] * f.col(0).transpose();
    return b;
}

} // namespace

QuadraticFem::QuadraticFem(QuadraticTetMesh mesh, std::vector<HyperelasticMaterial> materials,
                           std::vector<std::uint8_t> elementMaterial)
    : m_mesh(std::move(mesh)), m_materials(std::move(materials)), m_elementMaterial(std::move(elementMaterial))
{
    if (m_materials.empty())
        throw Error("the quadratic wall model needs a material");
    for (const HyperelasticMaterial& material : m_materials)
        material.validate();
    if (m_elementMaterial.empty())
        m_elementMaterial.assign(m_mesh.elements.size(), 0);
    if (m_elementMaterial.size() != m_mesh.elements.size())
        throw Error(Pattern{"the quadratic wall model has %1 material indices for %2 elements",
                            {std::to_string(m_elementMaterial.size()), std::to_string(m_mesh.elements.size())}});
    m_rest.resize(m_mesh.elements.size());
    for (std::size_t e = 0; e < m_mesh.elements.size(); ++e)
    {
        if (m_elementMaterial[e] >= m_materials.size())
            throw Error(Pattern{"element %1 has material %2 of %3",
                                {std::to_string(e), std::to_string(m_elementMaterial[e]),
                                 std::to_string(m_materials.size())}});
        const auto& element = m_mesh.elements[e];
        for (int node : element)
            if (node < 0 || std::size_t(node) >= m_mesh.points.size())
                throw Error(Pattern{"element %1 refers to node %2 of %3",
                                    {std::to_string(e), std::to_string(node), std::to_string(m_mesh.points.size())}});
        const Eigen::Vector3d x0 = m_mesh.points[std::size_t(element[0])];
        Eigen::Matrix3d edges;
        for (int c = 1; c < 4; ++c)
            edges.col(c - 1) = m_mesh.points[std::size_t(element[std::size_t(c)])] - x0;
        const double volume = edges.determinant() / 6.0;
        const double scale = std::max({edges.col(0).norm(), edges.col(1).norm(), edges.col(2).norm()});
        if (!(volume > 1e-6 * scale * scale * scale))
            throw Error(Pattern{"quadratic element %1 is degenerate or inverted (volume %2 m^3)",
                                {std::to_string(e), std::to_string(volume)}});
        // Rows 1-3 of the gradients: the rows of edges^-1; row 0 minus their sum.
        const Eigen::Matrix3d inverse = edges.inverse();
        m_rest[e].gradients.bottomRows<3>() = inverse;
        m_rest[e].gradients.row(0) = -inverse.colwise().sum();
        m_rest[e].volume = volume;
    }
    m_colours = colourElements(m_mesh.elements, m_mesh.points.size());
    m_pattern = BlockSparseMatrix(m_mesh.points.size(), m_mesh.elements);
    m_positions.resize(Eigen::Index(3 * m_mesh.points.size()));
    for (std::size_t i = 0; i < m_mesh.points.size(); ++i)
        m_positions.segment<3>(Eigen::Index(3 * i)) = m_mesh.points[i];
    m_forces = Eigen::VectorXd::Zero(m_positions.size());
    m_inverted.assign(m_mesh.elements.size(), 0);
}

Eigen::Matrix<double, 3, 10> QuadraticFem::elementPositions(std::size_t e) const
{
    Eigen::Matrix<double, 3, 10> x;
    for (int a = 0; a < 10; ++a)
        x.col(a) = m_positions.segment<3>(3 * Eigen::Index(m_mesh.elements[e][std::size_t(a)]));
    return x;
}

std::size_t QuadraticFem::updateElements()
{
    m_forces.setZero();
    std::size_t inverted = 0;
    for (const auto& colour : m_colours)
    {
#pragma omp parallel for schedule(static) reduction(+ : inverted)
        for (std::ptrdiff_t i = 0; i < std::ptrdiff_t(colour.size()); ++i)
        {
            const std::size_t e = colour[std::size_t(i)];
            const Eigen::Matrix<double, 3, 10> x = elementPositions(e);
            const HyperelasticMaterial& material = m_materials[m_elementMaterial[e]];
            Eigen::Matrix<double, 3, 10> forces = Eigen::Matrix<double, 3, 10>::Zero();
            bool bad = false;
            for (const Eigen::Vector4d& l : tetQuadraturePoints())
            {
                const Eigen::Matrix<double, 10, 3> g = quadraticShapeGradients(m_rest[e].gradients, l);
                const Eigen::Matrix3d f = x * g;
                if (!(f.determinant() > 0.0))
                {
                    bad = true;
                    break;
                }
                const Vector6d s = material.stress(f.transpose() * f);
                const double weight = 0.25 * m_rest[e].volume;
                for (int a = 0; a < 10; ++a)
                    forces.col(a) -= weight * strainVariation(f, g.row(a)).transpose() * s;
            }
            m_inverted[e] = bad ? 1 : 0;
            if (bad)
            {
                ++inverted;
                continue;
            }
            for (int a = 0; a < 10; ++a)
                m_forces.segment<3>(3 * Eigen::Index(m_mesh.elements[e][std::size_t(a)])) += forces.col(a);
        }
    }
    return inverted;
}

Eigen::Vector3d QuadraticFem::firstInvertedCentroid() const
{
    for (std::size_t e = 0; e < m_inverted.size(); ++e)
        if (m_inverted[e])
            return elementPositions(e).leftCols<4>().rowwise().mean();
    return Eigen::Vector3d::Constant(std::numeric_limits<double>::quiet_NaN());
}

void QuadraticFem::assembleTangent(BlockSparseMatrix& matrix, bool) const
{
    assemble(matrix, false);
}

void QuadraticFem::assembleDefiniteTangent(BlockSparseMatrix& matrix, bool) const
{
    assemble(matrix, true);
}

void QuadraticFem::assemble(BlockSparseMatrix& matrix, bool definite) const
{
    matrix.setZero();
    for (const auto& colour : m_colours)
    {
#pragma omp parallel for schedule(dynamic, 64)
        for (std::ptrdiff_t i = 0; i < std::ptrdiff_t(colour.size()); ++i)
        {
            const std::size_t e = colour[std::size_t(i)];
            if (m_inverted[e])
                continue;
            const Eigen::Matrix<double, 3, 10> x = elementPositions(e);
            const HyperelasticMaterial& material = m_materials[m_elementMaterial[e]];
            const double weight = 0.25 * m_rest[e].volume;
            std::array<Eigen::Matrix3d, 55> upper; // blocks (a, b), a <= b, row by row
            upper.fill(Eigen::Matrix3d::Zero());
            for (const Eigen::Vector4d& l : tetQuadraturePoints())
            {
                const Eigen::Matrix<double, 10, 3> g = quadraticShapeGradients(m_rest[e].gradients, l);
                const Eigen::Matrix3d f = x * g;
                Matrix6d tangent;
                Eigen::Matrix3d s = fromVoigt(material.stress(f.transpose() * f, &tangent));
                if (definite)
                    s = positivePart<3>(s), tangent = positivePart<6>(tangent);
                std::array<Eigen::Matrix<double, 6, 3>, 10> b, db;
                for (int a = 0; a < 10; ++a)
                    b[std::size_t(a)] = strainVariation(f, g.row(a)), db[std::size_t(a)] = weight * tangent * b[std::size_t(a)];
                const Eigen::Matrix<double, 10, 10> geometric = weight * g * s * g.transpose();
                std::size_t k = 0;
                for (int a = 0; a < 10; ++a)
                    for (int c = a; c < 10; ++c, ++k)
                    {
                        upper[k].noalias() += b[std::size_t(a)].transpose() * db[std::size_t(c)];
                        upper[k].diagonal().array() += geometric(a, c);
                    }
            }
            std::size_t k = 0;
            for (int a = 0; a < 10; ++a)
                for (int c = a; c < 10; ++c, ++k)
                {
                    matrix.block(matrix.slot(e, a, c)) += upper[k];
                    if (c != a)
                        matrix.block(matrix.slot(e, c, a)) += upper[k].transpose();
                }
        }
    }
}

double QuadraticFem::elasticEnergy() const
{
    double energy = 0.0;
#pragma omp parallel for schedule(static) reduction(+ : energy)
    for (std::ptrdiff_t i = 0; i < std::ptrdiff_t(m_mesh.elements.size()); ++i)
    {
        const std::size_t e = std::size_t(i);
        const Eigen::Matrix<double, 3, 10> x = elementPositions(e);
        for (const Eigen::Vector4d& l : tetQuadraturePoints())
        {
            const Eigen::Matrix3d f = x * quadraticShapeGradients(m_rest[e].gradients, l);
            energy += 0.25 * m_rest[e].volume * m_materials[m_elementMaterial[e]].energyDensity(f.transpose() * f);
        }
    }
    return energy;
}

ElementStresses QuadraticFem::elementStresses() const
{
    std::vector<Eigen::Matrix3d> tensors(m_mesh.elements.size());
#pragma omp parallel for schedule(static)
    for (std::ptrdiff_t i = 0; i < std::ptrdiff_t(m_mesh.elements.size()); ++i)
    {
        const std::size_t e = std::size_t(i);
        const Eigen::Matrix<double, 3, 10> x = elementPositions(e);
        Eigen::Matrix3d mean = Eigen::Matrix3d::Zero();
        for (const Eigen::Vector4d& l : tetQuadraturePoints())
        {
            const Eigen::Matrix3d f = x * quadraticShapeGradients(m_rest[e].gradients, l);
            const Eigen::Matrix3d s = fromVoigt(m_materials[m_elementMaterial[e]].stress(f.transpose() * f));
            mean += 0.25 * f * s * f.transpose() / f.determinant();
        }
        tensors[e] = mean;
    }
    return elementStressesFrom(std::move(tensors));
}

} // namespace vsim::sim::fem
