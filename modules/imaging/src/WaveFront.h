#pragma once

// The engine of the guided segmentation (GuidedSegmentation.h): competing geodesic fronts on a work box, advancing
// in waves whose cross-sections are checked for leaks.

#include "vsim/core/ImageVolume.h"
#include "vsim/core/Progress.h"

#include <Eigen/Core>

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace vsim::imaging::detail {

/// One front: where it starts, which voxels it may take, how far it may go.
struct FrontSeed
{
    Eigen::Vector3d pointMm = Eigen::Vector3d::Zero();
    bool include = true;            ///< false: an exclude point (claims voxels, never in the label)
    bool grows = true;              ///< false: a point joined by its minimal path only (VesselPaths.h), no front
    double lowerHu = 0.0, upperHu = 0.0; ///< the smoothed-HU window of this front
    double maxLengthMm = 1e9;       ///< path length limit from the point
    double branchLengthMm = 1e9;    ///< path length allowed into a branch (cross-section < a quarter of the trunk's)
    double inscribedRadiusMm = 0.0; ///< radius of the largest ball of accepted voxels at the point
    double boneHu = 1e9;            ///< include fronts refuse voxels touching raw HU above this (bone, calcium)
    /// The front grows on from a voxel only if its smoothed HU reaches this (hysteresis): voxels between lowerHu and
    /// coreHu are the lumen's partial-volume rim, taken but not crossed, so that a contact with tissue of about
    /// the rim's HU (cancellous bone beside the aorta) is no bridge; in the trunk only, not in its branches.
    /// -inf: no core level.
    double coreHu = -1e30;
    /// The lower level of thin vessels: a voxel reached from a cross-section under WaveSettings::thinAreaMm2 (once
    /// the front has filled its point's lumen) is taken from this smoothed HU up, below lowerHu: the blur dims a
    /// tip under 1 mm below the half level of the blood, not below the tissue's noise. 1e30: no such level.
    double thinHu = 1e30;
    /// The tissue level of the window: a voxel at the thin level must stand (thinHu - tissueHu) above the median of
    /// a shell 1.5 to 2.5 mm around it (a tip does; the inside of a vein as bright as the thin level does not).
    double tissueHu = 0.0;
};

struct WaveSettings
{
    double waveWidthMm = 1.0;       ///< path-length width of one wave
    double leakAreaFactor = 3.0;    ///< a cross-section this many times its ancestors' median is a leak
    double leakMinAreaMm2 = 20.0;   ///< smaller cross-sections are never leaks
    double thinAreaMm2 = 0.0;       ///< cross-sections under this grow on at their front's thinHu
    std::vector<std::pair<Eigen::Vector3d, Eigen::Vector3d>> stops; ///< (point, normal): not crossed by includes
};

struct WaveResult
{
    LabelVolume label;              ///< 1 where an include front took the voxel (not cut as a leak)
    std::size_t waves = 0, leaksCut = 0, workVoxels = 0, limitedVoxels = 0;
    std::size_t thinBursts = 0;     ///< thin-level cross-sections that burst and were blocked (WaveFront.cpp)
    std::vector<std::string> leakNotes; ///< where each leak was cut and the area jump
};

/// Grows every front; the label is on the CT's grid. Throws vsim::Cancelled.
WaveResult propagateFronts(const CtVolume& ct, const std::vector<FrontSeed>& seeds, const WaveSettings& settings,
                           const Progress& progress);

} // namespace vsim::imaging::detail
