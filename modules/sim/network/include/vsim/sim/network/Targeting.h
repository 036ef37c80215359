#pragma once

// Chemoembolization targeting: the outlets that feed a tumour, the share of the injected drug that reaches it, and
// candidate catheter-tip positions ranked by that share.

#include "vsim/core/Progress.h"
#include "vsim/core/VesselNetwork.h"
#include "vsim/sim/network/FlowSolver.h"

#include <functional>
#include <vector>

namespace vsim::sim::network {

/// A tumour as a sphere (mm).
struct TumourSphere
{
    Eigen::Vector3d centreMm = Eigen::Vector3d::Zero();
    double radiusMm = 0.0;
    bool contains(const Eigen::Vector3d& pointMm) const { return (pointMm - centreMm).norm() <= radiusMm; }
    /// contains() as a region for NetworkRunSetup::tumour; throws vsim::Error for a radius that is not positive.
    std::function<bool(const Eigen::Vector3d&)> region() const;
};

/// The end nodes (not the root) inside the region: the terminal segments that feed the tumour.
std::vector<int> feedingOutlets(const VesselNetwork& network, const std::function<bool(const Eigen::Vector3d&)>& inside);

/// The share of the injected fluid leaving through `outlets` (FlowSolution::outletInjectate over injectedFlow).
double deliveredFraction(const FlowSolution& flow, const std::vector<int>& outlets);

struct TipCandidate
{
    int node = -1;
    double tumourFraction = 0.0;   ///< share of the injected drug reaching the tumour (its outlets, or its tissue)
    int depth = 0;                 ///< segments from the root
    double radiusMm = 0.0;         ///< largest vessel radius at the node (catheter access)
    char grade = '-';              ///< with territories: the coverage grade from here
    double coveredPercent = 0.0;   ///< with territories: the lesions' voxels perfused from here
    double nonTargetMl = 0.0;      ///< with territories: non-tumour liver perfused from here
};

/// The candidate tip positions: every node that is not an end, and the root; with their depth and radius.
std::vector<TipCandidate> tipCandidates(const VesselNetwork& network);

/// The flow with the catheter tip at a node (the run's model: the injected fluid alone, or carried by blood).
using TipSolve = std::function<FlowSolution(int tipNode)>;

/// Every node that is not an end (and the root) as the catheter tip, the flow from `solve`; ranked by tumour share,
/// then nearer the root first (the less selective, easier position).
std::vector<TipCandidate> rankTipPositions(const VesselNetwork& network, const std::vector<int>& feeders,
                                           const TipSolve& solve, const Progress& progress = {});

} // namespace vsim::sim::network
