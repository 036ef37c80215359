#include "vsim/sim/fem/StaticWallRun.h"

#include "vsim/core/Error.h"
#include "vsim/core/Units.h"
#include "vsim/sim/fem/QuadraticFem.h"
#include "vsim/sim/fem/SurfaceLoads.h"
#include "vsim/sim/fem/WallBoundaryConditions.h"

#include <algorithm>
#include <cmath>

namespace vsim::sim::fem {
namespace {

/// The state as a frame on the linear mesh (mm): corner displacements, element stresses (kPa).
TetMesh frameOf(const TetMesh& wall, const QuadraticFem& model)
{
    TetMesh frame;
    frame.points = wall.points;
    frame.tets = wall.tets;
    const std::size_t n = wall.points.size();
    std::vector<double> dx(n), dy(n), dz(n), magnitude(n);
    for (std::size_t i = 0; i < n; ++i)
    {
        const Eigen::Vector3d d = units::mToMm(1.0) * (model.positions().segment<3>(Eigen::Index(3 * i)) - model.mesh().points[i]);
        dx[i] = d.x(), dy[i] = d.y(), dz[i] = d.z(), magnitude[i] = d.norm();
    }
    frame.pointFields["displacement_x_mm"] = dx;
    frame.pointFields["displacement_y_mm"] = dy;
    frame.pointFields["displacement_z_mm"] = dz;
    frame.pointFields["displacement_mm"] = magnitude;
    ElementStresses stresses = model.elementStresses();
    for (double& v : stresses.vonMises)
        v *= 1e-3;
    for (double& v : stresses.maxPrincipal)
        v *= 1e-3;
    frame.cellFields["von_mises_kpa"] = std::move(stresses.vonMises);
    frame.cellFields["max_principal_kpa"] = std::move(stresses.maxPrincipal);
    if (const auto material = wall.cellFields.find("material"); material != wall.cellFields.end())
        frame.cellFields["material"] = material->second;
    return frame;
}

} // namespace

FemRunResult runStaticWall(const StaticWallSetup& setup, const Progress& progress)
{
    if (!(setup.pressurePa > 0.0) || setup.loadIncrements < 1)
        throw Error("the static wall analysis needs a positive pressure and at least one load increment");
    const WallBoundaryConditions conditions = wallBoundaryConditions(setup.wall);
    std::vector<Eigen::Vector3d> metres(setup.wall.points.size());
    for (std::size_t i = 0; i < metres.size(); ++i)
        metres[i] = units::mmToM(1.0) * setup.wall.points[i];
    QuadraticFem model(quadraticFromLinear(metres, setup.wall.tets), setup.materials, setup.elementMaterial);
    const std::vector<std::uint8_t> held = quadraticConstraints(model.mesh(), conditions.fixed);
    const std::vector<std::array<int, 6>> faces = quadraticFaces(model.mesh(), conditions.faceNodes(setup.wall.tets));

    FemRunResult result;
    RunStatus& status = result.status;
    status.forceTolerance = setup.tolerance;
    auto addFrame = [&](double loadFactor) {
        result.frames.push_back(frameOf(setup.wall, model));
        result.frameTimesS.push_back(loadFactor); // pseudo-time: the load factor
        result.framePressuresPa.push_back(loadFactor * setup.pressurePa);
    };
    addFrame(0.0);
    // Load increments of 1 / loadIncrements; one that fails (no convergence, an element inverted on every step)
    // is undone and retried at half the size, down to 1/16 of the pressure.
    double reached = 0.0, increment = 1.0 / setup.loadIncrements;
    int totalUpdates = 0, cutbacks = 0, factorisations = 0;
    while (reached < 1.0)
    {
        const double factor = std::min(1.0, reached + increment), pressure = factor * setup.pressurePa;
        const bool last = factor >= 1.0;
        StaticSolveSettings settings;
        settings.tolerance = last ? setup.tolerance : std::max(setup.tolerance, setup.intermediateTolerance);
        settings.maxUpdates = setup.maxUpdatesPerIncrement;
        settings.linear = setup.linear;
        settings.linearTolerance = 1e-8;
        settings.rotationStiffness = true;
        settings.directionalLineSearch = true;
        const Progress stage = progress.subRange(reached, factor);
        settings.afterResidual = [&](int updates, double residual) {
            stage.throwIfCancelled();
            // Newton converges quadratically: progress by the residual's decades towards the tolerance.
            const double decades = std::log10(std::max(residual, settings.tolerance) / settings.tolerance);
            stage.report(std::clamp(1.0 - decades / 8.0, double(updates) / settings.maxUpdates, 0.99),
                         "equilibrium at " + std::to_string(int(std::lround(100 * factor))) + " % of the pressure");
        };
        const Eigen::VectorXd start = model.positions();
        StaticSolveReport report;
        std::string failure;
        try
        {
            const FollowerPressure load = followerPressure(faces, pressure);
            report = solveStatic(model, load.forces, held, settings, load.stiffness);
        }
        catch (const Cancelled&)
        {
            model.positions() = start;
            throw;
        }
        catch (const Error& error)
        {
            failure = error.what();
        }
        const bool krylov = setup.linear == LinearSolver::CholeskyGmres;
        for (std::size_t update = 0; update < report.linearResiduals.size(); ++update)
            status.recordSolve(report.linearIterations[update], report.linearResiduals[update], 1e-8,
                               krylov ? settings.gmresMaxIterations : 0);
        factorisations += report.factorisations;
        totalUpdates += report.updates;
        result.equilibriumResiduals.insert(result.equilibriumResiduals.end(), report.residualHistory.begin(),
                                           report.residualHistory.end());
        if (!failure.empty() || !report.converged)
        {
            model.positions() = start; // back to the last converged increment
            model.updateElements();
            if (increment > 1.0 / 16.0 + 1e-12)
            {
                increment *= 0.5;
                ++cutbacks;
                continue;
            }
            status.forceResidual = report.residualHistory.empty() ? 1.0 : report.residualHistory.back();
            status.stoppedBy = RunStatus::StoppedBy::Guard;
            status.stopMessage = "the equilibrium at " + std::to_string(int(std::lround(100 * factor))) +
                                 " % of the pressure " +
                                 (failure.empty() ? "did not converge in " + std::to_string(report.updates) +
                                                        " Newton updates (force residual " +
                                                        std::to_string(status.forceResidual) + ")"
                                                  : "failed: " + failure) +
                                 " even in increments of 1/16; the last converged increment is kept";
            result.stopReason = status.stopMessage;
            break;
        }
        status.forceResidual = report.forceResidual;
        reached = factor;
        addFrame(factor);
    }
    result.metrics["load_cutbacks"] = double(cutbacks);

    // The wall's peaks (the thrombus, material 1, carries little stress and is not the wall).
    std::vector<std::uint8_t> wallElements;
    for (std::uint8_t material : setup.elementMaterial)
        wallElements.push_back(material == 0 ? 1 : 0);
    addPeakMetrics(result, wallElements);
    result.metrics["thrombus_elements"] =
        double(std::count(setup.elementMaterial.begin(), setup.elementMaterial.end(), std::uint8_t(1)));
    result.metrics["element_order"] = 2.0;
    result.metrics["quadratic_nodes"] = double(model.nodeCount());
    result.metrics["load_increments"] = double(result.frames.size() - 1);
    result.metrics["equilibrium_updates"] = double(totalUpdates);
    result.metrics["equilibrium_factorisations"] = double(factorisations);
    result.metrics["final_pressure_kpa"] = reached * setup.pressurePa * 1e-3;
    status.reachedQuantity = "pressure";
    status.reachedUnit = "kPa";
    status.reached = reached * setup.pressurePa * 1e-3;
    status.target = setup.pressurePa * 1e-3;
    for (const auto& [key, value] : status.metrics())
        result.metrics[key] = value;
    return result;
}

FemRunResult runStaticWallFromZeroPressure(const StaticWallSetup& setup, int maxIterations, double toleranceMm,
                                           const Progress& progress)
{
    const std::vector<Eigen::Vector3d>& imaged = setup.wall.points;
    StaticWallSetup unloaded = setup;
    FemRunResult run;
    double mismatch = 0.0;
    int iteration = 0;
    for (; iteration < maxIterations; ++iteration)
    {
        run = runStaticWall(unloaded, progress.subRange(double(iteration) / maxIterations,
                                                        double(iteration + 1) / maxIterations));
        if (!run.status.complete() || !run.status.converged())
            return run;
        // The loaded shape of this reference against the image (corner nodes; mm).
        const TetMesh& loaded = run.frames.back();
        const auto& dx = loaded.pointFields.at("displacement_x_mm");
        const auto& dy = loaded.pointFields.at("displacement_y_mm");
        const auto& dz = loaded.pointFields.at("displacement_z_mm");
        mismatch = 0.0;
        std::vector<Eigen::Vector3d> next = unloaded.wall.points;
        for (std::size_t n = 0; n < next.size(); ++n)
        {
            const Eigen::Vector3d off = unloaded.wall.points[n] + Eigen::Vector3d(dx[n], dy[n], dz[n]) - imaged[n];
            mismatch = std::max(mismatch, off.norm());
            next[n] -= off;
        }
        if (mismatch <= toleranceMm)
            break;
        unloaded.wall.points = std::move(next);
    }
    // The figures on the imaged geometry: the frames' points are the image, their displacements from the
    // unloaded reference.
    for (TetMesh& frame : run.frames)
        frame.points = imaged;
    run.metrics["zero_pressure_iterations"] = double(std::min(iteration + 1, maxIterations));
    run.metrics["zero_pressure_mismatch_mm"] = mismatch;
    run.metrics["zero_pressure_converged"] = mismatch <= toleranceMm ? 1.0 : 0.0;
    return run;
}

} // namespace vsim::sim::fem
