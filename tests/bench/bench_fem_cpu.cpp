// Implicit steps per second of the co-rotational wall solver on the CPU.
//
//   bench_fem_cpu [steps=300] [repetitions=3]
//
// Two closed tube walls (radius 10 mm, wall 1.5 mm, one layer of elements through the wall as the wall mesher
// builds it from a lumen surface, E = 4.23 MPa, nu = 0.23,
// Rayleigh beta = 0.22 s, h = 1 ms, both ends fixed) under a 16 kPa (120 mmHg) follower pressure: 2,250 vertices
// (the thesis's largest mesh has 2,251; thesis Table 4.3: 1.5-2.1 FPS on its CPU, 21.2-29.8 on its GPU) and
// about 20,000 tets (the interactive GUI case). One step = rotations + assembly + pressure + PCG to 1e-6 (at most
// 100 iterations). Prints one JSON object per mesh with the median steps/s; exit 1 when the 2,250-vertex mesh
// runs under 200 steps/s or the 20k-tet one under 30.

#include "vsim/sim/fem/BackwardEuler.h"
#include "vsim/sim/fem/StructuredMeshes.h"
#include "vsim/core/TetMesh.h"
#include "vsim/sim/fem/SurfaceLoads.h"

#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <cstdio>
#include <string>
#include <vector>

using namespace vsim::sim::fem;

namespace {

struct Figures
{
    double stepsPerSecond = 0.0;
    double meanCgIterations = 0.0;
    double elementPassShare = 0.0;
    double radialGrowthUm = 0.0;
};

Figures run(const StructuredTetMesh& mesh, int steps)
{
    ElasticMaterial material;
    material.youngModulusPa = 4.23e6;
    material.poissonRatio = 0.23;
    CorotationalFem model(mesh.points, mesh.tets, material);
    std::vector<std::uint8_t> fixed(3 * model.nodeCount(), 0);
    std::vector<std::array<int, 3>> inner;
    for (std::size_t n = 0; n < model.nodeCount(); ++n)
        if (mesh.points[n].z() < 1e-9 || mesh.points[n].z() > 0.1 - 1e-9)
            fixed[3 * n] = fixed[3 * n + 1] = fixed[3 * n + 2] = 1;
    for (const auto& face : vsim::boundaryFaces(mesh.tets))
    {
        bool onInner = true;
        for (int node : face)
            onInner = onInner && mesh.points[std::size_t(node)].head<2>().norm() < 0.01 + 1e-9;
        if (onInner)
            inner.push_back(face);
    }
    BackwardEulerSettings settings;
    if (const char* cap = std::getenv("VSIM_BENCH_CG_MAX"))
        settings.cgMaxIterations = std::atoi(cap);
    BackwardEuler integrator(model, settings);
    Eigen::VectorXd forces(model.positions().size());
    long cgIterations = 0;
    const auto start = std::chrono::steady_clock::now();
    for (int step = 0; step < steps; ++step)
    {
        forces.setZero();
        addPressureForces(inner, model.positions(), 16e3, forces);
        cgIterations += integrator.step(model, forces, fixed).cgIterations;
    }
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    Figures figures;
    figures.stepsPerSecond = steps / elapsed;
    figures.meanCgIterations = double(cgIterations) / steps;
    // Radial growth of the mid-length inner ring: the wall is inflating (a sanity figure, not a check).
    double growth = 0.0;
    int count = 0;
    for (std::size_t n = 0; n < model.nodeCount(); ++n)
        if (std::abs(mesh.points[n].z() - 0.05) < 1e-6 && mesh.points[n].head<2>().norm() < 0.01 + 1e-9)
        {
            growth += (model.positions().segment<2>(Eigen::Index(3 * n)) - mesh.points[n].head<2>()).dot(mesh.points[n].head<2>().normalized());
            ++count;
        }
    figures.radialGrowthUm = count ? 1e6 * growth / count : 0.0;
    return figures;
}

} // namespace

int main(int argc, char** argv)
{
    const int steps = argc > 1 ? std::stoi(argv[1]) : 300;
    const int repetitions = argc > 2 ? std::stoi(argv[2]) : 3;
    struct Case
    {
        const char* name;
        StructuredTetMesh mesh;
        double required;
    };
    std::vector<Case> cases{{"tube_2250_vertices", tubeWallTetMesh(0.01, 0.0115, 0.1, {1, 75, 14}), 200.0},
                            {"tube_20k_tets", tubeWallTetMesh(0.01, 0.0115, 0.1, {1, 128, 26}), 30.0}};
    bool ok = true;
    for (Case& c : cases)
    {
        std::vector<Figures> runs;
        for (int r = 0; r < repetitions; ++r)
            runs.push_back(run(c.mesh, steps));
        std::sort(runs.begin(), runs.end(), [](const Figures& a, const Figures& b) { return a.stepsPerSecond < b.stepsPerSecond; });
        const Figures& median = runs[runs.size() / 2];
        std::printf("{\"case\": \"%s\", \"vertices\": %zu, \"tets\": %zu, \"threads\": %d, \"steps\": %d, "
                    "\"repetitions\": %d, \"median_steps_per_s\": %.1f, \"mean_cg_iterations\": %.1f, "
                    "\"mid_radial_growth_um\": %.2f, \"required_steps_per_s\": %.0f}\n",
                    c.name, c.mesh.points.size(), c.mesh.tets.size(), omp_get_max_threads(), steps, repetitions,
                    median.stepsPerSecond, median.meanCgIterations, median.radialGrowthUm, c.required);
        ok = ok && median.stepsPerSecond >= c.required;
    }
    return ok ? 0 : 1;
}
