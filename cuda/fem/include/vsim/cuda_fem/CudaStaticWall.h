#pragma once

// The static solve's model on the GPU (sim::fem::RemoteStaticModel): the co-rotational wall's element pass, elastic
// forces and tangent (R K R^T + the rotations' derivative, CorotationalFem::addRotationStiffness) on the device, each
// update's linear solve by the device's PCG with block Jacobi or the smoothed-aggregation V-cycle (set up from the
// first update's tangent and again by MultigridSetUpRule). solveStatic (StaticSolver.h, ConjugateGradient) drives
// it from the host: the same modified Newton iteration, line search and follower pressure as on the CPU, whose
// positions, forces and updates cross the bus each update. It keeps its device state and hierarchy across the
// solves of one mesh (the quasi-static ramp's equilibria), taking the host model's state before each. No CUDA types
// in this header.

#include "vsim/sim/fem/CorotationalFem.h"
#include "vsim/sim/fem/MultigridSetUpRule.h"
#include "vsim/sim/fem/StaticSolver.h"

#include <Eigen/Core>

#include <cstdint>
#include <memory>
#include <vector>

namespace vsim::cuda {

class CudaStaticWall final : public sim::fem::RemoteStaticModel
{
public:
    /// Copies `model` (its current state) and the constrained components (3 per node, 1 = held) to the GPU. Throws
    /// vsim::Error without a CUDA device or for a model other than the co-rotational linear one.
    CudaStaticWall(const sim::fem::CorotationalFem& model, const std::vector<std::uint8_t>& constrained);
    ~CudaStaticWall() override;
    CudaStaticWall(const CudaStaticWall&) = delete;
    CudaStaticWall& operator=(const CudaStaticWall&) = delete;

    /// The positions and element rotations of `model` (the mesh this one was made from).
    void takeStateOf(const sim::fem::CorotationalFem& model) override;
    Eigen::VectorXd& positions() override { return m_positions; }
    /// Uploads the positions and runs the element pass and the force sum on the device.
    std::size_t updateElements() override;
    Eigen::VectorXd elasticForces() const override { return m_forces; }
    Eigen::Vector3d firstInvertedCentroid() const override;
    sim::fem::BlockSparseMatrix makeMatrix() const override { return {}; }
    void assembleTangent(sim::fem::BlockSparseMatrix&, bool) const override {}
    bool solvesItsTangent() const override { return true; }
    /// The tangent always holds the rotations' derivative: the CPU's with settings.rotationStiffness (as
    /// WallSimulation::equilibrate sets it).
    sim::fem::TangentSolveResult solveTangent(const Eigen::VectorXd& f, Eigen::VectorXd& dx, double tolerance,
                                              const sim::fem::StaticSolveSettings& settings) override;

private:
    struct Device;
    std::unique_ptr<Device> m_device;
    sim::fem::CorotationalFem m_host; // the inverted element's centroid
    Eigen::VectorXd m_positions, m_forces;
    sim::fem::MultigridSetUpRule m_setUpRule{2.0};
};

/// The factory WallSimulation::setEquilibriumSolver takes (sim::fem::StaticModelFactory).
sim::fem::StaticModelFactory cudaStaticWallFactory();

} // namespace vsim::cuda
