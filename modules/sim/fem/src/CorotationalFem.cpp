#include "vsim/sim/fem/CorotationalFem.h"

#include "vsim/core/Error.h"
#include "vsim/sim/fem/RotationExtraction.h"

#include <Eigen/Eigenvalues>

#include <cmath>
#include <string>

namespace vsim::sim::fem {

CorotationalFem::CorotationalFem(std::vector<Eigen::Vector3d> restPositions, std::vector<std::array<int, 4>> tets,
                                 const ElasticMaterial& material)
    : m_rest(std::move(restPositions)), m_tets(std::move(tets)), m_material(material)
{
    m_material.validate();
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
                throw Error("element " + std::to_string(t) + " refers to node " + std::to_string(node) + " of " +
                            std::to_string(m_rest.size()));
            corners[std::size_t(a)] = m_rest[std::size_t(node)];
        }
        try
        {
            m_elements.push_back(restTetrahedron(corners, m_material));
        }
        catch (const Error& error)
        {
            throw Error("element " + std::to_string(t) + ": " + error.what());
        }
        const double quarter = 0.25 * m_material.densityKgPerM3 * m_elements.back().volume;
        for (int node : m_tets[t])
            m_mass.segment<3>(3 * node).array() += quarter;
    }
    m_rotations.assign(m_tets.size(), Eigen::Quaterniond::Identity());
    m_positions.resize(Eigen::Index(3 * m_rest.size()));
    for (std::size_t n = 0; n < m_rest.size(); ++n)
        m_positions.segment<3>(Eigen::Index(3 * n)) = m_rest[n];
    m_velocities = Eigen::VectorXd::Zero(m_positions.size());
}

std::size_t CorotationalFem::updateRotations()
{
    std::size_t inverted = 0;
#pragma omp parallel for reduction(+ : inverted) schedule(static)
    for (std::ptrdiff_t t = 0; t < std::ptrdiff_t(m_tets.size()); ++t)
    {
        const auto& tet = m_tets[std::size_t(t)];
        const Eigen::Vector3d x0 = m_positions.segment<3>(3 * tet[0]);
        Eigen::Matrix3d edges;
        edges << m_positions.segment<3>(3 * tet[1]) - x0, m_positions.segment<3>(3 * tet[2]) - x0,
            m_positions.segment<3>(3 * tet[3]) - x0;
        const Eigen::Matrix3d deformation = edges * m_elements[std::size_t(t)].restEdgesInverse;
        if (deformation.determinant() <= 0.0)
        {
            ++inverted;
            continue;
        }
        extractRotation(deformation, m_rotations[std::size_t(t)]);
    }
    return inverted;
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
    Eigen::VectorXd forces = Eigen::VectorXd::Zero(m_positions.size());
    // Scatter per node would race: compute per element, then add serially (cheap next to the element pass).
    std::vector<Vector12d> elementForces(m_tets.size());
#pragma omp parallel for schedule(static)
    for (std::ptrdiff_t t = 0; t < std::ptrdiff_t(m_tets.size()); ++t)
    {
        const Eigen::Matrix3d r = m_rotations[std::size_t(t)].toRotationMatrix();
        const Vector12d f = m_elements[std::size_t(t)].stiffness * corotatedDisplacement(std::size_t(t), r);
        Vector12d rotated;
        for (int a = 0; a < 4; ++a)
            rotated.segment<3>(3 * a) = -(r * f.segment<3>(3 * a));
        elementForces[std::size_t(t)] = rotated;
    }
    for (std::size_t t = 0; t < m_tets.size(); ++t)
        for (int a = 0; a < 4; ++a)
            forces.segment<3>(3 * m_tets[t][std::size_t(a)]) += elementForces[t].segment<3>(3 * a);
    return forces;
}

void CorotationalFem::assemble(BlockSparseMatrix& matrix, double massFactor, double stiffnessFactor) const
{
    if (matrix.nodeCount() != nodeCount())
        throw Error("the matrix does not have this mesh's pattern");
    matrix.setZero();
    // Rotated element blocks in parallel, added serially through the precomputed slots.
    std::vector<std::array<Eigen::Matrix3d, 16>> rotatedBlocks(m_tets.size());
#pragma omp parallel for schedule(static)
    for (std::ptrdiff_t t = 0; t < std::ptrdiff_t(m_tets.size()); ++t)
    {
        const Eigen::Matrix3d r = m_rotations[std::size_t(t)].toRotationMatrix();
        const Matrix12d& k = m_elements[std::size_t(t)].stiffness;
        for (int a = 0; a < 4; ++a)
            for (int b = 0; b < 4; ++b)
                rotatedBlocks[std::size_t(t)][std::size_t(4 * a + b)].noalias() =
                    stiffnessFactor * (r * k.block<3, 3>(3 * a, 3 * b) * r.transpose());
    }
    for (std::size_t t = 0; t < m_tets.size(); ++t)
        for (int a = 0; a < 4; ++a)
            for (int b = 0; b < 4; ++b)
                matrix.block(matrix.slot(t, a, b)) += rotatedBlocks[t][std::size_t(4 * a + b)];
    for (std::size_t n = 0; n < nodeCount(); ++n)
        matrix.diagonal(n).diagonal().array() += massFactor * m_mass[Eigen::Index(3 * n)];
}

double CorotationalFem::elasticEnergy() const
{
    double energy = 0.0;
#pragma omp parallel for reduction(+ : energy) schedule(static)
    for (std::ptrdiff_t t = 0; t < std::ptrdiff_t(m_tets.size()); ++t)
    {
        const Vector12d u = corotatedDisplacement(std::size_t(t), m_rotations[std::size_t(t)].toRotationMatrix());
        energy += 0.5 * u.dot(m_elements[std::size_t(t)].stiffness * u);
    }
    return energy;
}

double CorotationalFem::kineticEnergy() const
{
    return 0.5 * m_velocities.dot(m_mass.cwiseProduct(m_velocities));
}

ElementStresses CorotationalFem::elementStresses() const
{
    ElementStresses out;
    out.vonMises.resize(m_tets.size());
    out.maxPrincipal.resize(m_tets.size());
    out.tensors.resize(m_tets.size());
    const Eigen::Matrix<double, 6, 6> d = m_material.elasticityMatrix();
#pragma omp parallel for schedule(static)
    for (std::ptrdiff_t t = 0; t < std::ptrdiff_t(m_tets.size()); ++t)
    {
        const std::size_t e = std::size_t(t);
        const Eigen::Matrix3d r = m_rotations[e].toRotationMatrix();
        const Eigen::Matrix<double, 6, 1> s = d * (strainDisplacement(m_elements[e].gradients) * corotatedDisplacement(e, r));
        Eigen::Matrix3d local;
        local << s[0], s[3], s[5], s[3], s[1], s[4], s[5], s[4], s[2];
        out.tensors[e] = r * local * r.transpose();
        out.vonMises[e] = std::sqrt(0.5 * ((s[0] - s[1]) * (s[0] - s[1]) + (s[1] - s[2]) * (s[1] - s[2]) +
                                           (s[2] - s[0]) * (s[2] - s[0])) +
                                    3.0 * (s[3] * s[3] + s[4] * s[4] + s[5] * s[5]));
        out.maxPrincipal[e] = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(local, Eigen::EigenvaluesOnly).eigenvalues()[2];
    }
    return out;
}

} // namespace vsim::sim::fem
