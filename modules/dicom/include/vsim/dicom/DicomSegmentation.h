#pragma once

// DICOM Segmentation objects (SEG, SOP class 1.2.840.10008.5.1.4.1.1.66.4; PS3.3 A.51): labels from other programs
// (3D Slicer, TotalSegmentator, vendor workstations) read onto a volume, and VascuSim's labels written as SEG.
// Reading parses the dataset itself (PS3.3 C.8.20, the multi-frame functional groups C.7.6.16): 1-bit BINARY frames
// packed across frame boundaries, 8-bit FRACTIONAL frames (set where over half the maximum fractional value); the
// frames may come in any order and hold any of the segments. Writing uses DCMTK's dcmseg (BINARY).

#include "vsim/core/ImageVolume.h"

#include <filesystem>
#include <string>
#include <vector>

namespace vsim::dicom {

/// True when `file` is a readable DICOM file of SOP class Segmentation Storage.
bool isDicomSegmentation(const std::filesystem::path& file);

struct SegmentationMask
{
    /// On the SEG's own grid (its frames' orientation, pixel spacing and positions); each voxel holds the number of
    /// the segment that covers it, 0 elsewhere.
    CtVolume mask;
    std::vector<std::string> segmentLabels; ///< by segment number - 1
    std::vector<std::string> warnings;      ///< overlapping segments (the higher number kept), gaps between frames
};

/// Reads a DICOM SEG. Throws vsim::Error for a file that is not a SEG, frames of several orientations, positions
/// that are not a regular stack, missing geometry or pixel data, or a grid over `maxVoxels` (checked before
/// anything that size is allocated).
SegmentationMask readDicomSegmentation(const std::filesystem::path& file, std::size_t maxVoxels = std::size_t(1) << 30);

/// What a written SEG says about itself and the CT it belongs to: its study and frame of reference, and, when the
/// CT's instances are known slice by slice, the images each frame was derived from (Derivation Image Sequence per
/// frame, Referenced Series Sequence of the Common Instance Reference module).
struct SegmentationDescription
{
    std::string seriesDescription = "VascuSim vessel labels";
    std::string frameOfReferenceUid;         ///< the CT's frame of reference ("" generates one)
    std::string studyInstanceUid;            ///< "" generates one
    std::string patientName = "ANONYMOUS", patientId = "VSIM";
    std::string sourceSeriesUid;             ///< the CT's Series Instance UID ("" writes no references)
    std::string sourceSopClassUid;           ///< the CT images' SOP Class UID
    std::vector<std::string> sourceSopInstanceUids; ///< one per slice of the label's grid (else no references)
};

/// Writes `label` (values 1..N) as a BINARY DICOM SEG: segment N holds value N (named by `segmentNames[N - 1]` or
/// "segment N"; a value the label does not use gets a segment without frames, so that the values read back as
/// they were), one frame per slice and segment that holds any voxel. Throws vsim::Error.
void writeDicomSegmentation(const LabelVolume& label, const std::vector<std::string>& segmentNames,
                            const SegmentationDescription& description, const std::filesystem::path& file);

} // namespace vsim::dicom
