#pragma once

// Perfusion territories, tumour coverage and feeders for chemoembolization planning (issue 19, items 2 and 3).
//
// Territories. The CT resolves only the larger arteries; the arterioles that perfuse the tissue leave from all
// along them, terminal or not. So every voxel of the liver (the liver label and the tumour within it) is fed by
// the visible vessel whose centerline is nearest (Euclidean, mm), among the segments that lead to the liver (a
// segment whose outlets downstream all lie outside it feeds no liver). The tissue of a vessel is perfused through
// its hidden side branches; the tests judge the rule against trees grown far below CT resolution. An outlet is
// hepatic when its end lies in the liver or within `hepatic_reach_mm` of it; the others (the gastroduodenal artery
// and its kin) feed no liver tissue.
//
// Outlet resistances (outlet_model 1). Tissue is perfused at one rate per volume, tumour tissue at
// tumour_perfusion_factor times it: a segment's weight is V_liver + f V_tumour of its tissue. The network drains
// only at its outlets, so a segment's side-branch tissue is dealt to the outlets below it in proportion to their
// subtrees' weights: the flow through every segment then goes with the weight of everything it perfuses. Every
// outlet's share of the reference inflow starts from Murray's law (the terminal radius cubed, NetworkRun.h); the
// hepatic outlets' shares together are dealt out again by those weights. Extrahepatic outlets keep their Murray
// share.
//
// A tip's perfused territory: the tissue of the segments the drug reaches, at an injected fraction of at least
// kPerfusedShare of the largest (the fraction below the tip): the tissue takes the drug at the concentration its
// vessel carries, however small that vessel's flow. The drug reaching an outlet is shared within the tissue dealt
// to it by perfusion (f for tumour).
//

#include "vsim/core/ImageVolume.h"
#include "vsim/core/Parameters.h"
#include "vsim/core/Progress.h"
#include "vsim/core/VesselNetwork.h"
#include "vsim/sim/network/FlowSolver.h"

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace vsim::sim::network {

/// The voxels of a label volume holding `value` (any non-zero value when 0).
struct LabelRegion
{
    const LabelVolume* label = nullptr;
    int value = 0;
    bool holds(std::uint8_t v) const { return value == 0 ? v != 0 : int(v) == value; }
    /// The voxel nearest the point (mm) is in the region.
    bool contains(const Eigen::Vector3d& pointMm) const;
};

struct LiverTerritories
{
    VolumeGeometry geometry;            ///< the liver label's grid
    double voxelMl = 0.0;
    std::vector<std::size_t> voxels;    ///< linear indices of the liver's voxels, ascending
    std::vector<char> tumour;           ///< per liver voxel: 1 in the tumour
    std::vector<int> fedBy;             ///< per liver voxel: the segment whose tissue it is
    std::vector<double> volumeMl;       ///< per segment: its tissue (tumour included)
    std::vector<double> tumourVolumeMl; ///< per segment: the tumour in its tissue
    std::vector<int> outlets;           ///< hepatic outlet nodes
    std::vector<int> extrahepatic;      ///< outlet nodes outside the liver
    std::vector<double> outletVolumeMl;       ///< per hepatic outlet: tissue dealt to it (see above)
    std::vector<double> outletTumourVolumeMl; ///< per hepatic outlet: tumour tissue dealt to it
    double tumourPerfusionFactor = 1.0;

    /// Position (mm) of liver voxel `v` (an index into `voxels`).
    Eigen::Vector3d position(std::size_t v) const;
};

/// Parameters of territories, coverage and feeders (group "Territories"): hepatic_reach_mm,
/// tumour_perfusion_factor, outlet_model.
std::vector<ParameterSpec> territoryParameters();

/// The territories of `network`'s outlets in the liver (and the tumour label, when given, which counts as liver
/// too; else `tumourShape`, e.g. a sphere, marks the liver voxels it holds). Throws vsim::Error for an empty liver or
/// a tree with no end in the liver.
LiverTerritories liverTerritories(const VesselNetwork& network, const LabelRegion& liver, const LabelRegion* tumour,
                                  const ParameterSet& parameters, const Progress& progress = {},
                                  const std::function<bool(const Eigen::Vector3d&)>& tumourShape = {});

/// Terminal resistances from the territories (see above) for the outlets without a condition.
void addTerritoryOutlets(VesselNetwork& network, const LiverTerritories& territories, const ParameterSet& parameters);

/// A segment's tissue counts as perfused from this share of the largest injected fraction up.
inline constexpr double kPerfusedShare = 1e-3;

struct PerfusedTerritory
{
    std::vector<char> perfused;      ///< per liver voxel
    std::vector<int> segments;       ///< the segments whose tissue is perfused
    double volumeMl = 0.0;           ///< perfused liver (tumour included)
    double tumourVolumeMl = 0.0;     ///< perfused tumour
    double drugToTumour = 0.0;       ///< shares of the injected drug: reaching tumour tissue,
    double drugToLiver = 0.0;        ///< non-tumour liver,
    double drugExtrahepatic = 0.0;   ///< the extrahepatic outlets,
    double drugElsewhere = 0.0;      ///< and the rest (refluxed to outlets without tissue, or lost to rounding)
    std::vector<std::pair<int, double>> extrahepaticDrug; ///< per extrahepatic outlet node: its share of the drug
};

/// The tip's territory, from a solved flow (its segment flows, injected fractions, outletInjectate, injectedFlow).
PerfusedTerritory perfusedTerritory(const LiverTerritories& territories, const FlowSolution& flow);

} // namespace vsim::sim::network
