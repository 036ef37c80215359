#pragma once

// The tumour's lesions in the liver's territories (issue 19, item 3): their coverage from a tip's perfused
// territory, their feeders, catheter positions ranked by coverage, and the perfused territory with them as a label.
//
// Coverage (the technical-success grading of TACE): each lesion (a 6-connected component of the tumour) with a
// margin of 5 mm (longest diameter under 25 mm) or 10 mm (25 mm and over) of liver around it: grade A when the
// lesion and its margin are perfused (kCoveredShare of their voxels: a voxel's width of boundary is forgiven), B
// when the lesion is and the margin only partly, C when the lesion is not. The study's grade is its worst lesion's.
//
// Feeders: the segments whose centerline enters a lesion or its margin (a point of it inside, its upstream node,
// towards the root, outside), and the segments whose tissue holds 1 % of a lesion or more.

#include "vsim/core/ImageVolume.h"
#include "vsim/core/Progress.h"
#include "vsim/core/VesselNetwork.h"
#include "vsim/sim/network/Targeting.h"
#include "vsim/sim/network/Territories.h"

#include <cstdint>
#include <vector>

namespace vsim::sim::network {

/// A lesion or margin counts as covered from this share of its voxels up.
inline constexpr double kCoveredShare = 0.99;

struct Lesion
{
    Eigen::Vector3d centreMm = Eigen::Vector3d::Zero();
    double volumeMl = 0.0;
    double diameterMm = 0.0;         ///< longest diameter (largest distance between two of its voxels' centres)
    double marginMm = 0.0;           ///< 5 or 10
    std::vector<std::size_t> voxels; ///< indices into LiverTerritories::voxels
    std::vector<std::size_t> margin; ///< the margin's liver voxels (not in any lesion)
};

/// The lesions of the territories' tumour, largest first, each with its margin.
std::vector<Lesion> findLesions(const LiverTerritories& territories, const Progress& progress = {});

struct LesionCoverage
{
    double coveredPercent = 0.0;       ///< of the lesion's voxels
    double marginCoveredPercent = 0.0; ///< of its margin's
    char grade = 'C';
};
struct Coverage
{
    std::vector<LesionCoverage> lesions; ///< as findLesions
    char grade = 'C';                    ///< the worst lesion's ('-' when there is none)
};
Coverage tumourCoverage(const std::vector<Lesion>& lesions, const PerfusedTerritory& perfused);

struct Feeder
{
    int segment = -1;
    int lesion = -1;          ///< the first lesion it feeds
    bool entersLesion = false; ///< its centerline enters the lesion or its margin (else: its tissue holds tumour)
    double radiusMm = 0.0;    ///< at its upstream end
    Eigen::Vector3d entryMm = Eigen::Vector3d::Zero(); ///< where it enters the lesion or margin (else: its end nearest the lesion)
    bool byHand = false;      ///< added by the user (automatic detection alone misses feeders: see editFeeders)
    bool reached = false;     ///< the drug from the run's tip flows through it (set by the run)
};
/// The feeders of the lesions (see above), by segment.
std::vector<Feeder> findFeeders(const VesselNetwork& network, const LiverTerritories& territories,
                                const std::vector<Lesion>& lesions);

/// The user's corrections to the feeders found (segments of the run's network): automatic feeder detection alone is
/// far less sensitive than detection the radiologist completes by hand (Iwazawa 2009; Miyayama 2013).
struct FeederEdits
{
    std::vector<int> added;
    std::vector<int> removed;
    bool empty() const { return added.empty() && removed.empty(); }
};
/// `found` less the removed segments, with the added ones (byHand; their lesion the nearest one, the entry their
/// path's point nearest it). Throws vsim::Error for a segment the network lacks or one both added and removed.
std::vector<Feeder> editFeeders(std::vector<Feeder> found, const VesselNetwork& network,
                                const std::vector<Lesion>& lesions, const FeederEdits& edits);

/// Values of territoryLabel.
enum TerritoryLabelValue : std::uint8_t
{
    kLiverNotPerfused = 1,
    kLiverPerfused = 2,
    kTumourPerfused = 3,
    kTumourMissed = 4,   ///< a lesion's voxel not perfused
    kMarginMissed = 5,   ///< a margin's voxel not perfused
};
/// The perfused territory over the liver's grid for viewing over the CT (values above; 0 outside the liver).
LabelVolume territoryLabel(const LiverTerritories& territories, const PerfusedTerritory& perfused,
                           const std::vector<Lesion>& lesions);

/// Every candidate tip (tipCandidates) with the flow from `solve`: ranked by coverage grade, then the lesions'
/// share perfused, then the least non-tumour liver perfused (the more selective), then nearer the root.
std::vector<TipCandidate> rankTipsByCoverage(const VesselNetwork& network, const LiverTerritories& territories,
                                             const std::vector<Lesion>& lesions, const TipSolve& solve,
                                             const Progress& progress = {});

} // namespace vsim::sim::network
