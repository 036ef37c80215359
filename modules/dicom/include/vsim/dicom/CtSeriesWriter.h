#pragma once

#include "vsim/core/ImageVolume.h"
#include "vsim/core/Progress.h"
#include "vsim/dicom/SliceStack.h"

#include <filesystem>
#include <string>
#include <vector>

namespace vsim::dicom {

enum class TransferSyntax
{
    ExplicitLittleEndian, ///< "explicit-le" 1.2.840.10008.1.2.1
    ImplicitLittleEndian, ///< "implicit-le" 1.2.840.10008.1.2
    JpegLossless,         ///< "jpeg-lossless" process 14, selection value 1 (1.2.840.10008.1.2.4.70)
    JpegLs,               ///< "jpeg-ls" lossless (1.2.840.10008.1.2.4.80)
    Rle,                  ///< "rle" (1.2.840.10008.1.2.5)
    JpegExtended,         ///< "jpeg-extended" lossy 12-bit process 2/4 (1.2.840.10008.1.2.4.51): for tests of lossy input
};

/// The names of the CLI: "explicit-le", "implicit-le", "jpeg-lossless", "jpeg-ls", "rle", "jpeg-extended".
std::string transferSyntaxName(TransferSyntax syntax);
/// Throws vsim::Error for an unknown name (listing the known ones).
TransferSyntax transferSyntaxFromName(const std::string& name);

/// Identity and encoding of a written CT series. Empty UIDs are generated; empty dates become today.
struct CtSeriesDescription
{
    std::string patientName = "PHANTOM^VASCUSIM";
    std::string patientId = "VSIM-PHANTOM";
    std::string patientBirthDate = "19600101";
    std::string patientSex = "O";
    std::string studyDescription = "CT angiography phantom";
    std::string seriesDescription = "CTA arterial phase";
    std::string studyInstanceUid;
    std::string seriesInstanceUid;
    std::string frameOfReferenceUid;
    std::string studyDate;              ///< YYYYMMDD
    int seriesNumber = 1;
    int acquisitionNumber = 1;
    std::string imageType = "ORIGINAL\\PRIMARY\\AXIAL";
    TransferSyntax transferSyntax = TransferSyntax::ExplicitLittleEndian;
    /// One Enhanced CT Image Storage file with per-frame functional groups instead of one file per slice.
    bool enhancedMultiFrame = false;
    /// Store HU directly as signed values (intercept 0) instead of unsigned HU + 1024 (intercept -1024).
    bool signedPixels = false;
    std::string fileNamePrefix = "IM";  ///< files IM000001, ...: 8 characters, usable in a DICOMDIR
    int firstInstanceNumber = 1;
};

struct WrittenSeries
{
    std::vector<std::filesystem::path> files;
    std::string studyInstanceUid;
    std::string seriesInstanceUid;
};

/// Writes `pixels` (HU, one slice per k, in stack order) as a CT series in `folder` (created if needed), with
/// the patient, general study, general series, frame of reference, equipment, image plane, image pixel, CT
/// image, VOI LUT (CTA and soft tissue windows) and SOP common modules, then encodes it in the requested
/// transfer syntax. Values must lie in -1024..3071 HU for unsigned storage (12 bits stored). Throws vsim::Error
/// when a value does not fit, the stack and pixels disagree, or a file cannot be written.
WrittenSeries writeCtSeries(const CtVolume& pixels, const SliceStack& stack, const CtSeriesDescription& description,
                            const std::filesystem::path& folder, const Progress& progress = {});

} // namespace vsim::dicom
