#include "vsim/sim/fem/CorotationalFem.h"

#include "vsim/core/Error.h"
#include "vsim/sim/fem/RotationExtraction.h"
#include "vsim/sim/fem/StVenantKirchhoff.h"
#include "vsim/sim/fem/TetElement.h"

#include <Eigen/Eigenvalues>

#include <cmath>
#include <limits>
#include <string>

namespace vsim::sim::fem {
namespace {

/// Where block (a, b) of an element's 4 x 4 blocks is stored among its 10 distinct ones, and whether transposed.
struct StoredBlock
{
    int index;
    bool transposed;
};

constexpr StoredBlock storedBlock(int a, int b)
{
    return a == b ? StoredBlock{a, false} : StoredBlock{kUpperBlockIndex[a][b], a > b};
}

} // namespace

CorotationalFem::CorotationalFem(std::vector<Eigen::Vector3d> restPositions, std::vector<std::array<int, 4>> tets,
                                 const ElasticMaterial& material)
    : m_rest(std::move(restPositions)), m_tets(std::move(tets)), m_material(material)
{
    m_material.validate();
    m_svk = m_material.model == ElasticMaterial::Model::StVenantKirchhoff;
    m_lambda = m_material.lambda();
    m_mu = m_material.mu();
    if (m_tets.empty())
        throw Error("the mesh has no elements");
    m_elements.reserve(m_tets.size());
    m_mass = Eigen::VectorXd::Zero(Eigen::Index(3 * m_rest.size()));
    for (std::size_t t = 0; t < m_tets.size(); ++t)
    {
        std::array<Eigen::Vector3d, 4> corners;
        for (int a = 0; a < 4; ++a)
        {
            const int node = m_tets[t][std::size_t(a)];
            if (node < 0 || std::size_t(node) >= m_rest.size())
                throw Error(Pattern{"element %1 refers to node %2 of %3",
                                    {std::to_string(t), std::to_string(node), std::to_string(m_rest.size())}});
            corners[std::size_t(a)] = m_rest[std::size_t(node)];
        }
        try
        {
            m_elements.push_back(restTetrahedron(corners, m_material));
        }
        catch (const Error& error)
        {
            throw Error(Pattern{"element %1: %2", {std::to_string(t), error.what()}});
        }
        const double quarter = 0.25 * m_material.densityKgPerM3 * m_elements.back().volume;
        for (int node : m_tets[t])
            m_mass.segment<3>(3 * node).array() += quarter;
    }
    m_rotations.assign(m_tets.size(), Eigen::Quaterniond::Identity());
    m_rotatedBlocks.resize(m_tets.size());
    m_elementForces.assign(m_tets.size(), Vector12d::Zero());
    m_inverted.assign(m_tets.size(), 0);
    m_pattern = BlockSparseMatrix(m_rest.size(), m_tets);
    // Gather lists: counting sort of the element entries by matrix block and by node.
    m_blockEntryStart.assign(m_pattern.blockCount() + 1, 0);
    m_nodeEntryStart.assign(m_rest.size() + 1, 0);
    for (std::size_t t = 0; t < m_tets.size(); ++t)
        for (int a = 0; a < 4; ++a)
        {
            ++m_nodeEntryStart[std::size_t(m_tets[t][std::size_t(a)]) + 1];
            for (int b = 0; b < 4; ++b)
                ++m_blockEntryStart[m_pattern.slot(t, a, b) + 1];
        }
    for (std::size_t s = 0; s < m_pattern.blockCount(); ++s)
        m_blockEntryStart[s + 1] += m_blockEntryStart[s];
    for (std::size_t n = 0; n < m_rest.size(); ++n)
        m_nodeEntryStart[n + 1] += m_nodeEntryStart[n];
    m_blockEntries.resize(m_blockEntryStart.back());
    m_nodeEntries.resize(m_nodeEntryStart.back());
    std::vector<std::uint32_t> blockFill(m_blockEntryStart.begin(), m_blockEntryStart.end() - 1);
    std::vector<std::uint32_t> nodeFill(m_nodeEntryStart.begin(), m_nodeEntryStart.end() - 1);
    for (std::size_t t = 0; t < m_tets.size(); ++t)
        for (int a = 0; a < 4; ++a)
        {
            m_nodeEntries[nodeFill[std::size_t(m_tets[t][std::size_t(a)])]++] = std::uint32_t(4 * t + std::size_t(a));
            for (int b = 0; b < 4; ++b)
                m_blockEntries[blockFill[m_pattern.slot(t, a, b)]++] = std::uint32_t(16 * t + std::size_t(4 * a + b));
        }
    m_positions.resize(Eigen::Index(3 * m_rest.size()));
    for (std::size_t n = 0; n < m_rest.size(); ++n)
        m_positions.segment<3>(Eigen::Index(3 * n)) = m_rest[n];
    m_velocities = Eigen::VectorXd::Zero(m_positions.size());
}

std::size_t CorotationalFem::updateElements()
{
    std::size_t inverted = 0;
#pragma omp parallel for reduction(+ : inverted) schedule(static)
    for (std::ptrdiff_t t = 0; t < std::ptrdiff_t(m_tets.size()); ++t)
    {
        const std::size_t e = std::size_t(t);
        const auto& tet = m_tets[e];
        const Eigen::Vector3d x0 = m_positions.segment<3>(3 * tet[0]);
        Eigen::Matrix3d edges;
        edges << m_positions.segment<3>(3 * tet[1]) - x0, m_positions.segment<3>(3 * tet[2]) - x0,
            m_positions.segment<3>(3 * tet[3]) - x0;
        const Eigen::Matrix3d deformation = edges * m_elements[e].restEdgesInverse;
        m_inverted[e] = deformation.determinant() <= 0.0;
        if (m_inverted[e])
            ++inverted;
        else
            extractRotation(deformation, m_rotations[e]);
        if (m_svk)
        {
            stVenantKirchhoffElement(deformation, m_elements[e].gradients, m_elements[e].volume, m_lambda, m_mu,
                                     m_elementForces[e], m_rotatedBlocks[e]);
            continue;
        }
        const Eigen::Matrix3d r = m_rotations[e].toRotationMatrix();
        const Matrix12d& k = m_elements[e].stiffness;
        const Vector12d f = k.lazyProduct(corotatedDisplacement(e, r)); // small fixed size: no GEMV kernel
        std::array<Eigen::Matrix3d, 10>& blocks = m_rotatedBlocks[e];
        for (int a = 0; a < 4; ++a)
            blocks[std::size_t(a)].setZero();
        for (int a = 0; a < 4; ++a)
        {
            m_elementForces[e].segment<3>(3 * a).noalias() = -(r * f.segment<3>(3 * a));
            for (int b = a + 1; b < 4; ++b)
            {
                Eigen::Matrix3d& block = blocks[std::size_t(kUpperBlockIndex[a][b])];
                block.noalias() = r * (k.block<3, 3>(3 * a, 3 * b) * r.transpose());
                blocks[std::size_t(a)] -= block;
                blocks[std::size_t(b)] -= block.transpose();
            }
        }
    }
    return inverted;
}

Eigen::Vector3d CorotationalFem::firstInvertedCentroid() const
{
    for (std::size_t t = 0; t < m_tets.size(); ++t)
        if (m_inverted[t])
        {
            Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
            for (int node : m_tets[t])
                centroid += 0.25 * m_positions.segment<3>(3 * node);
            return centroid;
        }
    return Eigen::Vector3d::Constant(std::numeric_limits<double>::quiet_NaN());
}

Vector12d CorotationalFem::corotatedDisplacement(std::size_t t, const Eigen::Matrix3d& rotation) const
{
    Vector12d u;
    for (int a = 0; a < 4; ++a)
    {
        const int node = m_tets[t][std::size_t(a)];
        u.segment<3>(3 * a) = rotation.transpose() * m_positions.segment<3>(3 * node) - m_rest[std::size_t(node)];
    }
    return u;
}

Eigen::VectorXd CorotationalFem::elasticForces() const
{
    Eigen::VectorXd forces(m_positions.size());
#pragma omp parallel for schedule(static)
    for (std::ptrdiff_t n = 0; n < std::ptrdiff_t(m_rest.size()); ++n)
    {
        Eigen::Vector3d sum = Eigen::Vector3d::Zero();
        for (std::uint32_t i = m_nodeEntryStart[std::size_t(n)]; i < m_nodeEntryStart[std::size_t(n) + 1]; ++i)
            sum += m_elementForces[m_nodeEntries[i] / 4].segment<3>(3 * (m_nodeEntries[i] % 4));
        forces.segment<3>(3 * n) = sum;
    }
    return forces;
}

void CorotationalFem::assemble(BlockSparseMatrix& matrix, double massFactor, double stiffnessFactor) const
{
    if (matrix.nodeCount() != nodeCount() || matrix.blockCount() != m_pattern.blockCount())
        throw Error("the matrix does not have this mesh's pattern");
#pragma omp parallel for schedule(static)
    for (std::ptrdiff_t s = 0; s < std::ptrdiff_t(m_pattern.blockCount()); ++s)
    {
        Eigen::Matrix3d sum = Eigen::Matrix3d::Zero();
        for (std::uint32_t i = m_blockEntryStart[std::size_t(s)]; i < m_blockEntryStart[std::size_t(s) + 1]; ++i)
        {
            const std::uint32_t local = m_blockEntries[i] % 16;
            const StoredBlock stored = storedBlock(int(local / 4), int(local % 4));
            const Eigen::Matrix3d& block = m_rotatedBlocks[m_blockEntries[i] / 16][std::size_t(stored.index)];
            if (stored.transposed)
                sum += block.transpose();
            else
                sum += block;
        }
        matrix.block(std::uint32_t(s)) = stiffnessFactor * sum;
    }
    for (std::size_t n = 0; n < nodeCount(); ++n)
        matrix.diagonal(n).diagonal().array() += massFactor * m_mass[Eigen::Index(3 * n)];
}

void CorotationalFem::addRotationStiffness(BlockSparseMatrix& matrix) const
{
    if (m_svk)
        return;
    if (matrix.nodeCount() != nodeCount() || matrix.blockCount() != m_pattern.blockCount())
        throw Error("the matrix does not have this mesh's pattern");
    const auto skew = [](const Eigen::Vector3d& v) {
        Eigen::Matrix3d m;
        m << 0.0, -v.z(), v.y(), v.z(), 0.0, -v.x(), -v.y(), v.x(), 0.0;
        return m;
    };
    for (std::size_t e = 0; e < m_tets.size(); ++e)
    {
        if (m_inverted[e])
            continue;
        const auto& tet = m_tets[e];
        const Eigen::Matrix3d r = m_rotations[e].toRotationMatrix();
        const Matrix12d& k = m_elements[e].stiffness;
        Vector12d rotated; // R^T x per node
        for (int a = 0; a < 4; ++a)
            rotated.segment<3>(3 * a) = r.transpose() * m_positions.segment<3>(3 * tet[std::size_t(a)]);
        const Vector12d ku = k.lazyProduct(corotatedDisplacement(e, r));
        // S = R^T F with F = sum_a x_a g_a^T.
        Eigen::Matrix3d s = Eigen::Matrix3d::Zero();
        for (int a = 0; a < 4; ++a)
            s += rotated.segment<3>(3 * a) * m_elements[e].gradients.row(a);
        const Eigen::Matrix3d lambda = s.trace() * Eigen::Matrix3d::Identity() - s;
        if (std::abs(lambda.determinant()) < 1e-12)
            continue;
        const Eigen::Matrix3d lambdaInverse = lambda.inverse();
        // C (12 x 3): node a's rows -[K u]_a x + sum_m K_am [R^T x_m]x.
        Eigen::Matrix<double, 12, 3> c;
        for (int a = 0; a < 4; ++a)
        {
            Eigen::Matrix3d rows = -skew(ku.segment<3>(3 * a));
            for (int m = 0; m < 4; ++m)
                rows += k.block<3, 3>(3 * a, 3 * m) * skew(rotated.segment<3>(3 * m));
            c.block<3, 3>(3 * a, 0) = rows;
        }
        for (int b = 0; b < 4; ++b)
        {
            const Eigen::Matrix3d spin = lambdaInverse * skew(m_elements[e].gradients.row(b).transpose()) * r.transpose();
            for (int a = 0; a < 4; ++a)
                matrix.block(m_pattern.slot(e, a, b)) += r * (c.block<3, 3>(3 * a, 0) * spin);
        }
    }
}

std::vector<double> CorotationalFem::elementEnergies() const
{
    std::vector<double> energies(m_tets.size());
#pragma omp parallel for schedule(static)
    for (std::ptrdiff_t t = 0; t < std::ptrdiff_t(m_tets.size()); ++t)
    {
        const std::size_t e = std::size_t(t);
        if (m_svk)
        {
            energies[e] = stVenantKirchhoffEnergy(deformation(e), m_elements[e].volume, m_lambda, m_mu);
            continue;
        }
        const Vector12d u = corotatedDisplacement(e, m_rotations[e].toRotationMatrix());
        energies[e] = 0.5 * u.dot(m_elements[e].stiffness * u);
    }
    return energies;
}

double CorotationalFem::elasticEnergy() const
{
    const std::vector<double> energies = elementEnergies();
    double energy = 0.0;
    for (double e : energies)
        energy += e;
    return energy;
}

double CorotationalFem::kineticEnergy() const
{
    return 0.5 * m_velocities.dot(m_mass.cwiseProduct(m_velocities));
}

Eigen::Matrix3d CorotationalFem::deformation(std::size_t e) const
{
    const auto& tet = m_tets[e];
    const Eigen::Vector3d x0 = m_positions.segment<3>(3 * tet[0]);
    Eigen::Matrix3d edges;
    edges << m_positions.segment<3>(3 * tet[1]) - x0, m_positions.segment<3>(3 * tet[2]) - x0,
        m_positions.segment<3>(3 * tet[3]) - x0;
    return edges * m_elements[e].restEdgesInverse;
}

Eigen::Matrix3d CorotationalFem::elementStress(std::size_t e) const
{
    if (m_svk)
        return stVenantKirchhoffCauchy(deformation(e), m_lambda, m_mu);
    const Eigen::Matrix3d r = m_rotations[e].toRotationMatrix();
    const Eigen::Matrix<double, 6, 1> s =
        m_material.elasticityMatrix() * (strainDisplacement(m_elements[e].gradients) * corotatedDisplacement(e, r));
    Eigen::Matrix3d local;
    local << s[0], s[3], s[5], s[3], s[1], s[4], s[5], s[4], s[2];
    return r * local * r.transpose();
}

ElementStresses CorotationalFem::elementStresses() const
{
    std::vector<Eigen::Matrix3d> tensors(m_tets.size());
#pragma omp parallel for schedule(static)
    for (std::ptrdiff_t t = 0; t < std::ptrdiff_t(m_tets.size()); ++t)
        tensors[std::size_t(t)] = elementStress(std::size_t(t));
    return elementStressesFrom(std::move(tensors));
}

std::vector<double> CorotationalFem::elementVonMises() const
{
    std::vector<double> vonMises(m_tets.size());
#pragma omp parallel for schedule(static)
    for (std::ptrdiff_t t = 0; t < std::ptrdiff_t(m_tets.size()); ++t)
        vonMises[std::size_t(t)] = vonMisesOf(elementStress(std::size_t(t)));
    return vonMises;
}

} // namespace vsim::sim::fem
