#pragma once

// Implicit (backward) Euler for the co-rotational model with Rayleigh damping C = alpha M + beta K (thesis
// ch. 4.4; Baraff & Witkin 1998 linearised form): with the rotations of the step's start,
//   [(1 + h alpha) M + (h beta + h^2) K] dv = h (f_elastic + f_external - alpha M v) - h (beta + h) K v,
//   v += dv, x += h v,
// solved by PCG warm-started from the last step's dv, preconditioned by block Jacobi or by smoothed-aggregation
// multigrid (AggregationMultigrid.h; set up at the first step, and again when the iterations have more than
// doubled since). Constrained components keep dv = 0.

#include "vsim/sim/fem/AggregationMultigrid.h"
#include "vsim/sim/fem/BlockSparseMatrix.h"
#include "vsim/sim/fem/Contacts.h"
#include "vsim/sim/fem/CorotationalFem.h"
#include "vsim/sim/fem/MultigridSetUpRule.h"

#include <Eigen/Core>

#include <cstdint>
#include <memory>
#include <vector>

namespace vsim::sim::fem {

enum class CgPreconditioner
{
    BlockJacobi, ///< 3x3 diagonal blocks: cheap, hundreds of iterations to 1e-8 on a wall
    Multigrid,   ///< one smoothed-aggregation V-cycle: tens of iterations, each about five products
};

struct BackwardEulerSettings
{
    double timeStep = 1e-3;      ///< s
    double rayleighAlpha = 0.0;  ///< 1/s (thesis: 0)
    double rayleighBeta = 0.22;  ///< s (thesis: 0.22 s)
    double cgTolerance = 1e-6;   ///< relative residual
    int cgMaxIterations = 100;
    CgPreconditioner preconditioner = CgPreconditioner::BlockJacobi;
    /// Multigrid: set the hierarchy up again at the step after one that took more than this times the iterations
    /// of the first solve with it, plus 5 (0: every second step, the first solve after a set-up being the measure).
    double multigridSetUpAgainFactor = 2.0;
};

struct StepReport
{
    int cgIterations = 0;
    double cgResidual = 0.0;
    bool cgConverged = false;
    std::size_t invertedElements = 0;
};

class BackwardEuler
{
public:
    BackwardEuler(const CorotationalFem& model, BackwardEulerSettings settings);

    const BackwardEulerSettings& settings() const { return m_settings; }
    /// One step of the model under `externalForces` (N, 3 per node; empty: none) with the components marked
    /// in `constrained` held (their velocity stays as it is, normally 0) and `contacts` acting (their stiffness
    /// joins K, so they are damped like the wall). Updates positions and velocities.
    StepReport step(CorotationalFem& model, const Eigen::VectorXd& externalForces,
                    const std::vector<std::uint8_t>& constrained, const Contacts& contacts = {});
    /// The system matrix of the last step (for the GPU parity tests and benchmarks).
    const BlockSparseMatrix& systemMatrix() const { return m_system; }
    /// The multigrid hierarchy (null with block Jacobi, or before the first step).
    const AggregationMultigrid* multigrid() const { return m_multigrid.get(); }
    /// How many times the multigrid hierarchy was set up (0 with block Jacobi).
    int multigridSetUps() const { return m_multigridSetUps; }

private:
    BackwardEulerSettings m_settings;
    BlockSparseMatrix m_system;
    Eigen::VectorXd m_lastDeltaV;
    std::unique_ptr<AggregationMultigrid> m_multigrid;
    std::vector<std::uint8_t> m_multigridConstraints;
    MultigridSetUpRule m_setUpRule;
    int m_multigridSetUps = 0;
};

} // namespace vsim::sim::fem
