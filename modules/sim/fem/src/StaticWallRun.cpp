#include "vsim/sim/fem/StaticWallRun.h"

#include "vsim/core/Error.h"
#include "WallDriverRun.h"
#include "vsim/sim/fem/StaticWallSolver.h"

namespace vsim::sim::fem {

FemRunResult runStaticWall(const StaticWallSetup& setup, const Progress& progress)
{
    StaticWallSolver solver(setup);
    RunControl control;
    control.frameEverySteps = 1; // every converged increment
    control.maxSteps = 64L * setup.loadIncrements;
    SolverRun run = detail::runOnWall(solver, setup.wall, control, progress);

    FemRunResult result;
    detail::moveFrames(run, result, [&](const RunFrame& frame) {
        const double loadFactor = frame.position / (setup.pressurePa * 1e-3);
        return std::pair{loadFactor, loadFactor * setup.pressurePa}; // pseudo-time: the load factor
    });
    result.status = run.status;
    if (result.status.stoppedBy == RunStatus::StoppedBy::Guard)
        result.stopReason = result.status.stopMessage;
    result.equilibriumResiduals = solver.equilibriumResiduals();
    result.metrics = solver.metrics();
    // The wall's peaks (the thrombus, material 1, carries little stress and is not the wall).
    std::vector<std::uint8_t> wallElements;
    for (std::uint8_t material : setup.elementMaterial)
        wallElements.push_back(material == 0 ? 1 : 0);
    addPeakMetrics(result, wallElements);
    for (const auto& [key, value] : result.status.metrics())
        result.metrics[key] = value;
    result.record = std::move(run);
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
