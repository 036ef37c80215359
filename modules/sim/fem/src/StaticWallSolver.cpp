#include "vsim/sim/fem/StaticWallSolver.h"

#include "vsim/core/Error.h"
#include "vsim/core/Parameters.h"
#include "vsim/core/StoredText.h"
#include "vsim/core/Units.h"
#include "vsim/sim/fem/SurfaceLoads.h"
#include "vsim/sim/fem/WallBoundaryConditions.h"

#include <algorithm>
#include <cmath>

namespace vsim::sim::fem {

StaticWallSolver::StaticWallSolver(StaticWallSetup setup) : m_setup(std::move(setup))
{
    m_setup.wall = {};
}

StaticWallSolver::~StaticWallSolver() = default;

void StaticWallSolver::initialize(const SimulationInput& input, const ParameterSet&)
{
    if (!(m_setup.pressurePa > 0.0) || m_setup.loadIncrements < 1)
        throw Error("the static wall analysis needs a positive pressure and at least one load increment");
    m_wall = input.get<TetMesh>("wall");
    const WallBoundaryConditions conditions = wallBoundaryConditions(m_wall);
    std::vector<Eigen::Vector3d> metres(m_wall.points.size());
    for (std::size_t i = 0; i < metres.size(); ++i)
        metres[i] = units::mmToM(1.0) * m_wall.points[i];
    m_model = std::make_unique<QuadraticFem>(quadraticFromLinear(metres, m_wall.tets), m_setup.materials,
                                             m_setup.elementMaterial);
    m_held = quadraticConstraints(m_model->mesh(), conditions.fixed);
    const std::vector<std::array<int, 3>> cornerFaces = conditions.faceNodes(m_wall.tets);
    m_faces = quadraticFaces(m_model->mesh(), cornerFaces);
    m_faceExtraPa.clear();
    if (const auto extra = m_wall.pointFields.find(kLumenExtraPressureField); extra != m_wall.pointFields.end())
        for (const auto& [a, b, c] : cornerFaces) // the face's mean of its corners' values
        {
            const double pa = (extra->second[std::size_t(a)] + extra->second[std::size_t(b)] +
                               extra->second[std::size_t(c)]) / 3.0;
            if (!std::isfinite(pa) || !(m_setup.pressurePa + pa > 0.0))
                throw Error(Pattern{"the lumen's added pressure (%1) must be finite and leave the pressure positive "
                                    "(%2 Pa + %3 Pa)",
                                    {kLumenExtraPressureField, numberText(m_setup.pressurePa), numberText(pa)}});
            m_faceExtraPa.push_back(pa);
        }
    m_reached = 0.0, m_increment = 1.0 / m_setup.loadIncrements;
    m_converged = m_updates = m_cutbacks = m_factorisations = 0;
    m_residuals.clear();
}

StepOutcome StaticWallSolver::step(RunStatus& status, const Progress& progress)
{
    status.forceTolerance = m_setup.tolerance;
    while (true)
    {
        const double factor = std::min(1.0, m_reached + m_increment), pressure = factor * m_setup.pressurePa;
        StaticSolveSettings settings;
        settings.tolerance = factor >= 1.0 ? m_setup.tolerance : std::max(m_setup.tolerance, m_setup.intermediateTolerance);
        settings.maxUpdates = m_setup.maxUpdatesPerIncrement;
        settings.linear = m_setup.linear;
        settings.linearTolerance = 1e-8;
        if (m_setup.linear == LinearSolver::MultigridGmres)
            settings.gmresMaxIterations = 2000; // a V-cycle is a weaker preconditioner than a factorisation
        settings.tangentCholeskyBelow = m_setup.tangentCholeskyBelow;
        settings.rotationStiffness = true;
        settings.directionalLineSearch = true;
        settings.stallStep = m_setup.stallStep;
        const bool halvable = m_increment > 1.0 / 16.0 + 1e-12;
        settings.firstSolveBudget = halvable ? m_setup.firstSolveBudget : 0; // the smallest increment: LU as before
        const Progress stage = progress.subRange(m_reached, factor);
        settings.cancelPoll = [&stage] { stage.throwIfCancelled(); };
        settings.afterResidual = [&](int updates, double residual) {
            stage.throwIfCancelled();
            // Newton converges quadratically: progress by the residual's decades towards the tolerance.
            const double decades = std::log10(std::max(residual, settings.tolerance) / settings.tolerance);
            stage.report(std::clamp(1.0 - decades / 8.0, double(updates) / settings.maxUpdates, 0.99),
                         "equilibrium at " + std::to_string(int(std::lround(100 * factor))) + " % of the pressure");
        };
        const Eigen::VectorXd start = m_model->positions();
        StaticSolveReport report;
        std::string failure;
        try
        {
            std::vector<double> facePressures(m_faceExtraPa.size());
            for (std::size_t f = 0; f < facePressures.size(); ++f) // the load factor scales the whole lumen load
                facePressures[f] = factor * (m_setup.pressurePa + m_faceExtraPa[f]);
            const FollowerPressure load =
                m_faceExtraPa.empty() ? followerPressure(m_faces, pressure) : followerPressure(m_faces, facePressures);
            report = solveStatic(*m_model, load.forces, m_held, settings, load.stiffness);
        }
        catch (const Cancelled&)
        {
            m_model->positions() = start;
            m_model->updateElements();
            throw;
        }
        catch (const Error& error)
        {
            failure = error.what();
        }
        const bool krylov = solvesByGmres(m_setup.linear);
        for (std::size_t update = 0; update < report.linearResiduals.size(); ++update)
            status.recordSolve(report.linearIterations[update], report.linearResiduals[update], 1e-8,
                               krylov ? settings.gmresMaxIterations : 0);
        m_factorisations += report.factorisations;
        m_updates += report.updates;
        m_residuals.insert(m_residuals.end(), report.residualHistory.begin(), report.residualHistory.end());
        if (failure.empty() && report.converged)
        {
            status.forceResidual = report.forceResidual;
            m_reached = factor;
            ++m_converged;
            return {};
        }
        m_model->positions() = start; // back to the last converged increment
        m_model->updateElements();
        if (halvable)
        {
            m_increment *= 0.5;
            ++m_cutbacks;
            continue;
        }
        status.forceResidual = report.residualHistory.empty() ? 1.0 : report.residualHistory.back();
        const std::string percent = std::to_string(int(std::lround(100 * factor)));
        return StepOutcome::guard(
            failure.empty()
                ? storedText(Pattern{"the equilibrium at %1 % of the pressure did not converge in %2 Newton updates "
                                     "(force residual %3) even in increments of 1/16; the last converged increment "
                                     "is kept",
                                     {percent, std::to_string(report.updates), numberText(status.forceResidual)}})
                : storedText(Pattern{"the equilibrium at %1 % of the pressure failed: %2 even in increments of 1/16; "
                                     "the last converged increment is kept",
                                     {percent, failure}}));
    }
}

SimulationData StaticWallSolver::snapshot() const
{
    TetMesh frame;
    frame.points = m_wall.points;
    frame.tets = m_wall.tets;
    const std::size_t n = m_wall.points.size();
    std::vector<double> dx(n), dy(n), dz(n), magnitude(n);
    for (std::size_t i = 0; i < n; ++i)
    {
        const Eigen::Vector3d d =
            units::mToMm(1.0) * (m_model->positions().segment<3>(Eigen::Index(3 * i)) - m_model->mesh().points[i]);
        dx[i] = d.x(), dy[i] = d.y(), dz[i] = d.z(), magnitude[i] = d.norm();
    }
    frame.pointFields["displacement_x_mm"] = dx;
    frame.pointFields["displacement_y_mm"] = dy;
    frame.pointFields["displacement_z_mm"] = dz;
    frame.pointFields["displacement_mm"] = magnitude;
    ElementStresses stresses = m_model->elementStresses();
    for (double& v : stresses.vonMises)
        v *= 1e-3;
    for (double& v : stresses.maxPrincipal)
        v *= 1e-3;
    frame.cellFields["von_mises_kpa"] = std::move(stresses.vonMises);
    frame.cellFields["max_principal_kpa"] = std::move(stresses.maxPrincipal);
    if (const auto material = m_wall.cellFields.find("material"); material != m_wall.cellFields.end())
        frame.cellFields["material"] = material->second;
    return frame;
}

std::map<std::string, double> StaticWallSolver::metrics() const
{
    const auto& materials = m_setup.elementMaterial;
    return {{"load_cutbacks", double(m_cutbacks)},
            {"thrombus_elements", double(std::count(materials.begin(), materials.end(), std::uint8_t(1)))},
            {"element_order", 2.0},
            {"quadratic_nodes", double(m_model->nodeCount())},
            {"load_increments", double(m_converged)},
            {"equilibrium_updates", double(m_updates)},
            {"equilibrium_factorisations", double(m_factorisations)},
            {"final_pressure_kpa", position()}};
}

} // namespace vsim::sim::fem
