#pragma once

#include "vsim/core/ImageVolume.h"
#include "vsim/core/Progress.h"
#include "vsim/dicom/DicomScan.h"

#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace vsim::dicom {

struct DicomImportOptions
{
    /// Refuse a series needing more memory than this (bytes); 0: the memory available now (MemAvailable).
    std::uint64_t memoryLimitBytes = 0;
    unsigned threads = 0; ///< decoding threads; 0: one per hardware thread
};

/// A series made into one CT volume.
struct DicomVolume
{
    CtVolume image;                                ///< HU, uniform LPS grid
    std::map<std::string, std::string> attributes; ///< patient / study / series attributes, series_key, ...
    std::vector<std::string> warnings;             ///< grouping, geometry and value-range warnings
};

/// Decodes a series into a volume: sorted along the normal, rescaled to HU, resampled when the geometry plan
/// says so (see planSeriesGeometry). Refuses before allocating when the memory needed exceeds the limit (the
/// message gives both sizes). Throws vsim::Error for an undecodable slice, vsim::Cancelled when cancelled.
DicomVolume importDicomSeries(const DicomSeries& series, const DicomImportOptions& options = {},
                              const Progress& progress = {});

/// Memory (bytes) the import of a series needs at its peak.
std::uint64_t importMemoryNeeded(const DicomSeries& series);

/// A size x size greyscale preview of the series' middle slice (CTA window 700/200, aspect kept, black border).
std::vector<std::uint8_t> seriesThumbnail(const DicomSeries& series, int size);

} // namespace vsim::dicom
