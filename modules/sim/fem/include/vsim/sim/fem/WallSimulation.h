#pragma once

// The wall as it steps: model, integrator, fixed ends, the lumen faces under pressure, contacts (the drag spring of
// the interactive protocol), tearing and its entropy, and the guards that restore the last good state. The run
// driver (FemRun.h) loops over it with a pressure curve; the workstation's interactive protocol steps it on a
// timer while the user drags the wall and moves the pressure slider. Input mesh in mm, state in SI.

#include "vsim/core/Progress.h"
#include "vsim/core/TetMesh.h"
#include "vsim/sim/fem/BackwardEuler.h"
#include "vsim/sim/fem/Contacts.h"
#include "vsim/sim/fem/CorotationalFem.h"
#include "vsim/sim/fem/ImplicitStepper.h"
#include "vsim/sim/fem/StaticSolver.h"
#include "vsim/sim/fem/Tearing.h"
#include "vsim/sim/fem/WallBoundaryConditions.h"

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace vsim::sim::fem {

class WallSimulation
{
public:
    /// Throws vsim::Error for a mesh that is not a wall (wall_layer / end_set missing), no fixed end or no lumen
    /// face under load (`loaded` selects lumen faces by centroid, mm; empty: all).
    WallSimulation(const TetMesh& wallMm, const ElasticMaterial& material, const BackwardEulerSettings& settings,
                   const std::function<bool(const Eigen::Vector3d&)>& loaded = {});

    /// Runs the implicit steps with steppers from `factory` (the CUDA backend) instead of BackwardEuler; an empty
    /// factory goes back to the CPU. Throws what the factory throws. Contacts (grab) need the CPU.
    void setStepper(StepperFactory factory);

    /// How equilibrate solves: `modifiedNewton` false, the full Newton iteration (below; this CPU); true, the
    /// modified one without the pressure's load stiffness, whose tangent R K R^T + the rotations' derivative is
    /// symmetric, by multigrid PCG (StaticSolver.h, ConjugateGradient), on this CPU or, with a factory, on the model
    /// it makes from the wall's state (the CUDA static wall). Throws vsim::Error for a factory without the modified
    /// iteration.
    void setEquilibriumSolver(bool modifiedNewton, StaticModelFactory elsewhere = {});

    void setPressure(double pressurePa) { m_pressure = pressurePa; }
    double pressure() const { return m_pressure; }
    /// Tears elements whose largest principal stress passes `strengthPa` after each step (0: no tearing).
    void setTearStrength(double strengthPa) { m_tearStrength = strengthPa; }
    /// Grabs the node nearest to `pointMm` (the current shape) with a spring of `stiffness` N/m; returns it.
    /// Throws vsim::Error when a stepper runs the steps (springs are a CPU feature).
    int grab(const Eigen::Vector3d& pointMm, double stiffness);
    /// Moves the grabbed node's spring anchor (mm); nothing when none is grabbed.
    void dragTo(const Eigen::Vector3d& targetMm);
    void release() { m_contacts.springs.clear(); }
    bool isGrabbing() const { return !m_contacts.springs.empty(); }

    struct StepOutcome
    {
        StepReport report;
        std::string guard;          ///< why the step was undone (the state is the last good one); empty when fine
        std::size_t tornNow = 0;    ///< elements torn by this step
    };
    /// One implicit step at the current pressure, contacts and tearing.
    StepOutcome step();
    /// Static equilibrium at the current pressure from the current state: the follower pressure on the current
    /// shape, fixed ends, no contacts, by the Newton solve of StaticSolver.h (by default the rotations' derivative
    /// and the pressure's load stiffness in the tangent, each linear solve by GMRES to 1e-8 with a Cholesky or LU
    /// preconditioner, TangentSolver.h; else as setEquilibriumSolver chose); velocities zeroed. When an
    /// element inverts the state is restored, the report is not converged and `failure` (when given) says where.
    /// `progress` follows the updates; a cancel restores the state and throws vsim::Cancelled.
    StaticSolveReport equilibrate(double tolerance, int maxUpdates, std::string* failure = nullptr,
                                  const Progress& progress = {});

    /// The elements (current indices) whose largest principal stress passes the tear strength, most stressed first.
    std::vector<std::size_t> elementsOverTearStrength() const;
    /// Tears `elements` (current indices; the fracture entropy counts them), splitting the nodes they separated.
    void tearElements(const std::vector<std::size_t>& elements) { tear(elements); }
    /// The wall mesh's element that current element `element` is (tearing renumbers them).
    std::size_t originalElement(std::size_t element) const { return m_originalElement[element]; }
    /// Puts the wall at `positions` (m, 3 per node of the current model) at rest: a state saved from positions().
    void restore(const Eigen::VectorXd& positions);

    double time() const { return m_time; }
    const CorotationalFem& model() const { return m_model; }
    const FractureEntropy& entropy() const { return m_entropy; }
    /// The current state as a frame (mm): displacement point fields, prism-averaged von Mises and largest principal
    /// stress (kPa) cell fields.
    TetMesh frame() const;

private:
    std::vector<std::array<int, 3>> pressureFaces() const;
    void tear(const std::vector<std::size_t>& over);
    /// One step on the stepper: the state comes back and the element pass runs here (stresses, tearing, guards).
    StepReport stepOnStepper();

    CorotationalFem m_model;
    BackwardEulerSettings m_settings;
    BackwardEuler m_integrator;
    StepperFactory m_stepperFactory;
    std::unique_ptr<ImplicitStepper> m_stepper; // made from the current model; remade when it changes
    std::vector<std::uint8_t> m_fixed;
    std::vector<WallBoundaryConditions::Face> m_faces;
    std::vector<std::size_t> m_originalElement; // the wall mesh's element each tet came from (prism = index / 3)
    Contacts m_contacts;
    FractureEntropy m_entropy;
    double m_pressure = 0.0;
    double m_tearStrength = 0.0;
    double m_time = 0.0;
    bool m_modifiedNewton = false;
    StaticModelFactory m_staticModelFactory;
    // What the modified iteration keeps across the equilibria of one mesh (reset by a tear): the CPU's multigrid
    // hierarchy, or the model elsewhere with its own.
    KeptMultigrid m_keptMultigrid;
    std::unique_ptr<RemoteStaticModel> m_elsewhere;
};

} // namespace vsim::sim::fem
