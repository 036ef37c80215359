#pragma once

#include "vsim/core/VolumeGeometry.h"
#include "vsim/dicom/DicomScan.h"
#include "vsim/dicom/SliceStack.h"

#include <string>
#include <vector>

namespace vsim::dicom {

/// How a series' slices become one uniform volume grid.
struct SeriesGeometry
{
    VolumeGeometry grid;             ///< the uniform LPS grid the import fills
    std::vector<DicomSlice> sorted;  ///< slices used, sorted along the slice normal, duplicates dropped
    std::vector<double> offsets;     ///< mm along the normal of each sorted slice from the first
    bool resample = false;           ///< the grid is filled by interpolation (tilt, uneven spacing, gaps)
    double tiltDegrees = 0.0;        ///< angle between the slice normal and the direction the slices advance
    int missingSlices = 0;           ///< slices missing from gaps that are whole multiples of the spacing
    int duplicateSlices = 0;         ///< slices dropped because another one has the same position
    std::vector<std::string> warnings;

    /// The source slice planes (in sorted order), for the resampler.
    SliceStack sourceStack(const DicomSeries& series) const;
};

/// Sorts a series along its slice normal and decides the output grid:
/// - duplicate positions (within 0.01 mm): keep the lowest instance number, warn;
/// - spacing: the median distance between neighbours; gaps of whole multiples count as missing slices, other
///   deviations beyond max(0.001 mm, 1 %) as uneven spacing: both resample onto the median spacing, warned;
/// - gantry tilt (the slices advance off their normal by more than a tenth of a pixel over the series): the grid
///   takes the direction of advance as its third axis (an axial grid for a tilt about the x axis), resampled and
///   warned with the angle.
/// Throws vsim::Error when the series lacks position, orientation or pixel spacing.
SeriesGeometry planSeriesGeometry(const DicomSeries& series);

} // namespace vsim::dicom
