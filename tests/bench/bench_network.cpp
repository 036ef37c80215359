// The drug network's speed on one core (issue 6: a 10,000-segment tree solves in <= 10 ms; 1,000 filling steps
// run in <= 1 s). A seeded random tree (NetworkBuild.h) with Murray-law outlets, 2 ml/min at its root:
//
//   bench_network [segments=10000] [repetitions=9] [filling steps=1000]
//
// Prints one JSON object: the median of `repetitions` steady solves (sparse Kirchhoff, long double LDL^T) and of
// the filling (every segment's filled length at each of the steps from the start to the last outlet's arrival).

#include "vsim/core/Units.h"
#include "vsim/sim/network/Filling.h"
#include "vsim/sim/network/NetworkBuild.h"
#include "vsim/sim/network/NetworkRun.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <string>
#include <vector>

using namespace vsim;
using namespace vsim::sim::network;

namespace {

double median(std::vector<double> v)
{
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
}

double since(std::chrono::steady_clock::time_point start)
{
    return 1e3 * std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

} // namespace

int main(int argc, char** argv)
{
    const int segments = argc > 1 ? std::stoi(argv[1]) : 10000;
    const int repetitions = argc > 2 ? std::stoi(argv[2]) : 9;
    const int steps = argc > 3 ? std::stoi(argv[3]) : 1000;
    VesselNetwork network = randomTree(segments, 20261122);
    addDefaultOutlets(network, ParameterSet(networkParameters()));
    const Injection injection{0, units::mlPerMinToM3PerS(2.0), 0.0};
    std::vector<double> solveMs, fillingMs;
    FlowSolution flow;
    double checksum = 0.0;
    for (int r = 0; r < repetitions; ++r)
    {
        auto start = std::chrono::steady_clock::now();
        flow = solveFlow(network, injection, 3.2e-3);
        solveMs.push_back(since(start));
        start = std::chrono::steady_clock::now();
        const FillingTimes times = fillingTimes(network, flow);
        std::vector<double> lengths;
        for (int step = 1; step <= steps; ++step)
        {
            filledLengths(network, flow, times, times.lastArrival * step / steps, lengths);
            checksum += lengths[std::size_t(step) % lengths.size()];
        }
        fillingMs.push_back(since(start));
    }
    std::printf("{\"case\": \"random_tree\", \"segments\": %d, \"outlets\": %zu, \"repetitions\": %d, "
                "\"solve_median_ms\": %.3f, \"filling_steps\": %d, \"filling_median_ms\": %.1f, "
                "\"conservation_error\": %.2e, \"checksum\": %.6g}\n",
                segments, flow.outletFlow.size(), repetitions, median(solveMs), steps, median(fillingMs),
                flow.conservationError, checksum);
    return 0;
}
