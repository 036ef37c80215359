// Writing a label volume as a BINARY DICOM SEG with DCMTK's dcmseg (DicomSegmentation.h): segment N for label
// value N, one frame per slice and segment holding any voxel, the plane position per frame, orientation and
// pixel measures shared; where the CT's instances are known, each frame's source image and the referenced series.

#include "vsim/dicom/DicomSegmentation.h"

#include "DcmtkSetup.h"
#include "DecimalString.h"

#include "vsim/core/DicomUid.h"
#include "vsim/core/Error.h"

#include <dcmtk/config/osconfig.h>
#include <dcmtk/dcmdata/dcuid.h>
#include <dcmtk/dcmfg/fgderimg.h>
#include <dcmtk/dcmfg/fgfracon.h>
#include <dcmtk/dcmfg/fgpixmsr.h>
#include <dcmtk/dcmfg/fgplanor.h>
#include <dcmtk/dcmfg/fgplanpo.h>
#include <dcmtk/dcmfg/fgseg.h>
#include <dcmtk/dcmiod/iodmacro.h>
#include <dcmtk/dcmiod/iodreferences.h>
#include <dcmtk/dcmseg/segdoc.h>
#include <dcmtk/dcmseg/segment.h>

#include <memory>
#include <set>

namespace vsim::dicom {
namespace {

using detail::decimalString;

void check(const OFCondition& condition, const std::string& what)
{
    if (condition.bad())
        throw Error(Pattern{"writing the DICOM SEG failed at %1: %2", {what, condition.text()}});
}

/// The Derivation Image functional group of a frame on slice k: derived (segmentation, DCM 113076) from the CT
/// image of that slice (purpose: source image for image processing operation, DCM 121322).
std::unique_ptr<FGDerivationImage> sourceOf(const SegmentationDescription& description, int k)
{
    ImageSOPInstanceReferenceMacro source;
    check(source.setReferencedSOPClassUID(description.sourceSopClassUid.c_str()), "source image class");
    check(source.setReferencedSOPInstanceUID(description.sourceSopInstanceUids[std::size_t(k)].c_str()), "source image");
    OFVector<ImageSOPInstanceReferenceMacro> sources;
    sources.push_back(source);
    std::unique_ptr<FGDerivationImage> derivation(FGDerivationImage::createMinimal(
        sources, "Segmentation", CodeSequenceMacro("113076", "DCM", "Segmentation"),
        CodeSequenceMacro("121322", "DCM", "Source image for image processing operation")));
    if (!derivation)
        throw Error(Pattern{"writing the DICOM SEG failed at the derivation image of slice %1",
                            {std::to_string(k + 1)}});
    return derivation;
}

} // namespace

void writeDicomSegmentation(const LabelVolume& label, const std::vector<std::string>& segmentNames,
                            const SegmentationDescription& description, const std::filesystem::path& file)
{
    ensureDcmtkCodecs();
    const VolumeGeometry& g = label.geometry();
    if (g.dims[0] > 65535 || g.dims[1] > 65535 || label.isEmpty())
        throw Error("the label cannot be written as a DICOM SEG (empty, or over 65535 pixels a row)");
    std::set<int> values;
    for (std::size_t v = 0; v < g.voxelCount(); ++v)
        if (label.data()[v])
            values.insert(label.data()[v]);
    if (values.empty())
        throw Error("the label has no labelled voxel to write as a DICOM SEG");

    IODGeneralEquipmentModule::EquipmentInfo equipment("VascuSim", "VascuSim", "1", "VascuSim");
    ContentIdentificationMacro content("1", "VSIM_LABELS", description.seriesDescription.c_str(), "VascuSim");
    DcmSegmentation* created = nullptr;
    check(DcmSegmentation::createBinarySegmentation(created, Uint16(g.dims[1]), Uint16(g.dims[0]), equipment, content),
          "creation");
    std::unique_ptr<DcmSegmentation> seg(created);
    check(seg->getPatient().setPatientName(description.patientName.c_str()), "patient name");
    check(seg->getPatient().setPatientID(description.patientId.c_str()), "patient ID");
    // Every UID under the configured root (vsim/core/DicomUid.h), not DCMTK's own.
    check(seg->getStudy().setStudyInstanceUID(
              (description.studyInstanceUid.empty() ? newDicomUid() : description.studyInstanceUid).c_str()),
          "study UID");
    check(seg->getFrameOfReference().setFrameOfReferenceUID(
              (description.frameOfReferenceUid.empty() ? newDicomUid() : description.frameOfReferenceUid).c_str()),
          "frame of reference");
    check(seg->getSeries().setSeriesInstanceUID(newDicomUid().c_str()), "series UID");
    check(seg->getSOPCommon().setSOPInstanceUID(newDicomUid().c_str()), "instance UID");
    check(seg->getSeries().setSeriesDescription(description.seriesDescription.c_str()), "series description");
    check(seg->getSeries().setSeriesNumber("900"), "series number");

    FGPixelMeasures measures;
    check(measures.setPixelSpacing((decimalString(g.spacing.y()) + "\\" + decimalString(g.spacing.x())).c_str()), "pixel spacing");
    check(measures.setSliceThickness(decimalString(g.spacing.z()).c_str()), "slice thickness");
    check(measures.setSpacingBetweenSlices(decimalString(g.spacing.z()).c_str()), "slice spacing");
    check(seg->addForAllFrames(measures), "pixel measures");
    FGPlaneOrientationPatient orientation;
    const Eigen::Matrix3d& d = g.direction;
    check(orientation.setImageOrientationPatient(decimalString(d(0, 0)).c_str(), decimalString(d(1, 0)).c_str(),
                                                 decimalString(d(2, 0)).c_str(), decimalString(d(0, 1)).c_str(),
                                                 decimalString(d(1, 1)).c_str(), decimalString(d(2, 1)).c_str()),
          "orientation");
    check(seg->addForAllFrames(orientation), "orientation");

    const std::size_t slicePixels = std::size_t(g.dims[0]) * std::size_t(g.dims[1]);
    const bool referenced = !description.sourceSeriesUid.empty() && !description.sourceSopClassUid.empty() &&
                            description.sourceSopInstanceUids.size() == std::size_t(g.dims[2]);
    std::set<int> sourceSlices;
    std::vector<Uint8> frame(slicePixels);
    // Segment N holds label value N, so that the values come back as they were (a sac's thrombus 4 and wall 5):
    // values between that the label does not use get a segment without frames.
    for (int value = 1; value <= *values.rbegin(); ++value)
    {
        const bool used = values.count(value) > 0;
        const std::string name = !used ? "unused label value " + std::to_string(value)
                                 : std::size_t(value) <= segmentNames.size() && !segmentNames[std::size_t(value - 1)].empty()
                                     ? segmentNames[std::size_t(value - 1)]
                                     : "segment " + std::to_string(value);
        DcmSegment* segment = nullptr;
        // SNOMED CT: category "Tissue" (85756007), type "Artery" (51114001).
        check(DcmSegment::create(segment, name.c_str(), CodeSequenceMacro("85756007", "SCT", "Tissue"),
                                 CodeSequenceMacro("51114001", "SCT", "Artery"), DcmSegTypes::SAT_SEMIAUTOMATIC,
                                 "VascuSim"),
              "segment " + name);
        Uint16 number = 0;
        check(seg->addSegment(segment, number), "segment " + name);
        if (number != value)
            throw Error(Pattern{"writing the DICOM SEG failed: segment %1 for label value %2",
                                {std::to_string(number), std::to_string(value)}});
        if (!used)
            continue;
        for (int k = 0; k < g.dims[2]; ++k)
        {
            bool any = false;
            for (std::size_t n = 0; n < slicePixels; ++n)
            {
                frame[n] = label.data()[std::size_t(k) * slicePixels + n] == value ? 1 : 0;
                any = any || frame[n];
            }
            if (!any)
                continue;
            FGPlanePosPatient position;
            const Eigen::Vector3d p = g.indexToPatient(Eigen::Vector3d(0.0, 0.0, k));
            check(position.setImagePositionPatient(decimalString(p.x()).c_str(), decimalString(p.y()).c_str(), decimalString(p.z()).c_str()),
                  "frame position");
            FGFrameContent frameContent;
            check(frameContent.setDimensionIndexValues(number, 0), "frame content");
            check(frameContent.setDimensionIndexValues(Uint32(k + 1), 1), "frame content");
            FGSegmentation identification;
            check(identification.setReferencedSegmentNumber(number), "frame segment");
            OFVector<FGBase*> perFrame;
            perFrame.push_back(&position);
            perFrame.push_back(&frameContent);
            perFrame.push_back(&identification);
            std::unique_ptr<FGDerivationImage> derivation;
            if (referenced)
            {
                derivation = sourceOf(description, k);
                perFrame.push_back(derivation.get());
                sourceSlices.insert(k);
            }
            check(seg->addFrame(frame.data(), number, perFrame), "frame");
        }
    }
    IODMultiframeDimensionModule& dimensions = seg->getDimensions();
    const std::string organisationUid = newDicomUid();
    const char* organisation = organisationUid.c_str();
    check(dimensions.addDimensionIndex(DCM_ReferencedSegmentNumber, organisation, DCM_SegmentIdentificationSequence,
                                       "Segment"),
          "dimensions");
    check(dimensions.addDimensionIndex(DCM_ImagePositionPatient, organisation, DCM_PlanePositionSequence, "Position"),
          "dimensions");
    if (referenced)
    {
        // The Common Instance Reference module: the CT series and the instances the frames were derived from.
        IODReferences references;
        OFString studyUid;
        check(seg->getStudy().getStudyInstanceUID(studyUid), "study UID");
        for (int k : sourceSlices)
            references.add(new IODImageReference(description.patientId.c_str(), studyUid,
                                                 description.sourceSeriesUid.c_str(),
                                                 description.sourceSopInstanceUids[std::size_t(k)].c_str(),
                                                 description.sourceSopClassUid.c_str()));
        if (seg->getCommonInstanceReference().addReferences(references) != sourceSlices.size())
            throw Error("writing the DICOM SEG failed at the referenced series");
    }
    auto* item = new IODMultiframeDimensionModule::DimensionOrganizationItem;
    item->setDimensionOrganizationUID(organisation);
    dimensions.getDimensionOrganizationSequence().push_back(item);
    check(seg->saveFile(file.string().c_str(), EXS_LittleEndianExplicit), "saving " + file.filename().string());
}

} // namespace vsim::dicom
