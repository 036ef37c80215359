#pragma once

// The FEM model of the vessel wall (thesis ch. 4.3-4.5), co-rotational linear by default (Mueller & Gross 2004,
// "Interactive virtual materials"): per element the rotation R of the deformation gradient (polar decomposition),
// the elastic force f_e = -R K_e (R^T x_e - X_e) and the stiffness R K_e R^T; optionally St. Venant-Kirchhoff
// (StVenantKirchhoff.h: forces and the consistent tangent from the Green strain); lumped (diagonal) mass (thesis eq. 4.12: a
// quarter of each element's mass on each node). State and parameters in SI: positions in m, forces in N.
// Time integration is separate (BackwardEuler.h).

#include "vsim/sim/fem/BlockSparseMatrix.h"
#include "vsim/sim/fem/ElasticMaterial.h"
#include "vsim/sim/fem/ElementStresses.h"
#include "vsim/sim/fem/TetElement.h"

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <array>
#include <cstdint>
#include <vector>

namespace vsim::sim::fem {

class CorotationalFem
{
public:
    /// Rest positions (m) and elements (positively oriented). Throws vsim::Error for a bad material, an index
    /// out of range, or a degenerate or inverted element (naming it).
    CorotationalFem(std::vector<Eigen::Vector3d> restPositions, std::vector<std::array<int, 4>> tets,
                    const ElasticMaterial& material);

    std::size_t nodeCount() const { return m_rest.size(); }
    std::size_t elementCount() const { return m_tets.size(); }
    const std::vector<std::array<int, 4>>& tets() const { return m_tets; }
    const std::vector<Eigen::Vector3d>& restPositions() const { return m_rest; }
    const ElasticMaterial& material() const { return m_material; }
    const std::vector<TetRest>& elements() const { return m_elements; }

    /// Current positions and velocities, 3 entries per node (m, m/s).
    Eigen::VectorXd& positions() { return m_positions; }
    const Eigen::VectorXd& positions() const { return m_positions; }
    Eigen::VectorXd& velocities() { return m_velocities; }
    const Eigen::VectorXd& velocities() const { return m_velocities; }
    /// Lumped mass per degree of freedom (kg), 3 equal entries per node.
    const Eigen::VectorXd& lumpedMass() const { return m_mass; }

    /// The element pass, one parallel sweep: every element's rotation from the current positions (warm-started),
    /// its elastic force -R K (R^T x - X) and its rotated stiffness blocks R K_ab R^T, kept for elasticForces()
    /// and assemble(). Returns the number of inverted elements (det F <= 0), whose rotation is left as it was.
    std::size_t updateElements();
    /// Whether element `tet` was inverted (det F <= 0) in the last element pass.
    bool isInverted(std::size_t tet) const { return m_inverted[tet] != 0; }
    /// Centroid (m, current positions) of the first inverted element of the last pass; NaN when none.
    Eigen::Vector3d firstInvertedCentroid() const;
    /// Elastic forces (N) of the last element pass, gathered per node.
    Eigen::VectorXd elasticForces() const;
    /// Adds what R K R^T leaves out of the co-rotational tangent d(R K (R^T x - X)) / dx: the derivative of the
    /// element rotations, R (-[K u]x + K [R^T x]x) Lambda^-1 [g_b]x R^T per block (a, b), with u = R^T x - X,
    /// Lambda = tr(S) I - S, S = R^T F and g_b the shape-function gradients (the polar decomposition's
    /// derivative, material spin omega = Lambda^-1 axial(R^T dF - dF^T R)). Not symmetric away from equilibrium;
    /// nothing for the St. Venant-Kirchhoff model (its tangent is already consistent) or inverted elements. Uses the
    /// last element pass; `matrix` must have this mesh's pattern.
    void addRotationStiffness(BlockSparseMatrix& matrix) const;
    /// Writes c_mass M + c_stiffness R K R^T (the last element pass) into `matrix`, which must have this mesh's
    /// pattern (makeMatrix()); gathered per matrix block, in parallel.
    void assemble(BlockSparseMatrix& matrix, double massFactor, double stiffnessFactor) const;
    /// The pattern of this mesh's matrices.
    BlockSparseMatrix makeMatrix() const { return m_pattern; }
    /// Elastic energy 1/2 sum_e u_e^T K_e u_e with u_e = R^T x_e - X_e (J).
    double elasticEnergy() const;
    /// The same per element (J).
    std::vector<double> elementEnergies() const;
    /// Kinetic energy 1/2 v^T M v (J).
    double kineticEnergy() const;
    ElementStresses elementStresses() const;
    /// Von Mises stress per element (Pa) alone (no eigen-decomposition: the interactive display's colours).
    std::vector<double> elementVonMises() const;
    /// Gather lists (see the members): for matrix block s, entries m_blockEntries[start[s] .. start[s + 1]).
    const std::vector<std::uint32_t>& blockEntryStart() const { return m_blockEntryStart; }
    const std::vector<std::uint32_t>& blockEntries() const { return m_blockEntries; }
    const std::vector<std::uint32_t>& nodeEntryStart() const { return m_nodeEntryStart; }
    const std::vector<std::uint32_t>& nodeEntries() const { return m_nodeEntries; }
    /// The rotation of element `tet`.
    Eigen::Matrix3d rotation(std::size_t tet) const { return m_rotations[tet].toRotationMatrix(); }

private:
    Vector12d corotatedDisplacement(std::size_t tet, const Eigen::Matrix3d& rotation) const;
    /// Cauchy stress (Pa) of element `tet` in the patient frame.
    Eigen::Matrix3d elementStress(std::size_t tet) const;
    /// Deformation gradient of element `tet` at the current positions.
    Eigen::Matrix3d deformation(std::size_t tet) const;

    std::vector<Eigen::Vector3d> m_rest;
    std::vector<std::array<int, 4>> m_tets;
    ElasticMaterial m_material;
    bool m_svk = false;        // St. Venant-Kirchhoff instead of co-rotational linear
    double m_lambda = 0.0, m_mu = 0.0;
    std::vector<TetRest> m_elements;
    std::vector<Eigen::Quaterniond> m_rotations;
    // The last element pass, and where its pieces go: per matrix block and per node, the (element, local) entries
    // that add up there (gathers instead of racing scatters; the CUDA backend uses the same lists).
    // The 10 distinct rotated blocks of each element: the 4 diagonal (a, a), then the 6 above it (a < b); the
    // blocks below are their transposes (K_e is symmetric) and each diagonal block is minus the sum of the
    // others in its row (K_e annihilates translations), so only the 6 off-diagonal products are computed.
    std::vector<std::array<Eigen::Matrix3d, 10>> m_rotatedBlocks;
    std::vector<Vector12d> m_elementForces;
    std::vector<std::uint8_t> m_inverted;
    BlockSparseMatrix m_pattern;
    std::vector<std::uint32_t> m_blockEntryStart, m_blockEntries; // entry = 16 * element + 4 * a + b
    std::vector<std::uint32_t> m_nodeEntryStart, m_nodeEntries;   // entry = 4 * element + a
    Eigen::VectorXd m_positions;
    Eigen::VectorXd m_velocities;
    Eigen::VectorXd m_mass;
};

} // namespace vsim::sim::fem
