// Quasi-static tearing (issue 16 item 6) with its equilibria on the CPU and on the GPU (CudaStaticWall), the same
// modified Newton iteration with multigrid PCG on both, on the thinned tube at a given resolution.
//
//   bench_fem_quasi_static_cuda [layers=1] [around=36] [along=30] [backends=cpu,cuda]
//
// The tube of tests/support/TubeWall.h (r 10 mm, 1.5 mm wall, 100 mm, ends held) thinned by 40 % at 2.0 rad,
// z 40 mm; the thesis's linear material, 0 to 120 kPa in 10 kPa increments, tearing at 0.5 MPa, 4 tears. Prints one
// JSON object per backend: the wall clock of the whole run (s, the GPU's set-ups included), the equilibria, Newton
// updates and PCG iterations, and the tears (onset, first element, count), which must agree between backends.

#include "TubeWall.h"
#include "vsim/cuda_common/DeviceInfo.h"
#include "vsim/cuda_fem/CudaStaticWall.h"
#include "vsim/sim/fem/QuasiStaticTearing.h"

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>

using namespace vsim;

int main(int argc, char** argv)
{
    const std::array<int, 3> cells = {argc > 1 ? std::atoi(argv[1]) : 1, argc > 2 ? std::atoi(argv[2]) : 36,
                                      argc > 3 ? std::atoi(argv[3]) : 30};
    const std::string backends = argc > 4 ? argv[4] : "cpu,cuda";
    const TetMesh wall = test::thinnedTube(2.0, 40.0, cells);
    for (const std::string backend : {"cpu", "cuda"})
    {
        if (backends.find(backend) == std::string::npos)
            continue;
        if (backend == "cuda" && cuda::devices().empty())
        {
            std::printf("SKIP: no CUDA device\n");
            continue;
        }
        sim::fem::QuasiStaticTearingSetup setup = test::thinnedTubeTearing(wall, 10e3);
        setup.modifiedNewton = true;
        if (backend == "cuda")
            setup.equilibriumElsewhere = cuda::cudaStaticWallFactory();
        const auto started = std::chrono::steady_clock::now();
        const sim::fem::FemRunResult run = sim::fem::runQuasiStaticTearing(setup);
        const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
        std::printf("{\"bench\": \"fem_quasi_static\", \"backend\": \"%s\", \"device\": \"%s\", \"cells\": [%d, %d, %d], "
                    "\"tets\": %zu, \"nodes\": %zu, \"seconds\": %.3f, \"equilibria\": %.0f, \"updates\": %ld, "
                    "\"pcg_iterations\": %ld, \"force_residual\": %.2e, \"onset_kpa\": %.4f, \"first_torn_element\": "
                    "%.0f, \"torn\": %.0f}\n",
                    backend.c_str(), backend == "cuda" ? cuda::deviceSummary().c_str() : "host", cells[0], cells[1],
                    cells[2], wall.tets.size(), wall.points.size(), seconds, run.metrics.at("equilibrium_solves"),
                    run.status.solves, run.status.iterations, run.status.forceResidual,
                    run.metrics.at("tear_onset_pressure_mpa") * 1e3, run.metrics.at("first_torn_element"),
                    run.metrics.at("torn_elements"));
        std::fflush(stdout);
    }
    return 0;
}
