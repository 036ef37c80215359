#include "vsim/sim/fem/WallSimulation.h"

#include "vsim/core/Error.h"
#include "vsim/core/StoredText.h"
#include "vsim/core/Units.h"
#include "vsim/sim/fem/SurfaceLoads.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>

namespace vsim::sim::fem {
namespace {

CorotationalFem modelOf(const TetMesh& wall, const ElasticMaterial& material)
{
    requireWallFields(wall);
    std::vector<Eigen::Vector3d> rest(wall.points.size());
    for (std::size_t i = 0; i < rest.size(); ++i)
        rest[i] = units::mmToM(1.0) * wall.points[i];
    return CorotationalFem(rest, wall.tets, material);
}

/// Averages per-tet values over the tets that came from one prism (original element index / 3).
std::vector<double> averageByPrism(const std::vector<double>& perTet, const std::vector<std::size_t>& originalElement)
{
    std::map<std::size_t, std::pair<double, int>> sums;
    for (std::size_t t = 0; t < perTet.size(); ++t)
    {
        auto& [sum, count] = sums[originalElement[t] / 3];
        sum += perTet[t];
        ++count;
    }
    std::vector<double> out(perTet.size());
    for (std::size_t t = 0; t < perTet.size(); ++t)
    {
        const auto& [sum, count] = sums[originalElement[t] / 3];
        out[t] = sum / count;
    }
    return out;
}

} // namespace

WallSimulation::WallSimulation(const TetMesh& wall, const ElasticMaterial& material, const BackwardEulerSettings& settings,
                               const std::function<bool(const Eigen::Vector3d&)>& loaded)
    : m_model(modelOf(wall, material)), m_settings(settings), m_integrator(m_model, settings)
{
    WallBoundaryConditions conditions = wallBoundaryConditions(wall, loaded);
    m_fixed = std::move(conditions.fixed);
    m_faces = std::move(conditions.lumenFaces);
    m_originalElement.resize(m_model.elementCount());
    for (std::size_t t = 0; t < m_originalElement.size(); ++t)
        m_originalElement[t] = t;
}

std::vector<std::array<int, 3>> WallSimulation::pressureFaces() const
{
    return WallBoundaryConditions{{}, m_faces}.faceNodes(m_model.tets());
}

void WallSimulation::setStepper(StepperFactory factory)
{
    m_stepper.reset();
    m_stepperFactory = std::move(factory);
    if (m_stepperFactory)
        m_stepper = m_stepperFactory(m_model, m_settings, m_fixed, pressureFaces());
}

StepReport WallSimulation::stepOnStepper()
{
    const StepReport report = m_stepper->step(m_pressure);
    m_stepper->download(m_model.positions(), m_model.velocities());
    m_model.updateElements(); // rotations for the stresses at the new positions (the CPU path's are a step older)
    return report;
}

int WallSimulation::grab(const Eigen::Vector3d& pointMm, double stiffness)
{
    if (m_stepper)
        throw Error("dragging the wall needs the CPU backend (the GPU stepper has no contact springs)");
    const Eigen::Vector3d point = units::mmToM(1.0) * pointMm;
    int nearest = 0;
    double best = 1e300;
    for (std::size_t n = 0; n < m_model.nodeCount(); ++n)
        if (const double d = (m_model.positions().segment<3>(Eigen::Index(3 * n)) - point).squaredNorm(); d < best)
            best = d, nearest = int(n);
    m_contacts.springs = {{nearest, m_model.positions().segment<3>(3 * nearest), stiffness}};
    return nearest;
}

void WallSimulation::dragTo(const Eigen::Vector3d& targetMm)
{
    if (!m_contacts.springs.empty())
        m_contacts.springs.front().anchor = units::mmToM(1.0) * targetMm;
}

void WallSimulation::setEquilibriumSolver(bool modifiedNewton, StaticModelFactory elsewhere)
{
    if (elsewhere && !modifiedNewton)
        throw Error("the static solve on the GPU is the modified Newton iteration with multigrid conjugate gradients");
    m_modifiedNewton = modifiedNewton;
    m_staticModelFactory = std::move(elsewhere);
    m_elsewhere.reset();
    m_keptMultigrid.hierarchy.reset();
}

StaticSolveReport WallSimulation::equilibrate(double tolerance, int maxUpdates, std::string* failure,
                                              const Progress& progress)
{
    const Eigen::VectorXd lastPositions = m_model.positions();
    const std::vector<std::array<int, 3>> faces = pressureFaces();
    const ExternalForces pressure = [&](const Eigen::VectorXd& positions) {
        Eigen::VectorXd forces = Eigen::VectorXd::Zero(positions.size());
        addPressureForces(faces, positions, m_pressure, forces);
        return forces;
    };
    const ExternalStiffness pressureStiffness = [&](const Eigen::VectorXd& positions, BlockSparseMatrix& tangent) {
        subtractPressureStiffness(faces, positions, m_pressure, tangent);
    };
    StaticSolveReport report;
    try
    {
        StaticSolveSettings settings;
        settings.tolerance = tolerance;
        settings.maxUpdates = maxUpdates;
        settings.linear = m_modifiedNewton ? LinearSolver::ConjugateGradient : LinearSolver::CholeskyGmres;
        settings.cgPreconditioner = CgPreconditioner::Multigrid;
        settings.keptMultigrid = &m_keptMultigrid;
        settings.rotationStiffness = true; // both iterations; the conjugate gradients leave out the load stiffness
        settings.cancelPoll = [&progress] { progress.throwIfCancelled(); };
        settings.afterResidual = [&](int updates, double residual) {
            progress.throwIfCancelled();
            // Newton's residual falls from about 1e-1 to the tolerance: progress on its logarithm.
            const double done = std::log10(std::max(residual, tolerance)) / std::log10(tolerance);
            char text[64];
            std::snprintf(text, sizeof text, "equilibrium: update %d, force residual %.1e", updates, residual);
            progress.report(std::clamp(done, 0.0, 1.0), text);
        };
        if (m_staticModelFactory)
        {
            if (m_elsewhere)
                m_elsewhere->takeStateOf(m_model);
            else
                m_elsewhere = m_staticModelFactory(m_model, m_fixed);
            report = solveStatic(*m_elsewhere, pressure, m_fixed, settings);
            m_model.positions() = m_elsewhere->positions();
            m_model.updateElements();
        }
        else
            report = solveStatic(m_model, pressure, m_fixed, settings, pressureStiffness);
    }
    catch (const Cancelled&)
    {
        m_model.positions() = lastPositions;
        m_model.updateElements();
        throw;
    }
    catch (const Error& error)
    {
        m_model.positions() = lastPositions;
        m_model.updateElements();
        if (failure)
            *failure = error.what();
        report.converged = false;
        return report;
    }
    m_model.velocities().setZero();
    if (m_stepper)
        setStepper(m_stepperFactory); // the stepper's state is the one before the solve
    return report;
}

WallSimulation::StepOutcome WallSimulation::step()
{
    StepOutcome outcome;
    const Eigen::VectorXd lastPositions = m_model.positions(), lastVelocities = m_model.velocities();
    if (m_stepper)
        outcome.report = stepOnStepper();
    else
    {
        Eigen::VectorXd forces = Eigen::VectorXd::Zero(m_model.positions().size());
        addPressureForces(pressureFaces(), m_model.positions(), m_pressure, forces);
        outcome.report = m_integrator.step(m_model, forces, m_fixed, m_contacts);
    }
    if (!m_model.positions().allFinite())
        outcome.guard = storedText("the solution is no longer finite (NaN or infinity)");
    else if (!outcome.report.cgConverged && outcome.report.invertedElements == 0 &&
             outcome.report.cgIterations < m_settings.cgMaxIterations)
        outcome.guard = storedText("the conjugate gradients broke down (the system is not positive definite)");
    if (!outcome.guard.empty() || outcome.report.invertedElements > 0)
    {
        m_model.positions() = lastPositions;
        m_model.velocities() = lastVelocities;
        m_model.updateElements(); // the inverted elements are those of this state (the step's element pass)
        if (outcome.guard.empty())
        {
            const Eigen::Vector3d where = 1e3 * m_model.firstInvertedCentroid();
            outcome.guard = storedText(Pattern{"%1 elements inverted (the first near %2, %3, %4 mm)",
                                               {std::to_string(outcome.report.invertedElements), storedNumber(where.x(), 1),
                                                storedNumber(where.y(), 1), storedNumber(where.z(), 1)}});
        }
        if (m_stepper)
            setStepper(m_stepperFactory); // the stepper's state is the failed one
        return outcome;
    }
    m_time += m_settings.timeStep;
    if (m_tearStrength > 0.0)
    {
        const std::vector<std::size_t> over = elementsOverStrength(m_model.elementStresses(), m_tearStrength);
        if (!over.empty())
        {
            tear(over);
            outcome.tornNow = over.size();
        }
    }
    return outcome;
}

std::vector<std::size_t> WallSimulation::elementsOverTearStrength() const
{
    return m_tearStrength > 0.0 ? elementsOverStrength(m_model.elementStresses(), m_tearStrength) : std::vector<std::size_t>{};
}

void WallSimulation::restore(const Eigen::VectorXd& positions)
{
    if (positions.size() != m_model.positions().size())
        throw Error(Pattern{"the saved wall state has %1 nodes, the wall %2",
                            {std::to_string(positions.size() / 3), std::to_string(m_model.nodeCount())}});
    m_model.positions() = positions;
    m_model.velocities().setZero();
    m_model.updateElements();
    if (m_stepper)
        setStepper(m_stepperFactory);
}

void WallSimulation::tear(const std::vector<std::size_t>& over)
{
    m_elsewhere.reset(); // another mesh: what the equilibria kept is set up again
    m_keptMultigrid.hierarchy.reset();
    const std::vector<double> energies = m_model.elementEnergies();
    for (std::size_t e : over)
        m_entropy.addTornElement(energies[e]);
    DetachedModel detached = detachElements(m_model, over);
    std::vector<long> newElementOf(m_model.elementCount(), -1);
    for (std::size_t e = 0; e < detached.oldElementOf.size(); ++e)
        newElementOf[detached.oldElementOf[e]] = long(e);
    std::vector<WallBoundaryConditions::Face> kept;
    for (const WallBoundaryConditions::Face& face : m_faces)
        if (newElementOf[face.element] >= 0)
            kept.push_back({std::size_t(newElementOf[face.element]), face.opposite});
    m_faces = std::move(kept);
    std::vector<std::uint8_t> fixed(3 * detached.model.nodeCount());
    std::vector<int> newNodeOf(m_model.nodeCount(), -1);
    for (std::size_t n = 0; n < detached.model.nodeCount(); ++n)
    {
        for (int d = 0; d < 3; ++d)
            fixed[3 * n + std::size_t(d)] = m_fixed[3 * std::size_t(detached.oldNodeOf[n]) + std::size_t(d)];
        if (newNodeOf[std::size_t(detached.oldNodeOf[n])] < 0)
            newNodeOf[std::size_t(detached.oldNodeOf[n])] = int(n);
    }
    m_fixed = std::move(fixed);
    std::vector<std::size_t> original(detached.oldElementOf.size());
    for (std::size_t e = 0; e < original.size(); ++e)
        original[e] = m_originalElement[detached.oldElementOf[e]];
    m_originalElement = std::move(original);
    std::vector<SpringConstraint> springs;
    for (SpringConstraint spring : m_contacts.springs)
        if (newNodeOf[std::size_t(spring.node)] >= 0)
        {
            spring.node = newNodeOf[std::size_t(spring.node)];
            springs.push_back(spring);
        }
    m_contacts.springs = std::move(springs);
    m_model = std::move(detached.model);
    m_integrator = BackwardEuler(m_model, m_settings);
    if (m_stepper)
        setStepper(m_stepperFactory);
}

TetMesh WallSimulation::frame() const
{
    TetMesh frame;
    frame.tets = m_model.tets();
    const std::size_t n = m_model.nodeCount();
    frame.points.resize(n);
    std::vector<double> dx(n), dy(n), dz(n), magnitude(n);
    for (std::size_t i = 0; i < n; ++i)
    {
        frame.points[i] = units::mToMm(1.0) * m_model.restPositions()[i];
        const Eigen::Vector3d d =
            units::mToMm(1.0) * (m_model.positions().segment<3>(Eigen::Index(3 * i)) - m_model.restPositions()[i]);
        dx[i] = d.x(), dy[i] = d.y(), dz[i] = d.z(), magnitude[i] = d.norm();
    }
    frame.pointFields["displacement_x_mm"] = dx;
    frame.pointFields["displacement_y_mm"] = dy;
    frame.pointFields["displacement_z_mm"] = dz;
    frame.pointFields["displacement_mm"] = magnitude;
    const ElementStresses stresses = m_model.elementStresses();
    std::vector<double> vonMises = averageByPrism(stresses.vonMises, m_originalElement);
    std::vector<double> principal = averageByPrism(stresses.maxPrincipal, m_originalElement);
    for (double& v : vonMises)
        v *= 1e-3;
    for (double& v : principal)
        v *= 1e-3;
    frame.cellFields["von_mises_kpa"] = vonMises;
    frame.cellFields["max_principal_kpa"] = principal;
    return frame;
}

} // namespace vsim::sim::fem
