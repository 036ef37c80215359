#pragma once

// The converged wall model: 10-node tetrahedra (QuadraticTet.h), total Lagrangian, hyperelastic laws
// (Hyperelastic.h) per element (the wall and the intraluminal thrombus as two materials), SI units. It gives the
// static solver (StaticSolver.h) the elastic forces f_a = -sum_q w_q B_a^T S and the consistent tangent
// K_ab = sum_q w_q (B_a^T C B_b + (g_a . S g_b) I), with B_a the Green strain's variation by node a's motion
// (rows g_ax F_:0^T, g_ay F_:1^T, g_az F_:2^T, g_ay F_:0^T + g_ax F_:1^T, g_az F_:1^T + g_ay F_:2^T,
// g_ax F_:2^T + g_az F_:0^T), g the shape-function gradients at the rest shape, w_q a quarter of the volume.
// Elements are coloured (no two of a colour share a node) so that forces and blocks are added in parallel.

#include "vsim/sim/fem/BlockSparseMatrix.h"
#include "vsim/sim/fem/ElementStresses.h"
#include "vsim/sim/fem/Hyperelastic.h"
#include "vsim/sim/fem/QuadraticTet.h"
#include "vsim/sim/fem/StaticSolver.h"

#include <Eigen/Core>

#include <cstdint>
#include <vector>

namespace vsim::sim::fem {

class QuadraticFem : public StaticModel
{
public:
    /// `mesh` in m; `elementMaterial` per element an index into `materials` (empty: all the first). Throws
    /// vsim::Error for a bad material or index, or a degenerate or inverted element (naming it).
    QuadraticFem(QuadraticTetMesh mesh, std::vector<HyperelasticMaterial> materials,
                 std::vector<std::uint8_t> elementMaterial = {});

    std::size_t nodeCount() const { return m_mesh.points.size(); }
    std::size_t elementCount() const { return m_mesh.elements.size(); }
    const QuadraticTetMesh& mesh() const { return m_mesh; }

    Eigen::VectorXd& positions() override { return m_positions; }
    const Eigen::VectorXd& positions() const { return m_positions; }
    /// Elastic forces at the current positions; returns the number of elements with det F <= 0 at a quadrature
    /// point (their forces are left out).
    std::size_t updateElements() override;
    Eigen::VectorXd elasticForces() const override { return m_forces; }
    Eigen::Vector3d firstInvertedCentroid() const override;
    BlockSparseMatrix makeMatrix() const override { return m_pattern; }
    /// The consistent tangent (material and geometric parts) at the current positions (`consistent` is ignored:
    /// there is no other).
    void assembleTangent(BlockSparseMatrix& matrix, bool consistent) const override;
    /// The tangent with each quadrature point's stress (geometric part) and material tangent projected onto
    /// their positive semi-definite parts (Teran et al. 2005): positive definite wherever the ends hold the wall.
    void assembleDefiniteTangent(BlockSparseMatrix& matrix, bool consistent) const override;

    /// Elastic energy (J).
    double elasticEnergy() const;
    /// Cauchy stress per element, the mean over its quadrature points (Pa).
    ElementStresses elementStresses() const;

private:
    struct Rest
    {
        Eigen::Matrix<double, 4, 3> gradients; ///< the linear tet's shape-function gradients (1/m)
        double volume = 0.0;                   ///< m^3
    };
    Eigen::Matrix<double, 3, 10> elementPositions(std::size_t e) const;
    void assemble(BlockSparseMatrix& matrix, bool definite) const;

    QuadraticTetMesh m_mesh;
    std::vector<HyperelasticMaterial> m_materials;
    std::vector<std::uint8_t> m_elementMaterial;
    std::vector<Rest> m_rest;
    std::vector<std::vector<std::uint32_t>> m_colours; // elements by colour
    BlockSparseMatrix m_pattern;
    Eigen::VectorXd m_positions;
    Eigen::VectorXd m_forces;
    std::vector<std::uint8_t> m_inverted;
};

} // namespace vsim::sim::fem
