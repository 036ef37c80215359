#pragma once

#include "vsim/core/Progress.h"
#include "vsim/dicom/DicomFile.h"

#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace vsim::dicom {

/// One image plane of a series: a classic image file, or one frame of a multi-frame file.
struct DicomSlice
{
    std::size_t header = 0; ///< index into DicomSeries::headers
    int frame = 0;          ///< frame within that file
};

/// One series as the user picks it: a DICOM series, or a sub-series of one (split by orientation, image size,
/// pixel spacing, image type or acquisition number). All slices share orientation, size and pixel spacing.
struct DicomSeries
{
    std::string key;                 ///< Series Instance UID, plus "#n" for its n-th sub-series (n >= 2)
    std::string studyInstanceUid;
    std::string seriesInstanceUid;
    std::string modality;
    std::string description;
    std::string imageType;
    int seriesNumber = 0;
    std::vector<DicomImageHeader> headers; ///< the files
    std::vector<DicomSlice> slices;        ///< unsorted
    std::vector<std::string> warnings;     ///< what grouping noticed (skipped localizers, split series, ...)

    const DicomImageHeader& headerOf(const DicomSlice& slice) const { return headers[slice.header]; }
    const FrameGeometry& geometryOf(const DicomSlice& slice) const
    {
        return headers[slice.header].frames[std::size_t(slice.frame)];
    }
    const PixelFormat& format() const { return headers.front().format; }
    const FrameGeometry& firstGeometry() const { return geometryOf(slices.front()); }
    /// Patient / study / series attributes (from the first file).
    const std::map<std::string, std::string>& attributes() const { return headers.front().attributes; }
};

/// What a scan found.
struct DicomScanResult
{
    std::vector<DicomSeries> series;        ///< importable series, localizers excluded
    std::size_t filesSeen = 0;
    std::size_t imageFiles = 0;             ///< DICOM images read
    std::size_t nonDicomFiles = 0;          ///< not DICOM at all (skipped)
    std::size_t nonImageFiles = 0;          ///< DICOM without pixel data: DICOMDIR, reports, ... (skipped)
    std::size_t damagedFiles = 0;           ///< DICOM that cannot be read: truncated, corrupt (skipped)
    std::vector<std::string> warnings;      ///< counts of the above, localizers, unusable series

    /// The series with this key or Series Instance UID (its first sub-series); nullptr when absent.
    const DicomSeries* find(const std::string& keyOrUid) const;
    /// The CT series with most slices (any modality when there is no CT); nullptr when there is no series.
    const DicomSeries* defaultSeries() const;
};

/// Scans a folder (recursively), a DICOMDIR (the files it references) or a single file. Reads headers only.
/// Never throws for bad files (they are counted); throws vsim::Error when `input` does not exist, and
/// vsim::Cancelled.
DicomScanResult scanDicom(const std::filesystem::path& input, const Progress& progress = {});

/// Groups headers into series and sub-series, skipping localizers (exposed for tests).
std::vector<DicomSeries> groupIntoSeries(std::vector<DicomImageHeader> headers, std::vector<std::string>& warnings);

} // namespace vsim::dicom
