// The converged physiological wall analysis (issue 16's speed goal): runStaticWall on a wall mesh (the thrombus
// layer where its "material" field says so), Raghavan-Vorp wall and Wang thrombus, 120 mmHg, one load increment,
// to a force residual of 1e-6, by each linear solver named. Prints one JSON object per solver: wall time, Newton
// updates, Krylov iterations, the force residuals, the peak wall stress; exit 1 when a solve does not converge or
// the solvers' peak stresses differ by more than 1e-4 relative. gmres: the default (TangentSolver.h);
// gmres-standin: its preconditioner always the model's definite stand-in (the tangent's own Cholesky never tried,
// as before 2026-12-01); gmres-multigrid: GMRES with a smoothed-aggregation V-cycle of the stand-in, no
// factorisation (LinearSolver::MultigridGmres); lu: an UMFPACK LU per update.
//
//   bench_fem_static <wall.vtu> [gmres | gmres-standin | gmres-multigrid | lu]...

#include "vsim/sim/fem/StaticWallRun.h"
#include "vsim/study/MeshFileImport.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <exception>
#include <string>

using namespace vsim;
using namespace vsim::sim::fem;

namespace {

int run(int argc, char** argv)
{
    if (argc < 2)
    {
        std::fprintf(stderr, "usage: bench_fem_static <wall.vtu> [gmres | gmres-standin | gmres-multigrid | lu]...\n");
        return 2;
    }
    StaticWallSetup setup;
    setup.wall = study::readTetMeshFile(argv[1]);
    setup.materials = {HyperelasticMaterial::raghavanVorp2000(0.49), HyperelasticMaterial::wang2001Thrombus(0.49)};
    if (const auto material = setup.wall.cellFields.find("material"); material != setup.wall.cellFields.end())
        for (double m : material->second)
            setup.elementMaterial.push_back(m > 0.5 ? 1 : 0);
    setup.pressurePa = 120.0 * 133.322387415;
    int status = 0;
    double firstPeak = -1.0;
    for (int a = 2; a < (argc > 2 ? argc : 3); ++a)
    {
        const std::string solver = argc > 2 ? argv[a] : "gmres";
        if (solver != "gmres" && solver != "gmres-standin" && solver != "gmres-multigrid" && solver != "lu")
        {
            std::fprintf(stderr, "bench_fem_static: unknown solver '%s' (gmres | gmres-standin | gmres-multigrid | lu)\n", solver.c_str());
            return 2;
        }
        setup.linear = solver == "lu"                ? LinearSolver::SparseLu
                       : solver == "gmres-multigrid" ? LinearSolver::MultigridGmres
                                                     : LinearSolver::CholeskyGmres;
        setup.tangentCholeskyBelow = solver == "gmres-standin" ? -1.0 : StaticWallSetup{}.tangentCholeskyBelow;
        const auto start = std::chrono::steady_clock::now();
        const FemRunResult run = runStaticWall(setup);
        const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        const double peak = run.metrics.at("peak_von_mises_kpa");
        std::string residuals;
        for (double r : run.equilibriumResiduals)
            residuals += (residuals.empty() ? "" : ", ") + std::to_string(r);
        std::printf("{\"bench\": \"fem_static\", \"solver\": \"%s\", \"tets\": %zu, \"quadratic_nodes\": %.0f, "
                    "\"thrombus_elements\": %.0f, \"seconds\": %.2f, \"updates\": %.0f, \"factorisations\": %.0f, \"krylov_iterations\": %.0f, "
                    "\"worst_linear_residual\": %.2e, \"force_residual\": %.2e, \"converged\": %d, "
                    "\"peak_von_mises_kpa\": %.3f, \"force_residuals\": [%s]}\n",
                    solver.c_str(), setup.wall.tets.size(), run.metrics.at("quadratic_nodes"),
                    run.metrics.at("thrombus_elements"), seconds, run.metrics.at("equilibrium_updates"), run.metrics.at("equilibrium_factorisations"),
                    run.metrics.at("run_mean_iterations") * run.metrics.at("run_solves"),
                    run.metrics.at("run_worst_residual"),
                    run.status.forceResidual, run.status.converged() ? 1 : 0, peak, residuals.c_str());
        std::fflush(stdout);
        if (!run.status.converged())
            status = 1;
        if (firstPeak < 0.0)
            firstPeak = peak;
        else if (std::abs(peak - firstPeak) > 1e-4 * firstPeak)
            status = 1;
    }
    return status;
}

} // namespace

int main(int argc, char** argv)
{
    try
    {
        return run(argc, argv);
    }
    catch (const std::exception& error) // a mesh that is not a wall, a failed factorisation: the reason, exit 1
    {
        std::fprintf(stderr, "bench_fem_static: %s\n", error.what());
        return 1;
    }
}
