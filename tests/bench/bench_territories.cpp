// Chemoembolization planning's speed on a full-size liver (issue 19: territories, feeders and coverage for one tip
// on a 512 x 512 x 400 liver <= 2 s on 2 cores; ranking 50 candidate tips <= 10 s). The liver: an ellipsoid of
// 95 x 75 x 65 mm semi-axes (1.94 l) in a 512 x 512 x 400 grid at 0.7 x 0.7 x 0.8 mm, its tree grown to 20,000
// hidden terminals (tests/support/GrownTree.h), a 28 mm tumour; the visible tree from 0.75 mm radius.
//
//   bench_territories [repetitions=3]
//
// Prints one JSON object with medians: the territories (every liver voxel to its nearest vessel), the lesion and
// its margin, one tip (flow, perfused territory, coverage, feeders), and the ranking of every candidate tip.

#include "GrownTree.h"

#include "vsim/core/Median.h"
#include "vsim/core/Units.h"
#include "vsim/sim/network/NetworkRun.h"
#include "vsim/sim/network/Lesions.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <string>
#include <thread>
#include <vector>

using namespace vsim;
using namespace vsim::sim::network;

namespace {

/// Seconds since `start`.
double secondsSince(std::chrono::steady_clock::time_point start)
{
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

} // namespace

int main(int argc, char** argv)
{
    const int repetitions = argc > 1 ? std::stoi(argv[1]) : 3;
    test::GrowthOptions options;
    options.dims = {512, 512, 400};
    options.spacingMm = {0.7, 0.7, 0.8};
    options.semiAxesMm = {95.0, 75.0, 65.0};
    options.tumourRadiusMm = 14.0;
    const test::GrownTree g = test::growTree(options);
    VesselNetwork network = g.visible;
    const ParameterSet parameters(networkParameters());
    const LabelRegion liver{&g.liver, 1}, tumour{&g.tumour, 1};
    std::vector<double> territories, lesions, oneTip, ranking;
    std::size_t voxels = 0, candidates = 0;
    for (int r = 0; r < repetitions; ++r)
    {
        auto start = std::chrono::steady_clock::now();
        const LiverTerritories t = liverTerritories(network, liver, &tumour, parameters);
        territories.push_back(secondsSince(start));
        voxels = t.voxels.size();
        start = std::chrono::steady_clock::now();
        const std::vector<Lesion> found = findLesions(t);
        lesions.push_back(secondsSince(start));
        VesselNetwork withOutlets = network;
        addTerritoryOutlets(withOutlets, t, parameters);
        const TipSolve solve = [&](int tip) {
            return solveFlow(withOutlets, {tip, units::mlPerMinToM3PerS(2.0), 0.0}, 3.5e-3);
        };
        start = std::chrono::steady_clock::now();
        const PerfusedTerritory perfused = perfusedTerritory(t, solve(withOutlets.root));
        const Coverage coverage = tumourCoverage(found, perfused);
        const std::vector<Feeder> feeders = findFeeders(withOutlets, t, found);
        oneTip.push_back(secondsSince(start));
        start = std::chrono::steady_clock::now();
        candidates = rankTipsByCoverage(withOutlets, t, found, solve).size();
        ranking.push_back(secondsSince(start));
        if (coverage.grade != 'A' || feeders.empty())
            std::fprintf(stderr, "unexpected: grade %c from the root, %zu feeders\n", coverage.grade, feeders.size());
    }
    const double perTip = median(ranking) / double(candidates);
    std::printf("{\n  \"benchmark\": \"territories\",\n  \"grid\": [512, 512, 400],\n  \"spacing_mm\": [0.7, 0.7, 0.8],\n"
                "  \"liver_voxels\": %zu,\n  \"visible_segments\": %zu,\n  \"threads\": %u,\n  \"repetitions\": %d,\n"
                "  \"territories_s\": %.3f,\n  \"lesion_and_margin_s\": %.3f,\n  \"one_tip_s\": %.3f,\n"
                "  \"territories_lesion_one_tip_s\": %.3f,\n  \"ranked_tips\": %zu,\n  \"ranking_s\": %.3f,\n"
                "  \"ranking_50_tips_s\": %.3f\n}\n",
                voxels, network.segments.size(), std::thread::hardware_concurrency(), repetitions, median(territories),
                median(lesions), median(oneTip), median(territories) + median(lesions) + median(oneTip), candidates,
                median(ranking), 50.0 * perTip);
    return 0;
}
