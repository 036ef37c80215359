// Reading a DICOM SEG from its dataset (DicomSegmentation.h): the frames' geometry from the functional groups
// (per-frame first, then shared), the segment of each frame, the pixel data unpacked.

#include "vsim/dicom/DicomSegmentation.h"

#include "DcmtkSetup.h"
#include "FunctionalGroups.h"

#include "vsim/core/Error.h"
#include "vsim/core/StoredText.h"

#include <dcmtk/config/osconfig.h>
#include <dcmtk/dcmdata/dcdeftag.h>
#include <dcmtk/dcmdata/dcfilefo.h>
#include <dcmtk/dcmdata/dcsequen.h>
#include <dcmtk/dcmdata/dcuid.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <map>

namespace vsim::dicom {
namespace {

using detail::functionalGroup;

using Eigen::Vector3d;

std::vector<double> numbers(DcmItem* item, const DcmTagKey& tag, unsigned long count, const std::string& what)
{
    std::vector<double> values(count);
    for (unsigned long n = 0; n < count; ++n)
        if (!item || item->findAndGetFloat64(tag, values[n], n).bad())
            throw Error(Pattern{"the DICOM SEG has no %1 for every frame: its geometry is unknown", {what}});
    return values;
}

struct Frame
{
    Vector3d position;
    int segment = 0;
};

} // namespace

bool isDicomSegmentation(const std::filesystem::path& file)
{
    ensureDcmtkCodecs();
    DcmFileFormat format;
    if (!std::filesystem::is_regular_file(file) || format.loadFile(file.c_str(), EXS_Unknown, EGL_noChange, 4096).bad())
        return false;
    OFString sopClass;
    return format.getDataset()->findAndGetOFString(DCM_SOPClassUID, sopClass).good() &&
           sopClass == UID_SegmentationStorage;
}

SegmentationMask readDicomSegmentation(const std::filesystem::path& file, std::size_t maxVoxels)
{
    ensureDcmtkCodecs();
    DcmFileFormat format;
    if (format.loadFile(file.c_str()).bad())
        throw Error(Pattern{"cannot read %1 as DICOM", {file.filename().string()}});
    DcmDataset* ds = format.getDataset();
    OFString sopClass, type;
    if (ds->findAndGetOFString(DCM_SOPClassUID, sopClass).bad() || sopClass != UID_SegmentationStorage)
        throw Error(Pattern{"%1 is not a DICOM Segmentation object (SOP class %2)",
                            {file.filename().string(), sopClass.c_str()}});
    Uint16 rows = 0, columns = 0, bits = 0, maxFraction = 255;
    Sint32 frameCount = 0;
    ds->findAndGetUint16(DCM_Rows, rows);
    ds->findAndGetUint16(DCM_Columns, columns);
    ds->findAndGetUint16(DCM_BitsAllocated, bits);
    ds->findAndGetSint32(DCM_NumberOfFrames, frameCount);
    ds->findAndGetOFString(DCM_SegmentationType, type);
    const bool binary = type == "BINARY";
    if (!binary)
        ds->findAndGetUint16(DCM_MaximumFractionalValue, maxFraction);
    if (rows == 0 || columns == 0 || frameCount <= 0 || (binary ? bits != 1 : bits != 8))
        throw Error(Pattern{"the DICOM SEG's image description is incomplete or unsupported (rows %1, columns %2, "
                            "frames %3, %4 bits, type %5)",
                            {std::to_string(rows), std::to_string(columns), std::to_string(frameCount),
                             std::to_string(bits), type.c_str()}});

    SegmentationMask result;
    DcmSequenceOfItems* segments = nullptr;
    if (ds->findAndGetSequence(DCM_SegmentSequence, segments).good() && segments)
        for (unsigned long n = 0; n < segments->card(); ++n)
        {
            Uint16 number = 0;
            OFString label;
            segments->getItem(n)->findAndGetUint16(DCM_SegmentNumber, number);
            segments->getItem(n)->findAndGetOFString(DCM_SegmentLabel, label);
            if (number >= 1 && number <= 255)
            {
                result.segmentLabels.resize(std::max<std::size_t>(result.segmentLabels.size(), number));
                result.segmentLabels[number - 1u] = label.c_str();
            }
        }

    DcmItem* shared = nullptr;
    ds->findAndGetSequenceItem(DCM_SharedFunctionalGroupsSequence, shared, 0);
    DcmSequenceOfItems* perFrame = nullptr;
    ds->findAndGetSequence(DCM_PerFrameFunctionalGroupsSequence, perFrame);
    if (!perFrame || perFrame->card() != unsigned(frameCount))
        throw Error("the DICOM SEG's per-frame functional groups do not match its number of frames");
    const std::vector<double> orientation =
        numbers(functionalGroup(perFrame->getItem(0), shared, DCM_PlaneOrientationSequence), DCM_ImageOrientationPatient, 6,
                "image orientation");
    const std::vector<double> pixelSpacing =
        numbers(functionalGroup(perFrame->getItem(0), shared, DCM_PixelMeasuresSequence), DCM_PixelSpacing, 2, "pixel spacing");
    const Vector3d rowDirection(orientation[0], orientation[1], orientation[2]);
    const Vector3d columnDirection(orientation[3], orientation[4], orientation[5]);
    const Vector3d normal = rowDirection.cross(columnDirection).normalized();
    std::vector<Frame> frames(static_cast<std::size_t>(frameCount));
    for (Sint32 f = 0; f < frameCount; ++f)
    {
        DcmItem* item = perFrame->getItem(unsigned(f));
        const std::vector<double> o = numbers(functionalGroup(item, shared, DCM_PlaneOrientationSequence),
                                              DCM_ImageOrientationPatient, 6, "image orientation");
        for (int n = 0; n < 6; ++n)
            if (std::abs(o[std::size_t(n)] - orientation[std::size_t(n)]) > 1e-4)
                throw Error("the DICOM SEG's frames have several orientations: not one volume");
        const std::vector<double> p = numbers(functionalGroup(item, shared, DCM_PlanePositionSequence),
                                              DCM_ImagePositionPatient, 3, "image position");
        frames[std::size_t(f)].position = Vector3d(p[0], p[1], p[2]);
        Uint16 segment = 0;
        DcmItem* identification = functionalGroup(item, shared, DCM_SegmentIdentificationSequence);
        if (!identification || identification->findAndGetUint16(DCM_ReferencedSegmentNumber, segment).bad() ||
            segment < 1 || segment > 255)
            throw Error(Pattern{"frame %1 of the DICOM SEG names no segment (1..255)", {std::to_string(f + 1)}});
        frames[std::size_t(f)].segment = segment;
    }

    // The stack: the frames' distances along the normal, on a regular spacing (frames with nothing are often left
    // out, so the spacing is the smallest step and every step a whole multiple of it).
    std::vector<double> along;
    for (const Frame& frame : frames)
        along.push_back(frame.position.dot(normal));
    std::vector<double> levels = along;
    std::sort(levels.begin(), levels.end());
    levels.erase(std::unique(levels.begin(), levels.end(), [](double a, double b) { return std::abs(a - b) < 1e-3; }),
                 levels.end());
    double step = 0.0;
    for (std::size_t n = 1; n < levels.size(); ++n)
        step = step == 0.0 ? levels[n] - levels[n - 1] : std::min(step, levels[n] - levels[n - 1]);
    if (levels.size() == 1)
    {
        DcmItem* measures = functionalGroup(perFrame->getItem(0), shared, DCM_PixelMeasuresSequence);
        if (!measures || (measures->findAndGetFloat64(DCM_SpacingBetweenSlices, step).bad() &&
                          measures->findAndGetFloat64(DCM_SliceThickness, step).bad()) || !(step > 0.0))
            step = 1.0;
    }
    const double first = levels.front();
    for (double level : levels)
    {
        const double steps = (level - first) / step;
        if (std::abs(steps - std::round(steps)) > 0.01)
            throw Error(Pattern{"the DICOM SEG's frames are not a regular stack (positions along the normal are not "
                                "whole multiples of %1 mm apart)",
                                {std::to_string(step)}});
    }
    const Frame& lowest = frames[std::size_t(std::min_element(along.begin(), along.end()) - along.begin())];
    VolumeGeometry g;
    g.dims = {int(columns), int(rows), int(std::lround((levels.back() - first) / step)) + 1};
    g.spacing = Vector3d(pixelSpacing[1], pixelSpacing[0], step);
    g.direction.col(0) = rowDirection.normalized();
    g.direction.col(1) = columnDirection.normalized();
    g.direction.col(2) = normal;
    g.origin = lowest.position;
    for (const Frame& frame : frames) // every frame in the plane grid of the lowest one
    {
        const Vector3d offset = frame.position - g.origin;
        if ((offset - offset.dot(normal) * normal).norm() > 0.01 * g.spacing.head<2>().minCoeff() + 1e-3)
            throw Error("the DICOM SEG's frames are shifted within their planes: not one volume");
    }
    if (g.dims[2] > 4096 || g.voxelCount() > maxVoxels)
        throw Error(Pattern{"the DICOM SEG's grid is too large (%1 x %2 x %3 voxels)",
                            {std::to_string(g.dims[0]), std::to_string(g.dims[1]), std::to_string(g.dims[2])}});

    const Uint8* pixels = nullptr;
    unsigned long bytes = 0;
    if (ds->findAndGetUint8Array(DCM_PixelData, pixels, &bytes).bad() || !pixels)
        throw Error("the DICOM SEG has no readable pixel data (compressed SEG objects are not supported)");
    const std::size_t perFrame1 = std::size_t(rows) * columns;
    const std::size_t needed = binary ? (perFrame1 * std::size_t(frameCount) + 7) / 8 : perFrame1 * std::size_t(frameCount);
    if (bytes < needed)
        throw Error(Pattern{"the DICOM SEG's pixel data is shorter than its frames (%1 of %2 bytes)",
                            {std::to_string(bytes), std::to_string(needed)}});
    result.mask = CtVolume(g);
    std::fill(result.mask.data(), result.mask.data() + g.voxelCount(), std::int16_t(0));
    std::size_t overlaps = 0;
    for (std::size_t f = 0; f < frames.size(); ++f)
    {
        const int k = int(std::lround((along[f] - first) / step));
        for (std::size_t n = 0; n < perFrame1; ++n)
        {
            const std::size_t bit = f * perFrame1 + n;
            const bool set = binary ? (pixels[bit / 8] >> (bit % 8)) & 1u
                                    : 2u * pixels[f * perFrame1 + n] > maxFraction;
            if (!set)
                continue;
            std::int16_t& voxel = result.mask.at(int(n % columns), int(n / columns), k);
            overlaps += voxel != 0 && voxel != frames[f].segment;
            voxel = std::int16_t(std::max<int>(voxel, frames[f].segment));
        }
    }
    if (overlaps > 0)
        result.warnings.push_back(storedText(Pattern{
            "%1 voxels belong to several segments: the higher segment number is kept", {std::to_string(overlaps)}}));
    return result;
}

} // namespace vsim::dicom
