#pragma once

#include "vsim/core/Progress.h"
#include "vsim/dicom/CtSeriesWriter.h"
#include "vsim/dicom/PhantomModel.h"

#include <filesystem>

namespace vsim::dicom {

/// What writePhantom() put on disk.
struct PhantomFiles
{
    std::filesystem::path dicomFolder; ///< <out>/dicom: the CT series
    std::filesystem::path truthJson;   ///< <out>/truth.json
    std::filesystem::path truthLabels; ///< <out>/truth-label.nrrd (gzip)
    WrittenSeries series;
    VolumeGeometry geometry;           ///< the axial grid of the series

    /// Every file the phantom writer wrote (series, truth, the folder's marker): what may be removed again.
    std::vector<std::filesystem::path> written() const;
};

/// Identity of a phantom series: patient "PHANTOM^<KIND>", ID "VSIM-<KIND>", descriptions naming the kind.
CtSeriesDescription phantomSeriesDescription(PhantomKind kind);

/// Builds, renders and writes a phantom: the CT series (axial, options' size and spacing), truth.json and
/// truth-label.nrrd into `out`, a new, empty or earlier phantom folder (claimOutputFolder "phantom"). Throws
/// vsim::Error for a folder holding other files, invalid options or a write failure, vsim::Cancelled when cancelled.
PhantomFiles writePhantom(PhantomKind kind, const PhantomOptions& options, const CtSeriesDescription& description,
                          const std::filesystem::path& out, const Progress& progress = {});

} // namespace vsim::dicom
