#pragma once

// One DICOM file: what the scanner needs from its header, and its pixels converted to HU. DCMTK stays in the
// .cpp files.

#include "vsim/core/Error.h"

#include <Eigen/Core>

#include <cstdint>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace vsim::dicom {

/// Thrown for a file that is not DICOM at all (no parseable dataset); counted apart from damaged DICOM files.
class NotDicomFile : public Error
{
public:
    using Error::Error;
};

/// Thrown for a DICOM file that holds no image (DICOMDIR, structured report, presentation state, ...).
class NotAnImage : public Error
{
public:
    using Error::Error;
};

/// Where one image plane lies and how its stored values map to HU.
struct FrameGeometry
{
    bool hasPosition = false;                               ///< Image Position (Patient) present
    Eigen::Vector3d position = Eigen::Vector3d::Zero();     ///< mm, centre of the first pixel
    bool hasOrientation = false;                            ///< Image Orientation (Patient) present
    Eigen::Vector3d xDirection = Eigen::Vector3d::UnitX();  ///< along a row
    Eigen::Vector3d yDirection = Eigen::Vector3d::UnitY();  ///< down a column
    double columnSpacing = 0.0;                             ///< mm, Pixel Spacing[1]; 0 when absent
    double rowSpacing = 0.0;                                ///< mm, Pixel Spacing[0]; 0 when absent
    double sliceThickness = 0.0;                            ///< mm; 0 when absent
    double rescaleSlope = 1.0;
    double rescaleIntercept = 0.0;
};

/// How the pixel data is stored.
struct PixelFormat
{
    int rows = 0;
    int columns = 0;
    int samplesPerPixel = 1;
    int bitsAllocated = 16;
    int bitsStored = 16;
    int highBit = 15;
    bool isSigned = false;                 ///< Pixel Representation 1
    std::string photometric;               ///< MONOCHROME2, MONOCHROME1, RGB, ...
    std::string transferSyntaxUid;
    bool isGrayscale() const { return samplesPerPixel == 1 && photometric.rfind("MONOCHROME", 0) == 0; }
    std::size_t pixelsPerFrame() const { return std::size_t(rows) * std::size_t(columns); }
};

/// The header of one DICOM image file (classic single-frame or multi-frame, e.g. Enhanced CT).
struct DicomImageHeader
{
    std::filesystem::path file;
    std::string sopClassUid;
    std::string sopInstanceUid;
    std::string studyInstanceUid;
    std::string seriesInstanceUid;
    std::string frameOfReferenceUid;
    std::string modality;
    std::string imageType;             ///< e.g. ORIGINAL\PRIMARY\AXIAL
    int instanceNumber = 0;
    int acquisitionNumber = 0;
    int seriesNumber = 0;
    PixelFormat format;
    std::vector<FrameGeometry> frames; ///< one per frame (1 for classic images)
    /// Byte offset of native little-endian pixel data that ends the file (verified against the element header),
    /// so that decoding can read the frames directly; 0 when unknown (compressed, big endian, trailing elements).
    std::uint64_t pixelDataOffset = 0;
    /// Patient / study / series attributes for the study: patient_name, patient_id, study_description, ...
    std::map<std::string, std::string> attributes;

    bool isLocalizer() const { return imageType.find("LOCALIZER") != std::string::npos; }
};

/// Reads the header of a file without its pixel data. Throws NotDicomFile when it is not DICOM, NotAnImage for
/// DICOM without pixel data, and vsim::Error when it is DICOM but unusable as an image (truncated, no pixel data, unsupported layout).
DicomImageHeader readDicomHeader(const std::filesystem::path& file);

/// Decodes frames of a file to HU (stored value * slope + intercept, rounded, clamped to int16): `frames`
/// lists the frame indices wanted, and frame frames[n] is written to out[n] (each pixelsPerFrame() values).
/// Compressed syntaxes: JPEG (baseline, extended, lossless), JPEG-LS, RLE through DCMTK; JPEG 2000 through GDCM.
/// Returns the number of values clamped to the int16 range. Throws vsim::Error for a damaged or truncated file.
std::size_t decodeFramesToHu(const DicomImageHeader& header, const std::vector<int>& frames,
                             const std::vector<std::int16_t*>& out);

} // namespace vsim::dicom
