#pragma once

// The boundary of a vessel label moved to the local half level of the scanner-blurred edge: half-way between the
// vessel's own plateau (its brightest smoothed HU within 2 mm) and the background just outside it (the median HU of
// the voxels 1 to 2.5 mm from the candidate that lie at least a voxel from the label: the tissue the edge blurs
// with, a dark arterial wall included). A blurred step edge
// crosses the half-way level at the step whatever the blur's width; a blurred tube's edge is curved, and its true
// radius reads 0.44-0.47 of the contrast at its centre while the radius is 2-6 blur sigmas (the level used is 0.45 of
// the way, LocalHalfLevel.cpp); a thin vessel's blurred peak is lower than its blood. One window for a whole tree puts the edge too far in where the vessel runs in fat and too far
// out beside brighter tissue; the local level follows the background. References: "Vessel size measurements in
// angiograms: a comparison of techniques", Med. Phys. 2002, doi:10.1118/1.1488603 (threshold and edge sizing are
// accurate for vessels wider than the blur's FWHM); Wörz and Rohr, IEEE Trans. Image Process. 2007 (a 3D blurred-
// cylinder model for the thinner ones).

#include "vsim/core/ImageVolume.h"

#include <array>
#include <cstddef>
#include <functional>

namespace vsim::imaging::detail {

struct HalfLevelChange
{
    std::size_t added = 0, removed = 0, passes = 0;
};

/// Moves the boundary of `label` (nonzero inside) by up to `passes` voxels; the movable voxels are looked for in
/// the box from `searchLow` of `searchSize` voxels. `mayMove(i, j, k)` says whether a voxel
/// may change: an inside voxel may be removed, an outside one added (the caller keeps other structures' voxels and
/// wide vessels fixed). A voxel is added or kept when its raw HU reaches the local half level and stays under
/// twice its plateau's contrast (calcium and bone beside a lumen are never added).
HalfLevelChange moveToLocalHalfLevel(const CtVolume& ct, LabelVolume& label, const std::array<int, 3>& searchLow,
                                     const std::array<int, 3>& searchSize,
                                     const std::function<bool(int, int, int)>& mayMove, int passes);

} // namespace vsim::imaging::detail
