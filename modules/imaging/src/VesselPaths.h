#pragma once

// Joins include points whose fronts stopped short of the trunk to the trunk's label along a minimal path on
// vesselness, and gives the path its lumen. On a portal-venous CT a small artery's front is cut back at every contact
// with the brighter portal vein or the liver beside it (a leak); the path follows the tube instead of the intensity.

#include "Vesselness.h"
#include "WaveFront.h"

#include <string>
#include <vector>

namespace vsim::imaging::detail {

struct PathSettings
{
    double marginMm = 30.0;       ///< the search box: the include points' bounding box grown by this (mm)
    VesselnessScales scales{0.75, 2.0, 4, 50.0}; ///< arteries of 1.5 to 4 mm across
    double costFloor = 0.02;      ///< cost per mm of path = 1 / (vesselness + floor): 50 off a tube, ~2 on its axis
    double tubeRadiusMm = 3.0;    ///< the lumen grown around the path stays this close to it (mm)
};

struct PathResult
{
    std::size_t joined = 0;       ///< points joined by a path
    std::size_t voxelsAdded = 0;  ///< label voxels added (paths and their lumens)
    double pathMm = 0.0;          ///< total length of the paths (mm)
    double dimPathMm = 0.0;       ///< length of path whose voxels lie below their half level (mm)
    std::vector<std::string> notes; ///< points that could not be joined, dim stretches
};

/// Joins every point of `points` whose voxel is not in the trunk point's 26-connected piece of `label` to that
/// piece (or to a path already joined), the points nearest the trunk first: Dijkstra on the 26-neighbour graph of the search box, step cost =
/// length (mm) x the mean of 1 / (vesselness + floor) at its two ends; voxels touching bone (raw HU above the seed's
/// boneHu) are not crossed. The path's lumen: voxels within tubeRadiusMm of a path voxel, connected to it, whose raw
/// HU reaches the half level between the path voxel's plateau (the brightest smoothed HU within 1 mm) and its
/// background (the median raw HU 2.5 to 4 mm away). Reference: minimal paths for vessel extraction, Deschamps and
/// Cohen, Med. Image Anal. 2001; Frangi et al., MICCAI 1998. Throws vsim::Cancelled.
PathResult joinByMinimalPaths(const CtVolume& ct, LabelVolume& label, const FrontSeed& trunk,
                              const std::vector<FrontSeed>& points, const PathSettings& settings, const Progress& progress);

} // namespace vsim::imaging::detail
