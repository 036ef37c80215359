// One implicit step of the wall solver on the GPU (CUDA graph of the whole step) against the CPU path, same meshes.
//
//   bench_fem_cuda [steps=50] [repetitions=3] [cpu=1] [case name: only that mesh, or "all"] [converged]
//
// Closed tube walls (radius 10 mm, wall 1.5 mm, both ends fixed, 16 kPa inside, E = 4.23 MPa, nu = 0.23, h = 1 ms,
// beta = 0.22 s; one step = element pass + assembly + PCG to 1e-6 relative, at most 100 iterations):
//   2,250 vertices (thesis's largest), about 100k tets (0.75 mm elements) and about 1M tets (0.375 mm).
// Prints one JSON object per mesh: median milliseconds per step on the GPU (host clock around step(), launch and
// the per-step copy of the PCG figures included) and, with cpu=1, on the CPU threads of this machine.
// With "converged": every step's PCG to 1e-8 relative (at most 5,000 iterations), once with block Jacobi and once
// with the smoothed-aggregation multigrid (AggregationMultigrid.h), one object per mesh and preconditioner, with
// the solver's set-up time (the multigrid hierarchy is set up on the host) and the steps that did not converge.

#include "vsim/cuda_common/DeviceInfo.h"
#include "vsim/cuda_fem/CudaBackwardEuler.h"
#include "vsim/sim/fem/StructuredMeshes.h"
#include "vsim/core/TetMesh.h"
#include "vsim/sim/fem/SurfaceLoads.h"

#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <string>
#include <vector>

using namespace vsim;
using namespace vsim::sim::fem;

namespace {

struct Setup
{
    StructuredTetMesh mesh;
    std::vector<std::uint8_t> fixed;
    std::vector<std::array<int, 3>> inner;
};

Setup setup(const std::array<int, 3>& cells)
{
    Setup s;
    s.mesh = tubeWallTetMesh(0.01, 0.0115, 0.1, cells);
    s.fixed.assign(3 * s.mesh.points.size(), 0);
    for (std::size_t n = 0; n < s.mesh.points.size(); ++n)
        if (s.mesh.points[n].z() < 1e-9 || s.mesh.points[n].z() > 0.1 - 1e-9)
            s.fixed[3 * n] = s.fixed[3 * n + 1] = s.fixed[3 * n + 2] = 1;
    for (const auto& face : vsim::boundaryFaces(s.mesh.tets))
    {
        bool onInner = true;
        for (int node : face)
            onInner = onInner && s.mesh.points[std::size_t(node)].head<2>().norm() < 0.01 + 1e-9;
        if (onInner)
            s.inner.push_back(face);
    }
    return s;
}

double median(std::vector<double> v)
{
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
}

} // namespace

int main(int argc, char** argv)
{
    const int steps = argc > 1 ? std::stoi(argv[1]) : 50;
    const int repetitions = argc > 2 ? std::stoi(argv[2]) : 3;
    const bool withCpu = argc > 3 ? std::stoi(argv[3]) != 0 : true;
    const std::string only = argc > 4 && std::string(argv[4]) != "all" ? argv[4] : "";
    const bool converged = argc > 5 && std::string(argv[5]) == "converged";
    std::printf("{\"devices\": \"%s\"}\n", cuda::deviceSummary().c_str());
    const std::vector<std::pair<const char*, std::array<int, 3>>> meshes{
        {"tube_2250_vertices", {1, 75, 14}}, {"tube_100k_tets", {2, 84, 100}}, {"tube_1m_tets", {4, 168, 248}}};
    ElasticMaterial material;
    std::vector<BackwardEulerSettings> variants(1);
    if (converged)
    {
        variants[0].cgTolerance = 1e-8, variants[0].cgMaxIterations = 5000;
        variants.push_back(variants[0]);
        variants[1].preconditioner = CgPreconditioner::Multigrid;
    }
    for (const auto& [name, cells] : meshes)
        for (const BackwardEulerSettings& settings : variants)
    {
        if (!only.empty() && only != name)
            continue;
        const Setup s = setup(cells);
        std::vector<double> gpuMs, cpuMs;
        double gpuIterations = 0.0, cpuIterations = 0.0, setupS = 0.0;
        std::size_t bytes = 0;
        int unconverged = 0;
        for (int r = 0; r < repetitions; ++r)
        {
            CorotationalFem model(s.mesh.points, s.mesh.tets, material);
            const auto setupStart = std::chrono::steady_clock::now();
            cuda::CudaBackwardEuler gpu(model, settings, s.fixed, s.inner);
            setupS = std::chrono::duration<double>(std::chrono::steady_clock::now() - setupStart).count();
            bytes = gpu.deviceBytes();
            for (int w = 0; w < 3; ++w)
                gpu.step(16e3);
            long iterations = 0;
            const auto start = std::chrono::steady_clock::now();
            for (int k = 0; k < steps; ++k)
            {
                const StepReport report = gpu.step(16e3);
                iterations += report.cgIterations;
                unconverged += report.cgConverged ? 0 : 1;
            }
            gpuMs.push_back(1e3 * std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() / steps);
            gpuIterations = double(iterations) / steps;
            if (withCpu)
            {
                BackwardEuler integrator(model, settings);
                Eigen::VectorXd forces(model.positions().size());
                const int cpuSteps = std::max(3, steps / (s.mesh.tets.size() > 500000 ? 10 : 1));
                forces.setZero();
                addPressureForces(s.inner, model.positions(), 16e3, forces);
                integrator.step(model, forces, s.fixed); // untimed, as the GPU's warm-up (the multigrid's set-up)
                iterations = 0;
                const auto cpuStart = std::chrono::steady_clock::now();
                for (int k = 0; k < cpuSteps; ++k)
                {
                    forces.setZero();
                    addPressureForces(s.inner, model.positions(), 16e3, forces);
                    const StepReport report = integrator.step(model, forces, s.fixed);
                    iterations += report.cgIterations;
                    unconverged += report.cgConverged ? 0 : 1;
                }
                cpuMs.push_back(1e3 * std::chrono::duration<double>(std::chrono::steady_clock::now() - cpuStart).count() / cpuSteps);
                cpuIterations = double(iterations) / cpuSteps;
            }
        }
        // The same step with one PCG iteration: what the element pass, assembly and graph launch cost alone.
        double oneIterationMs = 0.0;
        if (!converged)
        {
            CorotationalFem model(s.mesh.points, s.mesh.tets, material);
            BackwardEulerSettings single = settings;
            single.cgMaxIterations = 1;
            cuda::CudaBackwardEuler gpu(model, single, s.fixed, s.inner);
            gpu.step(16e3);
            const auto start = std::chrono::steady_clock::now();
            for (int k = 0; k < steps; ++k)
                gpu.step(16e3);
            oneIterationMs = 1e3 * std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() / steps;
        }
        std::printf("{\"case\": \"%s\", \"preconditioner\": \"%s\", \"cg_tolerance\": %.0e, "
                    "\"cg_max_iterations\": %d, \"gpu_setup_s\": %.3f, \"unconverged_solves\": %d, "
                    "\"vertices\": %zu, \"tets\": %zu, \"steps\": %d, \"repetitions\": %d, "
                    "\"gpu_ms_with_1_cg_iteration\": %.3f, "
                    "\"gpu_median_ms_per_step\": %.3f, \"gpu_mean_cg_iterations\": %.1f, \"gpu_memory_mib\": %.0f, "
                    "\"cpu_threads\": %d, \"cpu_median_ms_per_step\": %.3f, \"cpu_mean_cg_iterations\": %.1f}\n",
                    name, settings.preconditioner == CgPreconditioner::Multigrid ? "multigrid" : "block Jacobi",
                    settings.cgTolerance, settings.cgMaxIterations, setupS, unconverged,
                    s.mesh.points.size(), s.mesh.tets.size(), steps, repetitions, oneIterationMs, median(gpuMs), gpuIterations,
                    double(bytes) / (1 << 20), omp_get_max_threads(), withCpu ? median(cpuMs) : 0.0, cpuIterations);
        std::fflush(stdout);
    }
    return 0;
}
