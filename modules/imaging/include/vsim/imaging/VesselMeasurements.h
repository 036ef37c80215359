#pragma once

// Measurements along centerlines: cross-sections perpendicular to the centerline (area, equivalent, minimal and
// maximal diameter), segment lengths and end radii (the drug-network model needs them), the AAA maximum diameter
// and the worst stenosis (percent diameter and area against the segment's reference).

#include "vsim/core/ImageVolume.h"
#include "vsim/core/Parameters.h"
#include "vsim/core/Progress.h"
#include "vsim/core/SkeletonGraph.h"

#include <Eigen/Core>

#include <vector>

namespace vsim::imaging {

/// section_step_mm, junction_clearance_mm.
std::vector<ParameterSpec> measurementParameters();

struct CrossSection
{
    double arcLengthMm = 0.0;                          ///< along the centerline from its first point
    Eigen::Vector3d centre = Eigen::Vector3d::Zero();  ///< mm
    double areaMm2 = 0.0;
    double equivalentDiameterMm = 0.0;                 ///< 2 sqrt(area / pi)
    double minDiameterMm = 0.0;                        ///< smallest caliper width (Feret) of the section
    double maxDiameterMm = 0.0;                        ///< largest caliper width
    bool nearJunction = false;                         ///< within the clearance of a junction: left out of figures
};

struct SegmentMeasurements
{
    int from = -1, to = -1;
    double lengthMm = 0.0;
    double startRadiusMm = 0.0, endRadiusMm = 0.0;     ///< equivalent radii one clearance in from the ends
    double referenceDiameterMm = 0.0;                  ///< median equivalent diameter
    double minimalDiameterMm = 0.0;                    ///< smallest equivalent diameter
    double diameterStenosisPercent = 0.0;              ///< 100 (1 - minimal / reference)
    double areaStenosisPercent = 0.0;                  ///< 100 (1 - minimal area / reference area)
    /// Largest equivalent diameter of a round section (smallest caliper >= 0.8 x largest) away from junctions: on
    /// voxel labels the area is unbiased while caliper widths catch the staircase (up to half a voxel per side).
    double maxDiameterMm = 0.0;
    double maxCaliperMm = 0.0;                         ///< largest caliper width of those sections
    std::vector<CrossSection> sections;
};

struct VesselMeasurements
{
    std::vector<SegmentMeasurements> segments; ///< one per centerline
    double maxDiameterMm = 0.0;                ///< over every segment: the AAA maximum diameter (see the segment's)
    double maxCaliperMm = 0.0;                 ///< over every segment
    int worstStenosisSegment = -1;             ///< index of the segment with the largest diameter stenosis
};

/// Measures every centerline of `centerlines` in the lumen `label` (value 1). Sections are sampled on a plane
/// grid of a quarter voxel with the label interpolated trilinearly and cut at 0.5, keeping the part connected to
/// the centre. Throws vsim::Error for empty centerlines.
VesselMeasurements measureVessels(const LabelVolume& label, const SkeletonGraph& centerlines,
                                  const ParameterSet& parameters, const Progress& progress = {});

} // namespace vsim::imaging
