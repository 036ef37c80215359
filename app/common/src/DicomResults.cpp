#include "vsim/app/DicomResults.h"

#include "vsim/app/StudyReport.h"
#include "vsim/dicom/DicomSegmentation.h"
#include "vsim/report/EncapsulatedPdf.h"

#include <QByteArray>

namespace vsim::app {
namespace {

std::string valueOf(const std::map<std::string, std::string>& map, const char* key)
{
    const auto found = map.find(key);
    return found == map.end() ? std::string() : found->second;
}

std::vector<std::string> splitBackslash(const std::string& values)
{
    std::vector<std::string> parts;
    for (std::size_t start = 0; !values.empty();)
    {
        const std::size_t end = values.find('\\', start);
        parts.push_back(values.substr(start, end - start));
        if (end == std::string::npos)
            break;
        start = end + 1;
    }
    return parts;
}

} // namespace

void writeLabelSegmentation(const study::Study& study, const std::string& labelId, const std::filesystem::path& out)
{
    const study::Artifact& label = study.artifact(labelId);
    dicom::SegmentationDescription description;
    description.seriesDescription = "VascuSim " + label.name;
    // The CT the label was made on: its study and frame of reference (from its DICOM attributes).
    const std::string imageId = study.newestArtifact(study::ArtifactKind::Image);
    if (!imageId.empty())
    {
        const auto& attributes = study.artifact(imageId).attributes;
        description.frameOfReferenceUid = valueOf(attributes, "frame_of_reference_uid");
        // The CT images slice by slice (recorded at import where the grid is the files' own): each frame then
        // names the image it was derived from.
        description.sourceSeriesUid = valueOf(attributes, "series_instance_uid");
        description.sourceSopClassUid = valueOf(attributes, "source_sop_class_uid");
        description.sourceSopInstanceUids = splitBackslash(valueOf(attributes, "source_sop_instance_uids"));
    }
    description.studyInstanceUid = valueOf(study.metadata(), "study_instance_uid");
    if (!valueOf(study.metadata(), "patient_name").empty())
        description.patientName = valueOf(study.metadata(), "patient_name");
    if (!valueOf(study.metadata(), "patient_id").empty())
        description.patientId = valueOf(study.metadata(), "patient_id");
    // The values VascuSim's labels use: 1 lumen; an AAA sac label also 4 thrombus and 5 wall.
    const std::vector<std::string> names{"vessel lumen", "", "", "thrombus", "aortic wall"};
    dicom::writeDicomSegmentation(study.loadLabel(labelId), names, description, out);
}

bool writeReportEncapsulatedPdf(const study::Study& study, const std::string& reportId, const std::filesystem::path& out)
{
    const bool anonymized = valueOf(study.artifact(reportId).provenance.parameters, "anonymized") == "1";
    const std::string pdf = study.loadReport(reportId);
    report::writeEncapsulatedPdf(QByteArray(pdf.data(), qsizetype(pdf.size())), documentIdentity(study, anonymized), out);
    return anonymized;
}

} // namespace vsim::app
