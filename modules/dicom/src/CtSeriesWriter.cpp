#include "vsim/dicom/CtSeriesWriter.h"

#include "DcmtkSetup.h"
#include "DecimalString.h"
#include "vsim/core/DicomUid.h"
#include "vsim/core/Localized.h"
#include "vsim/core/ParallelFor.h"
#include "vsim/core/Version.h"

#include <dcmtk/config/osconfig.h>
#include <dcmtk/dcmdata/dcdeftag.h>
#include <dcmtk/dcmdata/dcfilefo.h>
#include <dcmtk/dcmdata/dcrlerp.h>
#include <dcmtk/dcmdata/dcuid.h>
#include <dcmtk/dcmjpeg/djrplol.h>
#include <dcmtk/dcmjpeg/djrploss.h>
#include <dcmtk/dcmjpls/djrparam.h>

#include <chrono>
#include <cstdio>
#include <ctime>
#include <memory>

namespace vsim::dicom {

using detail::decimalString;
using detail::decimalStrings;

namespace {

constexpr int kUnsignedOffset = 1024; // stored = HU + 1024 for unsigned 12-bit storage (intercept -1024)

struct Encoding
{
    E_TransferSyntax xfer;
    std::unique_ptr<DcmRepresentationParameter> parameter; // null: native
};

Encoding encodingOf(TransferSyntax syntax)
{
    switch (syntax)
    {
    case TransferSyntax::ExplicitLittleEndian: return {EXS_LittleEndianExplicit, nullptr};
    case TransferSyntax::ImplicitLittleEndian: return {EXS_LittleEndianImplicit, nullptr};
    case TransferSyntax::JpegLossless: return {EXS_JPEGProcess14SV1, std::make_unique<DJ_RPLossless>(1, 0)};
    case TransferSyntax::JpegLs: return {EXS_JPEGLSLossless, std::make_unique<DJLSRepresentationParameter>(0, OFTrue)};
    case TransferSyntax::Rle: return {EXS_RLELossless, std::make_unique<DcmRLERepresentationParameter>()};
    case TransferSyntax::JpegExtended: return {EXS_JPEGProcess2_4, std::make_unique<DJ_RPLossy>(90)};
    }
    throw Error("unknown transfer syntax");
}

std::string today(const char* format)
{
    const std::time_t now = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
    std::tm local{};
    localtime_r(&now, &local);
    char buffer[16];
    std::strftime(buffer, sizeof buffer, format, &local);
    return buffer;
}

void put(DcmItem& item, const DcmTagKey& tag, const std::string& value)
{
    const OFCondition status = item.putAndInsertString(tag, value.c_str());
    if (status.bad())
        throw Error("cannot set a DICOM attribute", {{"tag", DcmTag(tag).getTagName()}, {"reason", status.text()}});
}

DcmItem& subItem(DcmItem& parent, const DcmTagKey& sequence, long index = 0)
{
    DcmItem* item = nullptr;
    if (parent.findOrCreateSequenceItem(sequence, item, index).bad() || !item)
        throw Error("cannot create a DICOM sequence item", {{"tag", DcmTag(sequence).getTagName()}});
    return *item;
}

/// The attributes every file of the series shares.
struct SeriesContext
{
    const CtSeriesDescription& description;
    const SliceStack& stack;
    std::string studyUid, seriesUid, frameUid, studyDate, studyTime;
    double intercept;
    int bitsStored;
    double sliceThickness;
};

void putSharedModules(DcmItem& dataset, const SeriesContext& context, bool enhanced)
{
    const CtSeriesDescription& d = context.description;
    put(dataset, DCM_SpecificCharacterSet, "ISO_IR 100");
    put(dataset, DCM_SOPClassUID, enhanced ? UID_EnhancedCTImageStorage : UID_CTImageStorage);
    // Patient
    put(dataset, DCM_PatientName, d.patientName);
    put(dataset, DCM_PatientID, d.patientId);
    put(dataset, DCM_PatientBirthDate, d.patientBirthDate);
    put(dataset, DCM_PatientSex, d.patientSex);
    // General study
    put(dataset, DCM_StudyInstanceUID, context.studyUid);
    put(dataset, DCM_StudyDate, context.studyDate);
    put(dataset, DCM_StudyTime, context.studyTime);
    put(dataset, DCM_ReferringPhysicianName, "");
    put(dataset, DCM_StudyID, "1");
    put(dataset, DCM_AccessionNumber, "");
    put(dataset, DCM_StudyDescription, d.studyDescription);
    // General series
    put(dataset, DCM_Modality, "CT");
    put(dataset, DCM_SeriesInstanceUID, context.seriesUid);
    put(dataset, DCM_SeriesNumber, std::to_string(d.seriesNumber));
    put(dataset, DCM_SeriesDate, context.studyDate);
    put(dataset, DCM_SeriesTime, context.studyTime);
    put(dataset, DCM_SeriesDescription, d.seriesDescription);
    put(dataset, DCM_PatientPosition, "HFS");
    put(dataset, DCM_BodyPartExamined, "ABDOMEN");
    // Frame of reference
    put(dataset, DCM_FrameOfReferenceUID, context.frameUid);
    put(dataset, DCM_PositionReferenceIndicator, "");
    // General equipment
    put(dataset, DCM_Manufacturer, "VascuSim phantom generator");
    put(dataset, DCM_ManufacturerModelName, "vascusim-cli phantom");
    put(dataset, DCM_SoftwareVersions, kVersion);
    // Contrast / CT acquisition
    put(dataset, DCM_ContrastBolusAgent, "IODINATED CONTRAST");
    put(dataset, DCM_KVP, "100");
    put(dataset, DCM_ConvolutionKernel, "STANDARD");
    put(dataset, DCM_AcquisitionNumber, std::to_string(d.acquisitionNumber));
    put(dataset, DCM_ImageType, enhanced ? "ORIGINAL\\PRIMARY\\VOLUME\\NONE" : d.imageType);
    // Image pixel
    put(dataset, DCM_SamplesPerPixel, "1");
    put(dataset, DCM_PhotometricInterpretation, "MONOCHROME2");
    put(dataset, DCM_Rows, std::to_string(context.stack.rows));
    put(dataset, DCM_Columns, std::to_string(context.stack.columns));
    put(dataset, DCM_BitsAllocated, "16");
    put(dataset, DCM_BitsStored, std::to_string(context.bitsStored));
    put(dataset, DCM_HighBit, std::to_string(context.bitsStored - 1));
    put(dataset, DCM_PixelRepresentation, d.signedPixels ? "1" : "0");
    // VOI LUT: CTA and soft-tissue windows
    put(dataset, DCM_WindowCenter, "200\\40");
    put(dataset, DCM_WindowWidth, "700\\400");
    put(dataset, DCM_WindowCenterWidthExplanation, "CTA\\SOFT TISSUE");
}

std::string orientationText(const SliceStack& stack)
{
    const auto& x = stack.xDirection;
    const auto& y = stack.yDirection;
    return decimalStrings({x.x(), x.y(), x.z(), y.x(), y.y(), y.z()});
}

/// Classic CT Image Storage: plane and rescale attributes at the top level.
void putPlaneModules(DcmItem& dataset, const SeriesContext& context, std::size_t slice)
{
    const SliceStack& stack = context.stack;
    const Eigen::Vector3d& p = stack.positions[slice];
    put(dataset, DCM_ImagePositionPatient, decimalStrings({p.x(), p.y(), p.z()}));
    put(dataset, DCM_ImageOrientationPatient, orientationText(stack));
    put(dataset, DCM_SliceLocation, decimalString(p.dot(stack.normal())));
    put(dataset, DCM_PixelSpacing, decimalStrings({stack.rowSpacing, stack.columnSpacing}));
    put(dataset, DCM_SliceThickness, decimalString(context.sliceThickness));
    put(dataset, DCM_RescaleIntercept, decimalString(context.intercept));
    put(dataset, DCM_RescaleSlope, "1");
    put(dataset, DCM_RescaleType, "HU");
}

/// Enhanced CT: shared and per-frame functional groups.
void putFunctionalGroups(DcmItem& dataset, const SeriesContext& context)
{
    const SliceStack& stack = context.stack;
    DcmItem& shared = subItem(dataset, DCM_SharedFunctionalGroupsSequence);
    DcmItem& measures = subItem(shared, DCM_PixelMeasuresSequence);
    put(measures, DCM_PixelSpacing, decimalStrings({stack.rowSpacing, stack.columnSpacing}));
    put(measures, DCM_SliceThickness, decimalString(context.sliceThickness));
    put(subItem(shared, DCM_PlaneOrientationSequence), DCM_ImageOrientationPatient, orientationText(stack));
    DcmItem& rescale = subItem(shared, DCM_PixelValueTransformationSequence);
    put(rescale, DCM_RescaleIntercept, decimalString(context.intercept));
    put(rescale, DCM_RescaleSlope, "1");
    put(rescale, DCM_RescaleType, "HU");
    put(subItem(shared, DCM_CTImageFrameTypeSequence), DCM_FrameType, "ORIGINAL\\PRIMARY\\VOLUME\\NONE");
    for (std::size_t f = 0; f < stack.positions.size(); ++f)
    {
        DcmItem& frame = subItem(dataset, DCM_PerFrameFunctionalGroupsSequence, -2);
        const Eigen::Vector3d& p = stack.positions[f];
        put(subItem(frame, DCM_PlanePositionSequence), DCM_ImagePositionPatient, decimalStrings({p.x(), p.y(), p.z()}));
        put(subItem(frame, DCM_FrameContentSequence), DCM_InStackPositionNumber, std::to_string(f + 1));
    }
    put(dataset, DCM_NumberOfFrames, std::to_string(stack.positions.size()));
}

std::vector<Uint16> storedValues(const std::int16_t* hu, std::size_t count, bool signedPixels)
{
    std::vector<Uint16> stored(count);
    for (std::size_t i = 0; i < count; ++i)
    {
        if (signedPixels)
        {
            stored[i] = Uint16(hu[i]);
            continue;
        }
        const int value = hu[i] + kUnsignedOffset;
        if (value < 0 || value > 4095)
            throw Error("HU value outside -1024..3071 cannot be stored in 12 unsigned bits",
                        {{"value", std::to_string(hu[i])}});
        stored[i] = Uint16(value);
    }
    return stored;
}

void saveEncoded(DcmFileFormat& file, const Encoding& encoding, const std::filesystem::path& path)
{
    DcmDataset& dataset = *file.getDataset();
    if (encoding.parameter)
    {
        const OFCondition status = dataset.chooseRepresentation(encoding.xfer, encoding.parameter.get());
        if (status.bad() || !dataset.canWriteXfer(encoding.xfer))
            throw Error("cannot encode the pixel data", {{"reason", status.text()}});
    }
    const OFCondition status = file.saveFile(path.string().c_str(), encoding.xfer, EET_ExplicitLength);
    if (status.bad())
        throw Error("cannot write DICOM file", {{"file", path.string()}, {"reason", status.text()}});
}

std::string fileName(const CtSeriesDescription& description, std::size_t number)
{
    char buffer[16];
    std::snprintf(buffer, sizeof buffer, "%06zu", number);
    return description.fileNamePrefix + buffer;
}

} // namespace

std::string transferSyntaxName(TransferSyntax syntax)
{
    switch (syntax)
    {
    case TransferSyntax::ExplicitLittleEndian: return "explicit-le";
    case TransferSyntax::ImplicitLittleEndian: return "implicit-le";
    case TransferSyntax::JpegLossless: return "jpeg-lossless";
    case TransferSyntax::JpegLs: return "jpeg-ls";
    case TransferSyntax::Rle: return "rle";
    case TransferSyntax::JpegExtended: return "jpeg-extended";
    }
    return {};
}

TransferSyntax transferSyntaxFromName(const std::string& name)
{
    for (TransferSyntax syntax : {TransferSyntax::ExplicitLittleEndian, TransferSyntax::ImplicitLittleEndian,
                                  TransferSyntax::JpegLossless, TransferSyntax::JpegLs, TransferSyntax::Rle,
                                  TransferSyntax::JpegExtended})
        if (transferSyntaxName(syntax) == name)
            return syntax;
    throw Error(Pattern{"unknown transfer syntax '%1'; known: explicit-le, implicit-le, jpeg-lossless, jpeg-ls, rle, "
                        "jpeg-extended",
                        {name}});
}

WrittenSeries writeCtSeries(const CtVolume& pixels, const SliceStack& stack, const CtSeriesDescription& description,
                            const std::filesystem::path& folder, const Progress& progress)
{
    const VolumeGeometry& geometry = pixels.geometry();
    if (pixels.isEmpty() || geometry.dims[0] != stack.columns || geometry.dims[1] != stack.rows ||
        std::size_t(geometry.dims[2]) != stack.positions.size())
        throw Error("the pixels and the slice stack of a CT series disagree");
    if (description.fileNamePrefix.size() > 2)
        throw Error("file name prefix must have at most 2 characters (8-character DICOMDIR names)");
    ensureDcmtkCodecs();
    std::error_code error;
    std::filesystem::create_directories(folder, error);
    if (error)
        throw Error("cannot create the output folder", {{"folder", folder.string()}, {"reason", error.message()}});

    SeriesContext context{description,
                          stack,
                          description.studyInstanceUid.empty() ? newDicomUid() : description.studyInstanceUid,
                          description.seriesInstanceUid.empty() ? newDicomUid() : description.seriesInstanceUid,
                          description.frameOfReferenceUid.empty() ? newDicomUid() : description.frameOfReferenceUid,
                          description.studyDate.empty() ? today("%Y%m%d") : description.studyDate,
                          today("%H%M%S"),
                          description.signedPixels ? 0.0 : -double(kUnsignedOffset),
                          description.signedPixels ? 16 : 12,
                          geometry.spacing.z()};
    const std::size_t perSlice = std::size_t(stack.columns) * std::size_t(stack.rows);
    WrittenSeries written{{}, context.studyUid, context.seriesUid};

    if (description.enhancedMultiFrame)
    {
        DcmFileFormat file;
        DcmDataset& dataset = *file.getDataset();
        putSharedModules(dataset, context, true);
        put(dataset, DCM_SOPInstanceUID, newDicomUid());
        put(dataset, DCM_InstanceNumber, std::to_string(description.firstInstanceNumber));
        put(dataset, DCM_ContentDate, context.studyDate);
        put(dataset, DCM_ContentTime, context.studyTime);
        putFunctionalGroups(dataset, context);
        const std::vector<Uint16> stored = storedValues(pixels.data(), pixels.size(), description.signedPixels);
        dataset.putAndInsertUint16Array(DCM_PixelData, stored.data(), static_cast<unsigned long>(stored.size()));
        progress.report(0.5, localized("vsim::Progress", "writing DICOM"));
        written.files.push_back(folder / fileName(description, 1));
        saveEncoded(file, encodingOf(description.transferSyntax), written.files.back());
        progress.report(1.0, localized("vsim::Progress", "writing DICOM"));
        return written;
    }

    const std::size_t slices = stack.positions.size();
    written.files.resize(slices);
    parallelFor(
        slices,
        [&](std::size_t k) {
            DcmFileFormat file;
            DcmDataset& dataset = *file.getDataset();
            putSharedModules(dataset, context, false);
            put(dataset, DCM_SOPInstanceUID, newDicomUid());
            const int instance = description.firstInstanceNumber + int(k);
            put(dataset, DCM_InstanceNumber, std::to_string(instance));
            putPlaneModules(dataset, context, k);
            const std::vector<Uint16> stored =
                storedValues(pixels.data() + k * perSlice, perSlice, description.signedPixels);
            dataset.putAndInsertUint16Array(DCM_PixelData, stored.data(), static_cast<unsigned long>(stored.size()));
            written.files[k] = folder / fileName(description, std::size_t(instance));
            saveEncoded(file, encodingOf(description.transferSyntax), written.files[k]);
        },
        [&](std::size_t done) { progress.report(double(done) / double(slices), localized("vsim::Progress", "writing DICOM")); });
    return written;
}

} // namespace vsim::dicom
