#pragma once

// Truth measurements of the patient-like phantoms, computed from their analytic geometry by the clinical
// definitions the measurements dock and the report use (SVS 2018 for the AAA, NASCET-style diameter stenosis).

#include "vsim/dicom/AnatomyPhantom.h"

#include <functional>

namespace vsim::dicom::detail {

/// The aorta of the AAA phantom as functions of patient z (mm).
struct AaaProfile
{
    std::function<double(double)> outerRadius, lumenRadius;        ///< mm
    std::function<Eigen::Vector3d(double)> outerCentre, lumenCentre; ///< mm, patient frame
    double wallMm = 1.8;
    double topZ = 0.0, bottomZ = 0.0; ///< the aorta from topZ down to the bifurcation at bottomZ
    double lowestRenalZ = 0.0;        ///< origin of the lowest renal artery
    double iliacWallMm = 1.2;
};

/// The sac's threshold: its outer diameter exceeds this factor times the neck's.
inline constexpr double kSacNeckFactor = 1.5;
/// The threshold when no neck is available (no renal artery found).
inline constexpr double kSacFallbackDiameterMm = 30.0;

/// Fills phantom.measures and phantom.definitions: maximum outer diameter (SVS) and where, lumen diameter there,
/// largest thrombus thickness, sac (limits, volume), neck (diameter, length, angulation), common iliac diameters.
void measureAaa(const AaaProfile& profile, AnatomyPhantom& phantom);

AnatomyPhantom buildAnatomyAaa(const PhantomOptions& options, const ScannerSettings& scanner);
AnatomyPhantom buildAnatomyHepatic(const PhantomOptions& options, const ScannerSettings& scanner);
AnatomyPhantom buildAnatomyStenosis(const PhantomOptions& options, const ScannerSettings& scanner);

} // namespace vsim::dicom::detail
