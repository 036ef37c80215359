// How evenly a saved SPH run's fluid particles stand (issue 18: the relaxed stenosis runs' late stops were
// clumps and voids in the slow zone past the throat; sim/sph README). Reads a checkpoint
// (bench_sph_cuda_stenosis --checkpoint C saves C, and C.guard where a guard stopped it) and prints one JSON
// object, over the fluid particles (not the walls, not the open ends' buffers) in slabs along x:
//   - how many stand within 0.1 and 0.3 spacings of another fluid particle (a lattice: none; a clump:
//     several),
//   - the least continuity density and the least summation density m_i sum_j W_ij (walls included, scaled
//     so that the seeding lattice reads rho0: SphRates.h), both as rho / rho0 - 1 (a void between clumps
//     reads far below),
//   - the mean of the two densities' difference (the continuity density's drift from the spacing).
//
//   bench_sph_particle_spacing <checkpoint> <spacing mm> [smoothing ratio, default 2] [slab mm, default 0.5]
//
// The rest density is blood's (1060 kg/m^3), as in the stenosis benches; a mixture's particles are read
// against it.

#include "vsim/core/Error.h"
#include "vsim/sim/sph/NeighbourGrid.h"
#include "vsim/sim/sph/QuarticKernel.h"
#include "vsim/sim/sph/SphCheckpoint.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

using namespace vsim;
using namespace vsim::sim::sph;

namespace {

constexpr double kRestDensity = 1060.0; // kg/m^3, blood (StenosisPipe.h)

struct Slab
{
    int fluid = 0, within01 = 0, within03 = 0;
    double leastContinuity = INFINITY, leastSummation = INFINITY, drift = 0.0;
};

} // namespace

int main(int argc, char** argv)
try
{
    if (argc < 3)
    {
        std::fprintf(stderr, "usage: bench_sph_particle_spacing <checkpoint> <spacing mm> [smoothing ratio] "
                             "[slab mm]\n");
        return 2;
    }
    const SphCheckpoint saved = readSphCheckpoint(argv[1]);
    const double spacing = 1e-3 * std::stod(argv[2]); // m
    const double ratio = argc > 3 ? std::stod(argv[3]) : 2.0;
    const double slab = 1e-3 * (argc > 4 ? std::stod(argv[4]) : 0.5); // m
    if (!(spacing > 0.0) || !(ratio > 0.0) || !(slab > 0.0))
        throw Error("the spacing, the smoothing ratio and the slab must be > 0");
    const QuarticKernel kernel(ratio * spacing);
    const double scale = 1.0 / (spacing * spacing * spacing * kernel.latticeSum(spacing)); // SphSolver's
    const ParticleState& p = saved.particles;
    const int n = int(p.size());
    NeighbourGrid grid(kernel.support());
    grid.build(p.position);
    double lowX = INFINITY, highX = -INFINITY;
    for (const auto& x : p.position)
        lowX = std::min(lowX, x.x()), highX = std::max(highX, x.x());
    std::vector<Slab> slabs(std::size_t(std::floor((highX - lowX) / slab)) + 1);
    for (int i = 0; i < n; ++i)
    {
        const std::size_t si = std::size_t(i);
        if (p.wall[si] || p.boundary[si])
            continue;
        double weights = kernel.value(0.0), nearest = INFINITY;
        grid.forEachNeighbour(p.position, i,
                              [&](int j, const Eigen::Vector3d&, double r)
                              {
                                  weights += kernel.value(r);
                                  if (!p.wall[std::size_t(j)] && !p.boundary[std::size_t(j)])
                                      nearest = std::min(nearest, r);
                              });
        const double continuity = p.density[si] / kRestDensity - 1.0;
        const double summation = scale * p.mass[si] * weights / kRestDensity - 1.0;
        Slab& s = slabs[std::size_t((p.position[si].x() - lowX) / slab)];
        ++s.fluid;
        s.within01 += nearest < 0.1 * spacing, s.within03 += nearest < 0.3 * spacing;
        s.leastContinuity = std::min(s.leastContinuity, continuity);
        s.leastSummation = std::min(s.leastSummation, summation);
        s.drift += continuity - summation;
    }
    nlohmann::json rows = nlohmann::json::array();
    int within01 = 0, within03 = 0;
    for (std::size_t k = 0; k < slabs.size(); ++k)
    {
        const Slab& s = slabs[k];
        if (s.fluid == 0)
            continue;
        within01 += s.within01, within03 += s.within03;
        rows.push_back({{"from_x_mm", 1e3 * (lowX + double(k) * slab)},
                        {"fluid", s.fluid},
                        {"within_0_1_spacing", s.within01},
                        {"within_0_3_spacing", s.within03},
                        {"least_continuity_departure", s.leastContinuity},
                        {"least_summation_departure", s.leastSummation},
                        {"mean_continuity_minus_summation", s.drift / s.fluid}});
    }
    const nlohmann::json report = {{"bench", "sph_particle_spacing"},
                                   {"checkpoint_time_s", saved.timeS},
                                   {"steps", saved.steps},
                                   {"particles", n},
                                   {"spacing_mm", 1e3 * spacing},
                                   {"smoothing_ratio", ratio},
                                   {"within_0_1_spacing", within01},
                                   {"within_0_3_spacing", within03},
                                   {"slabs", rows}};
    std::printf("%s\n", report.dump().c_str());
    return 0;
}
catch (const std::exception& error)
{
    std::fprintf(stderr, "bench_sph_particle_spacing: %s\n", error.what());
    return 1;
}
