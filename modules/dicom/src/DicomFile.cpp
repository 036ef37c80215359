#include "vsim/dicom/DicomFile.h"

#include "DatasetText.h"
#include "DcmtkSetup.h"
#include "FunctionalGroups.h"

#include <dcmtk/config/osconfig.h>
#include <dcmtk/dcmdata/dcdeftag.h>
#include <dcmtk/dcmdata/dcfilefo.h>
#include <dcmtk/dcmdata/dcmetinf.h>
#include <dcmtk/dcmdata/dcpixel.h>
#include <dcmtk/dcmdata/dcpixseq.h>
#include <dcmtk/dcmdata/dcpxitem.h>
#include <dcmtk/dcmdata/dcuid.h>
#include <dcmtk/dcmdata/dcxfer.h>
#include <gdcmJPEG2000Codec.h>
#include <gdcmSequenceOfFragments.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <fstream>
#include <limits>

namespace vsim::dicom {
namespace {

using detail::functionalGroup;

constexpr Uint32 kHeaderReadLength = 4096; // bytes; longer values (pixel data) stay on disk until accessed

std::string text(DcmItem& item, const DcmTagKey& tag)
{
    return detail::datasetText(item, tag);
}

int integer(DcmItem& item, const DcmTagKey& tag, int fallback = 0)
{
    Sint32 value = 0;
    return item.findAndGetSint32(tag, value).good() ? int(value) : fallback;
}

int unsignedShort(DcmItem& item, const DcmTagKey& tag, int fallback = 0)
{
    Uint16 value = 0;
    return item.findAndGetUint16(tag, value).good() ? int(value) : fallback;
}

/// Reads `count` decimal values; false when any is missing or not finite.
bool decimals(DcmItem& item, const DcmTagKey& tag, double* values, int count)
{
    for (int n = 0; n < count; ++n)
    {
        Float64 value = 0;
        if (item.findAndGetFloat64(tag, value, n).bad() || !std::isfinite(value))
            return false;
        values[n] = value;
    }
    return true;
}

/// Reads whatever of position, orientation, spacing and rescale one item holds into `geometry`.
void readPlaneAttributes(DcmItem& item, FrameGeometry& geometry)
{
    double v[6];
    if (decimals(item, DCM_ImagePositionPatient, v, 3))
    {
        geometry.position = {v[0], v[1], v[2]};
        geometry.hasPosition = true;
    }
    if (decimals(item, DCM_ImageOrientationPatient, v, 6))
    {
        const Eigen::Vector3d x(v[0], v[1], v[2]), y(v[3], v[4], v[5]);
        if (x.norm() > 0.5 && y.norm() > 0.5 && std::abs(x.normalized().dot(y.normalized())) < 1e-3)
        {
            geometry.xDirection = x.normalized();
            geometry.yDirection = y.normalized();
            geometry.hasOrientation = true;
        }
    }
    if (decimals(item, DCM_PixelSpacing, v, 2) && v[0] > 0 && v[1] > 0)
    {
        geometry.rowSpacing = v[0];
        geometry.columnSpacing = v[1];
    }
    if (decimals(item, DCM_SliceThickness, v, 1) && v[0] > 0)
        geometry.sliceThickness = v[0];
    if (decimals(item, DCM_RescaleSlope, v, 1) && v[0] != 0.0)
        geometry.rescaleSlope = v[0];
    if (decimals(item, DCM_RescaleIntercept, v, 1))
        geometry.rescaleIntercept = v[0];
}

std::vector<FrameGeometry> readFrames(DcmDataset& dataset, int frameCount)
{
    FrameGeometry common;
    readPlaneAttributes(dataset, common);
    DcmItem* shared = nullptr;
    dataset.findAndGetSequenceItem(DCM_SharedFunctionalGroupsSequence, shared, 0);
    DcmSequenceOfItems* perFrameSequence = nullptr;
    dataset.findAndGetSequence(DCM_PerFrameFunctionalGroupsSequence, perFrameSequence);
    if (!shared && !perFrameSequence)
        return std::vector<FrameGeometry>(std::size_t(frameCount), common);

    std::vector<FrameGeometry> frames;
    frames.reserve(std::size_t(frameCount));
    for (int f = 0; f < frameCount; ++f)
    {
        FrameGeometry geometry = common;
        DcmItem* perFrame =
            perFrameSequence && f < int(perFrameSequence->card()) ? perFrameSequence->getItem(unsigned(f)) : nullptr;
        for (const DcmTagKey& macro : {DCM_PlanePositionSequence, DCM_PlaneOrientationSequence,
                                       DCM_PixelMeasuresSequence, DCM_PixelValueTransformationSequence})
            if (DcmItem* item = functionalGroup(perFrame, shared, macro))
                readPlaneAttributes(*item, geometry);
        frames.push_back(geometry);
    }
    return frames;
}

DicomImageHeader headerOf(DcmFileFormat& fileFormat, const std::filesystem::path& file)
{
    DcmDataset& dataset = *fileFormat.getDataset();
    DicomImageHeader header;
    header.file = file;
    header.sopClassUid = text(dataset, DCM_SOPClassUID);
    if (header.sopClassUid.empty())
        header.sopClassUid = text(*fileFormat.getMetaInfo(), DCM_MediaStorageSOPClassUID);
    if (!dataset.tagExists(DCM_PixelData))
    {
        if (header.sopClassUid.empty() && !dataset.tagExists(DCM_StudyInstanceUID))
            throw NotDicomFile("not a DICOM file");
        throw NotAnImage("DICOM file without pixel data", {{"sop_class", header.sopClassUid}});
    }
    header.sopInstanceUid = text(dataset, DCM_SOPInstanceUID);
    header.studyInstanceUid = text(dataset, DCM_StudyInstanceUID);
    header.seriesInstanceUid = text(dataset, DCM_SeriesInstanceUID);
    header.frameOfReferenceUid = text(dataset, DCM_FrameOfReferenceUID);
    header.modality = text(dataset, DCM_Modality);
    header.imageType = text(dataset, DCM_ImageType);
    header.instanceNumber = integer(dataset, DCM_InstanceNumber);
    header.acquisitionNumber = integer(dataset, DCM_AcquisitionNumber);
    header.seriesNumber = integer(dataset, DCM_SeriesNumber);

    PixelFormat& format = header.format;
    format.rows = unsignedShort(dataset, DCM_Rows);
    format.columns = unsignedShort(dataset, DCM_Columns);
    format.samplesPerPixel = unsignedShort(dataset, DCM_SamplesPerPixel, 1);
    format.bitsAllocated = unsignedShort(dataset, DCM_BitsAllocated, 16);
    format.bitsStored = unsignedShort(dataset, DCM_BitsStored, format.bitsAllocated);
    format.highBit = unsignedShort(dataset, DCM_HighBit, format.bitsStored - 1);
    format.isSigned = unsignedShort(dataset, DCM_PixelRepresentation) == 1;
    format.photometric = text(dataset, DCM_PhotometricInterpretation);
    format.transferSyntaxUid = DcmXfer(dataset.getOriginalXfer()).getXferID();
    if (format.rows <= 0 || format.columns <= 0)
        throw Error("DICOM image has no rows or columns");
    if (format.bitsAllocated != 8 && format.bitsAllocated != 16)
        throw Error(Pattern{"unsupported pixel layout: %1 bits allocated", {std::to_string(format.bitsAllocated)}});
    if (format.bitsStored < 1 || format.bitsStored > format.bitsAllocated || format.highBit >= format.bitsAllocated ||
        format.highBit + 1 < format.bitsStored)
        throw Error("inconsistent Bits Stored / High Bit");
    const int frameCount = integer(dataset, DCM_NumberOfFrames, 1);
    if (frameCount < 1 || frameCount > 65535)
        throw Error(Pattern{"invalid Number of Frames: %1", {std::to_string(frameCount)}});
    header.frames = readFrames(dataset, frameCount);

    const std::pair<const char*, DcmTagKey> attributes[] = {
        {"patient_name", DCM_PatientName},           {"patient_id", DCM_PatientID},
        {"patient_birth_date", DCM_PatientBirthDate}, {"patient_sex", DCM_PatientSex},
        {"study_instance_uid", DCM_StudyInstanceUID}, {"study_date", DCM_StudyDate},
        {"study_time", DCM_StudyTime},               {"study_description", DCM_StudyDescription},
        {"accession_number", DCM_AccessionNumber},   {"study_id", DCM_StudyID},
        {"series_instance_uid", DCM_SeriesInstanceUID}, {"series_date", DCM_SeriesDate},
        {"series_description", DCM_SeriesDescription}, {"series_number", DCM_SeriesNumber},
        {"modality", DCM_Modality},                  {"manufacturer", DCM_Manufacturer},
        {"manufacturer_model", DCM_ManufacturerModelName}, {"body_part_examined", DCM_BodyPartExamined},
        {"convolution_kernel", DCM_ConvolutionKernel}, {"kvp", DCM_KVP},
        {"contrast_agent", DCM_ContrastBolusAgent},  {"frame_of_reference_uid", DCM_FrameOfReferenceUID},
        {"patient_position", DCM_PatientPosition}};
    for (const auto& [key, tag] : attributes)
        if (std::string value = text(dataset, tag); !value.empty())
            header.attributes[key] = value;
    return header;
}

bool hasDicomPreamble(const std::filesystem::path& file)
{
    std::ifstream stream(file, std::ios::binary);
    char magic[4] = {};
    stream.seekg(128);
    return stream.read(magic, 4) && std::memcmp(magic, "DICM", 4) == 0;
}

/// Stored value -> HU for one frame. Returns the number of clamped values. The common CT layouts (all bits
/// stored from bit 0, integer intercept, slope 1) take a branch-free loop the compiler vectorises.
template <typename Stored>
std::size_t storedToHu(const Stored* stored, std::size_t count, const PixelFormat& format,
                       const FrameGeometry& geometry, std::int16_t* out)
{
    constexpr std::int32_t kLow = std::numeric_limits<std::int16_t>::min(), kHigh = std::numeric_limits<std::int16_t>::max();
    const int shift = format.highBit + 1 - format.bitsStored;
    const std::uint32_t mask = (std::uint32_t(1) << format.bitsStored) - 1u;
    const std::int32_t signBit = std::int32_t(1) << (format.bitsStored - 1);
    const double slope = geometry.rescaleSlope, intercept = geometry.rescaleIntercept;
    std::size_t clamped = 0;
    if (shift == 0 && slope == 1.0 && intercept == std::round(intercept) && std::abs(intercept) < 65536.0)
    {
        const std::int32_t offset = std::int32_t(intercept);
        const std::int32_t extend = format.isSigned ? signBit : 0; // (x ^ s) - s sign-extends; s = 0 leaves x
        std::int32_t low = kHigh, high = kLow;
        for (std::size_t i = 0; i < count; ++i)
        {
            const std::int32_t hu = ((std::int32_t(stored[i]) & std::int32_t(mask)) ^ extend) - extend + offset;
            low = std::min(low, hu);
            high = std::max(high, hu);
            out[i] = std::int16_t(std::clamp(hu, kLow, kHigh));
        }
        if (low >= kLow && high <= kHigh)
            return 0;
        for (std::size_t i = 0; i < count; ++i) // rare: count what was clamped
        {
            const std::int32_t hu = ((std::int32_t(stored[i]) & std::int32_t(mask)) ^ extend) - extend + offset;
            clamped += std::size_t(hu < kLow) + std::size_t(hu > kHigh);
        }
        return clamped;
    }
    for (std::size_t i = 0; i < count; ++i)
    {
        std::int32_t raw = std::int32_t((std::uint32_t(stored[i]) >> shift) & mask);
        if (format.isSigned)
            raw = (raw ^ signBit) - signBit;
        const double hu = std::round(double(raw) * slope + intercept);
        clamped += std::size_t(hu < kLow) + std::size_t(hu > kHigh);
        out[i] = std::int16_t(std::clamp(hu, double(kLow), double(kHigh)));
    }
    return clamped;
}

/// Converts one frame of stored pixel data (native, local byte order) starting at `pixels`.
std::size_t convertFrame(const void* pixels, std::size_t bytes, const DicomImageHeader& header, int frame,
                         std::int16_t* out)
{
    const PixelFormat& format = header.format;
    if (frame < 0 || frame >= int(header.frames.size()))
        throw Error("frame index out of range", {{"frame", std::to_string(frame)}});
    const std::size_t perFrame = format.pixelsPerFrame();
    if (perFrame * std::size_t(format.bitsAllocated / 8) > bytes)
        throw Error("pixel data is shorter than the image it describes (truncated file?)");
    const FrameGeometry& geometry = header.frames[std::size_t(frame)];
    if (format.bitsAllocated == 16)
        return storedToHu(static_cast<const std::uint16_t*>(pixels), perFrame, format, geometry, out);
    return storedToHu(static_cast<const std::uint8_t*>(pixels), perFrame, format, geometry, out);
}

/// Converts frames of stored pixel data laid out frame after frame.
std::size_t convertFrames(const void* pixels, std::size_t bytes, const DicomImageHeader& header,
                          const std::vector<int>& frames, const std::vector<std::int16_t*>& out)
{
    const std::size_t frameBytes = header.format.pixelsPerFrame() * std::size_t(header.format.bitsAllocated / 8);
    std::size_t clamped = 0;
    for (std::size_t n = 0; n < frames.size(); ++n)
    {
        const std::size_t offset = std::size_t(std::max(frames[n], 0)) * frameBytes;
        clamped += convertFrame(static_cast<const std::uint8_t*>(pixels) + std::min(offset, bytes),
                                bytes - std::min(offset, bytes), header, frames[n], out[n]);
    }
    return clamped;
}

bool isJpeg2000(const std::string& transferSyntaxUid)
{
    return transferSyntaxUid == UID_JPEG2000LosslessOnlyTransferSyntax || transferSyntaxUid == UID_JPEG2000TransferSyntax;
}

std::uint32_t bigEndian32(const std::uint8_t* p)
{
    return std::uint32_t(p[0]) << 24 | std::uint32_t(p[1]) << 16 | std::uint32_t(p[2]) << 8 | std::uint32_t(p[3]);
}

/// Refuses a JPEG 2000 code stream whose image size (SIZ marker) is not the DICOM image's: the decoder would
/// allocate what the code stream declares, however large.
void checkJpeg2000Size(const std::string& codestream, const PixelFormat& format)
{
    const auto* bytes = reinterpret_cast<const std::uint8_t*>(codestream.data());
    constexpr std::size_t kSizFields = 2 + 2 + 4 * 4; // Lsiz, Rsiz, Xsiz, Ysiz, XOsiz, YOsiz
    for (std::size_t i = 0; i + 4 + kSizFields <= std::min<std::size_t>(codestream.size(), 4096); ++i)
        if (bytes[i] == 0xFF && bytes[i + 1] == 0x4F && bytes[i + 2] == 0xFF && bytes[i + 3] == 0x51) // SOC, SIZ
        {
            const std::uint8_t* siz = bytes + i + 4 + 4;
            const std::uint32_t xsiz = bigEndian32(siz), ysiz = bigEndian32(siz + 4);
            const std::uint32_t xosiz = bigEndian32(siz + 8), yosiz = bigEndian32(siz + 12);
            if (xosiz > xsiz || yosiz > ysiz || xsiz - xosiz != std::uint32_t(format.columns) ||
                ysiz - yosiz != std::uint32_t(format.rows))
                throw Error("JPEG 2000 code stream size differs from the image's rows and columns");
            return;
        }
    throw Error("JPEG 2000 pixel data has no code stream header");
}

/// The fragments of encapsulated pixel data (item 0, the basic offset table, excluded).
std::vector<std::pair<const Uint8*, std::size_t>> pixelFragments(DcmDataset& dataset)
{
    DcmElement* element = nullptr;
    DcmPixelSequence* sequence = nullptr;
    if (dataset.findAndGetElement(DCM_PixelData, element).bad() || !element ||
        static_cast<DcmPixelData*>(element)->getEncapsulatedRepresentation(dataset.getOriginalXfer(), nullptr, sequence).bad() ||
        !sequence || sequence->card() < 2)
        throw Error("compressed pixel data has no fragments");
    std::vector<std::pair<const Uint8*, std::size_t>> fragments;
    for (unsigned long f = 1; f < sequence->card(); ++f)
    {
        DcmPixelItem* item = nullptr;
        Uint8* bytes = nullptr;
        if (sequence->getItem(item, f).bad() || !item || item->getUint8Array(bytes).bad() || !bytes)
            throw Error("compressed pixel data fragment unreadable");
        fragments.emplace_back(bytes, item->getLength());
    }
    return fragments;
}

/// The compressed bytes of each frame: one fragment per frame, or all fragments of a single-frame image.
std::vector<std::string> frameCodestreams(DcmDataset& dataset, const DicomImageHeader& header)
{
    const auto fragments = pixelFragments(dataset);
    const std::size_t frames = header.frames.size();
    if (frames != 1 && fragments.size() != frames)
        throw Error("multi-frame JPEG 2000 with several fragments per frame is not supported");
    std::vector<std::string> codestreams(frames);
    for (std::size_t f = 0; f < fragments.size(); ++f)
        codestreams[frames == 1 ? 0 : f].append(reinterpret_cast<const char*>(fragments[f].first), fragments[f].second);
    return codestreams;
}

bool isJpegFamily(const std::string& transferSyntaxUid)
{
    return transferSyntaxUid.rfind("1.2.840.10008.1.2.4.", 0) == 0 && !isJpeg2000(transferSyntaxUid);
}

/// Walks the marker segments of a JPEG / JPEG-LS header up to the start of scan (ITU T.81 B.1.1): fill bytes,
/// stand-alone markers, segment lengths of at least 2 within the data, a frame header before the scan. DCMTK
/// 3.6.7 loops forever on some malformed headers (found by fuzzing), so they are refused before it sees them.
void checkJpegHeader(const Uint8* data, std::size_t length)
{
    std::size_t at = 0;
    bool frameHeader = false;
    if (length < 4 || data[0] != 0xFF || data[1] != 0xD8)
        throw Error("damaged JPEG stream: no start of image");
    at = 2;
    while (true)
    {
        if (at >= length || data[at] != 0xFF)
            throw Error("damaged JPEG stream: marker expected");
        while (at < length && data[at] == 0xFF) // fill bytes
            ++at;
        if (at >= length)
            throw Error("damaged JPEG stream: ends in fill bytes");
        const Uint8 marker = data[at++];
        if (marker == 0x01 || (marker >= 0xD0 && marker <= 0xD7)) // TEM, RSTn: no length
            continue;
        if (marker == 0xD9 || marker == 0xD8 || marker == 0x00)
            throw Error("damaged JPEG stream: unexpected marker before the scan");
        if (at + 2 > length)
            throw Error("damaged JPEG stream: truncated marker segment");
        const std::size_t segment = std::size_t(data[at]) << 8 | data[at + 1];
        if (segment < 2 || at + segment > length)
            throw Error("damaged JPEG stream: bad marker segment length");
        if (marker == 0xDA) // start of scan: the header is complete
        {
            if (!frameHeader)
                throw Error("damaged JPEG stream: scan without a frame header");
            return;
        }
        frameHeader |= (marker >= 0xC0 && marker <= 0xCF && marker != 0xC4 && marker != 0xC8 && marker != 0xCC) ||
                       marker == 0xF7; // SOFn, SOF55 (JPEG-LS)
        at += segment;
    }
}

/// JPEG 2000 (DCMTK 3.6.7 has no decoder): the code streams are taken from DCMTK's parse and decoded by GDCM's
/// JPEG 2000 codec (OpenJPEG), one frame at a time.
std::size_t decodeJpeg2000(DcmDataset& dataset, const DicomImageHeader& header, const std::vector<int>& frames,
                           const std::vector<std::int16_t*>& out)
{
    const PixelFormat& format = header.format;
    const std::vector<std::string> codestreams = frameCodestreams(dataset, header);
    std::size_t clamped = 0;
    for (std::size_t n = 0; n < frames.size(); ++n)
    {
        if (frames[n] < 0 || std::size_t(frames[n]) >= codestreams.size())
            throw Error("frame index out of range", {{"frame", std::to_string(frames[n])}});
        const std::string& codestream = codestreams[std::size_t(frames[n])];
        checkJpeg2000Size(codestream, format);
        gdcm::JPEG2000Codec codec;
        codec.SetNumberOfDimensions(2);
        const unsigned int dimensions[3] = {unsigned(format.columns), unsigned(format.rows), 1};
        codec.SetDimensions(dimensions);
        codec.SetPixelFormat(gdcm::PixelFormat(1, std::uint8_t(format.bitsAllocated), std::uint8_t(format.bitsStored),
                                               std::uint8_t(format.highBit), format.isSigned ? 1 : 0));
        codec.SetPhotometricInterpretation(gdcm::PhotometricInterpretation::MONOCHROME2);
        gdcm::SmartPointer<gdcm::SequenceOfFragments> fragments = new gdcm::SequenceOfFragments;
        gdcm::Fragment fragment;
        fragment.SetByteValue(codestream.data(), gdcm::VL(std::uint32_t(codestream.size())));
        fragments->AddFragment(fragment);
        gdcm::DataElement compressed(gdcm::Tag(0x7fe0, 0x0010));
        compressed.SetValue(*fragments);
        gdcm::DataElement decoded;
        const gdcm::ByteValue* pixels = codec.Decode(compressed, decoded) ? decoded.GetByteValue() : nullptr;
        if (!pixels)
            throw Error("cannot decode the JPEG 2000 code stream");
        clamped += convertFrame(pixels->GetPointer(), pixels->GetLength(), header, frames[n], out[n]);
    }
    return clamped;
}

std::size_t decodeWithDcmtk(DcmFileFormat& fileFormat, const DicomImageHeader& header, const std::vector<int>& frames,
                            const std::vector<std::int16_t*>& out)
{
    DcmDataset& dataset = *fileFormat.getDataset();
    if (isJpeg2000(header.format.transferSyntaxUid))
        return decodeJpeg2000(dataset, header, frames, out);
    if (isJpegFamily(header.format.transferSyntaxUid))
    {
        const auto fragments = pixelFragments(dataset);
        for (std::size_t f = 0; f < fragments.size(); ++f)
            if (f == 0 || (fragments[f].second >= 2 && fragments[f].first[0] == 0xFF && fragments[f].first[1] == 0xD8))
                checkJpegHeader(fragments[f].first, fragments[f].second);
    }
    if (DcmXfer(dataset.getOriginalXfer()).isEncapsulated())
    {
        const OFCondition status = dataset.chooseRepresentation(EXS_LittleEndianExplicit, nullptr);
        if (status.bad() || !dataset.canWriteXfer(EXS_LittleEndianExplicit))
            throw Error("cannot decompress the pixel data",
                        {{"transfer_syntax", header.format.transferSyntaxUid}, {"reason", status.text()}});
    }
    DcmElement* element = nullptr;
    if (dataset.findAndGetElement(DCM_PixelData, element).bad() || !element)
        throw Error("pixel data missing");
    const Uint32 bytes = element->getLength();
    std::error_code error;
    if (!DcmXfer(dataset.getOriginalXfer()).isEncapsulated() && !header.file.empty() &&
        bytes > std::filesystem::file_size(header.file, error) && !error) // checked before DCMTK allocates it
        throw Error("pixel data longer than the file (damaged length or truncated file)");
    const void* pixels = nullptr;
    if (header.format.bitsAllocated == 16)
    {
        Uint16* words = nullptr;
        if (element->getUint16Array(words).good())
            pixels = words;
    }
    else
    {
        Uint8* values = nullptr;
        if (element->getUint8Array(values).good())
            pixels = values;
    }
    if (!pixels)
        throw Error("cannot read the pixel data");
    return convertFrames(pixels, bytes, header, frames, out);
}

/// Where native little-endian pixel data starts when it is the last element of the file: its 8 (implicit VR) or
/// 12 (explicit VR) byte element header must sit right before the value and name Pixel Data and its length.
std::uint64_t trailingPixelDataOffset(DcmDataset& dataset, const DicomImageHeader& header)
{
    const E_TransferSyntax xfer = dataset.getOriginalXfer();
    if (xfer != EXS_LittleEndianExplicit && xfer != EXS_LittleEndianImplicit)
        return 0;
    DcmElement* element = nullptr;
    if (dataset.findAndGetElement(DCM_PixelData, element).bad() || !element)
        return 0;
    const std::uint64_t length = element->getLength();
    const std::uint64_t needed = std::uint64_t(header.format.pixelsPerFrame()) * header.frames.size() *
                                 std::uint64_t(header.format.bitsAllocated / 8);
    std::error_code error;
    const std::uint64_t fileSize = std::filesystem::file_size(header.file, error);
    const std::uint64_t elementHeader = xfer == EXS_LittleEndianExplicit ? 12 : 8;
    if (error || length < needed || length == 0xFFFFFFFFu || fileSize < length + elementHeader)
        return 0;
    const std::uint64_t offset = fileSize - length;
    std::ifstream stream(header.file, std::ios::binary);
    std::uint8_t bytes[12] = {};
    if (!stream.seekg(std::streamoff(offset - elementHeader)) || !stream.read(reinterpret_cast<char*>(bytes), std::streamsize(elementHeader)))
        return 0;
    const std::uint8_t* lengthField = bytes + elementHeader - 4;
    const std::uint64_t declared = std::uint64_t(lengthField[0]) | std::uint64_t(lengthField[1]) << 8 |
                                   std::uint64_t(lengthField[2]) << 16 | std::uint64_t(lengthField[3]) << 24;
    const bool tag = bytes[0] == 0xE0 && bytes[1] == 0x7F && bytes[2] == 0x10 && bytes[3] == 0x00;
    const bool vr = elementHeader == 8 || ((bytes[4] == 'O' && (bytes[5] == 'W' || bytes[5] == 'B')) && bytes[6] == 0 && bytes[7] == 0);
    return tag && vr && declared == length ? offset : 0;
}

/// Reads the wanted frames of trailing native pixel data straight from the file (no second DICOM parse).
std::size_t decodeTrailingPixelData(const DicomImageHeader& header, const std::vector<int>& frames,
                                    const std::vector<std::int16_t*>& out)
{
    const std::size_t frameBytes = header.format.pixelsPerFrame() * std::size_t(header.format.bitsAllocated / 8);
    std::ifstream stream(header.file, std::ios::binary);
    if (!stream)
        throw Error("cannot open the file");
    thread_local std::vector<char> buffer;
    buffer.resize(frameBytes);
    std::size_t clamped = 0;
    for (std::size_t n = 0; n < frames.size(); ++n)
    {
        if (frames[n] < 0 || std::size_t(frames[n]) >= header.frames.size())
            throw Error("frame index out of range", {{"frame", std::to_string(frames[n])}});
        stream.seekg(std::streamoff(header.pixelDataOffset + std::uint64_t(frames[n]) * frameBytes));
        if (!stream.read(buffer.data(), std::streamsize(frameBytes)))
            throw Error("pixel data is shorter than the image it describes (truncated file?)");
        clamped += convertFrame(buffer.data(), buffer.size(), header, frames[n], out[n]);
    }
    return clamped;
}

void checkDecodable(const DicomImageHeader& header)
{
    if (!header.format.isGrayscale())
        throw Error("not a greyscale image", {{"photometric", header.format.photometric}});
}

} // namespace

DicomImageHeader readDicomHeader(const std::filesystem::path& file)
{
    ensureDcmtkCodecs();
    DcmFileFormat fileFormat;
    const OFCondition status =
        fileFormat.loadFile(file.string().c_str(), EXS_Unknown, EGL_noChange, kHeaderReadLength, ERM_autoDetect);
    if (status.bad())
    {
        if (hasDicomPreamble(file))
            throw Error("damaged or truncated DICOM file", {{"reason", status.text()}});
        throw NotDicomFile("not a DICOM file", {{"reason", status.text()}});
    }
    DicomImageHeader header = headerOf(fileFormat, file);
    header.pixelDataOffset = trailingPixelDataOffset(*fileFormat.getDataset(), header);
    return header;
}

std::size_t decodeFramesToHu(const DicomImageHeader& header, const std::vector<int>& frames,
                             const std::vector<std::int16_t*>& out)
{
    if (frames.size() != out.size())
        throw Error("decodeFramesToHu: one output per frame expected");
    checkDecodable(header);
    if (header.pixelDataOffset != 0)
        return decodeTrailingPixelData(header, frames, out);
    ensureDcmtkCodecs();
    DcmFileFormat fileFormat;
    const OFCondition status = fileFormat.loadFile(header.file.string().c_str());
    if (status.bad())
        throw Error("damaged or truncated DICOM file", {{"reason", status.text()}});
    return decodeWithDcmtk(fileFormat, header, frames, out);
}

} // namespace vsim::dicom
