#include "vsim/app/DicomStudyImport.h"

#include "vsim/core/Hounsfield.h"
#include "vsim/core/Parameters.h"
#include "vsim/core/StoredText.h"
#include "vsim/dicom/SeriesGeometry.h"
#include "vsim/study/Study.h"

#include <nlohmann/json.hpp>

namespace vsim::app {
namespace {

using nlohmann::json;

std::string attribute(const std::map<std::string, std::string>& attributes, const std::string& key)
{
    const auto found = attributes.find(key);
    return found == attributes.end() ? std::string() : found->second;
}

/// Study-level attributes copied into the study's metadata.
constexpr const char* kStudyKeys[] = {"patient_name",       "patient_id",  "patient_birth_date", "patient_sex",
                                      "study_instance_uid", "study_date",  "study_description",  "accession_number"};

void adoptStudyMetadata(study::Study& study, const std::map<std::string, std::string>& attributes)
{
    const std::string studyPatient = attribute(study.metadata(), "patient_id");
    const std::string seriesPatient = attribute(attributes, "patient_id");
    if (!studyPatient.empty() && !seriesPatient.empty() && studyPatient != seriesPatient)
        throw Error("the series belongs to another patient than the study (Patient ID differs); import it into a "
                    "study of its own");
    for (const char* key : kStudyKeys)
        if (attribute(study.metadata(), key).empty() && !attribute(attributes, key).empty())
            study.setMetadata(key, attribute(attributes, key));
}

/// The study's image imported from the series `seriesUid`; null when none is (or the UID is empty).
const study::Artifact* imageOfSeries(const study::Study& study, const std::string& seriesUid)
{
    if (seriesUid.empty())
        return nullptr;
    for (const study::Artifact& artifact : study.artifacts())
        if (artifact.kind == study::ArtifactKind::Image && attribute(artifact.attributes, "series_instance_uid") == seriesUid)
            return &artifact;
    return nullptr;
}

json vec(const Eigen::Vector3d& v)
{
    return json::array({v.x(), v.y(), v.z()});
}

json seriesJson(const dicom::DicomSeries& series)
{
    const auto& attributes = series.attributes();
    const dicom::FrameGeometry& first = series.firstGeometry();
    json entry = {{"key", series.key},
                  {"series_instance_uid", series.seriesInstanceUid},
                  {"study_instance_uid", series.studyInstanceUid},
                  {"patient_name", attribute(attributes, "patient_name")},
                  {"patient_id", attribute(attributes, "patient_id")},
                  {"study_description", attribute(attributes, "study_description")},
                  {"study_date", attribute(attributes, "study_date")},
                  {"series_number", series.seriesNumber},
                  {"series_description", series.description},
                  {"modality", series.modality},
                  {"image_type", series.imageType},
                  {"files", series.headers.size()},
                  {"slices", series.slices.size()},
                  {"columns", series.format().columns},
                  {"rows", series.format().rows},
                  {"pixel_spacing_mm", {first.columnSpacing, first.rowSpacing}},
                  {"transfer_syntax_uid", series.format().transferSyntaxUid},
                  {"warnings", series.warnings}};
    try
    {
        const dicom::SeriesGeometry plan = dicom::planSeriesGeometry(series);
        entry["volume"] = {{"dims", plan.grid.dims},
                           {"spacing_mm", vec(plan.grid.spacing)},
                           {"origin_mm", vec(plan.grid.origin)},
                           {"resampled", plan.resample},
                           {"tilt_deg", plan.tiltDegrees},
                           {"missing_slices", plan.missingSlices},
                           {"duplicate_slices", plan.duplicateSlices}};
        for (const std::string& warning : plan.warnings)
            entry["warnings"].push_back(warning);
    }
    catch (const Error& error)
    {
        entry["error"] = error.message();
    }
    return entry;
}

} // namespace

std::string addDicomVolumeToStudy(study::Study& study, dicom::DicomVolume volume, const std::filesystem::path& source,
                                  const std::optional<HounsfieldRescale>& rescale)
{
    // A series fetched or imported twice is recognised: the study keeps one copy (PS3.3 C.7.3.1: the Series
    // Instance UID names the series wherever it comes from).
    if (const study::Artifact* artifact = imageOfSeries(study, attribute(volume.attributes, "series_instance_uid")))
        throw Error(Pattern{"this series is already in the study, as %1 (%2): it is not imported twice",
                            {artifact->id, artifact->name}});
    acceptAsHounsfield(volume.image, rescale, volume.warnings); // before the study changes: a refusal adds nothing
    adoptStudyMetadata(study, volume.attributes);
    study::Provenance provenance;
    provenance.command = "import dicom";
    provenance.parameters = {{"series", attribute(volume.attributes, "series_key")}};
    if (rescale)
        provenance.parameters["rescale"] = numberText(rescale->slope) + "," + numberText(rescale->intercept);
    provenance.inputs = {source.string()};
    std::string name = attribute(volume.attributes, "series_description");
    if (name.empty())
        name = storedText(Pattern{"DICOM series %1", {attribute(volume.attributes, "series_number")}});
    const std::string id = study.addImage(volume.image, name, provenance, volume.warnings);
    study.setArtifactAttributes(id, volume.attributes);
    return id;
}

std::string importDicomSeriesIntoStudy(study::Study& study, const dicom::DicomSeries& series,
                                       const std::filesystem::path& source, const dicom::DicomImportOptions& options,
                                       const Progress& progress, const std::optional<HounsfieldRescale>& rescale)
{
    return addDicomVolumeToStudy(study, dicom::importDicomSeries(series, options, progress), source, rescale);
}

const dicom::DicomSeries& chooseSeries(const dicom::DicomScanResult& scan, const std::string& keyOrUid)
{
    if (!keyOrUid.empty())
    {
        if (const dicom::DicomSeries* series = scan.find(keyOrUid))
            return *series;
        throw Error(Pattern{"no series '%1' among the %2 series found (see --list)",
                            {keyOrUid, std::to_string(scan.series.size())}});
    }
    if (const dicom::DicomSeries* series = scan.defaultSeries())
        return *series;
    std::string reason = "no importable DICOM image series among " + std::to_string(scan.filesSeen) + " files";
    for (const std::string& warning : scan.warnings)
        reason += "; " + warning;
    throw Error(reason);
}

std::string dicomScanJson(const dicom::DicomScanResult& scan)
{
    json series = json::array();
    for (const dicom::DicomSeries& entry : scan.series)
        series.push_back(seriesJson(entry));
    const dicom::DicomSeries* preferred = scan.defaultSeries();
    const json document = {{"files", scan.filesSeen},
                           {"image_files", scan.imageFiles},
                           {"non_dicom_files", scan.nonDicomFiles},
                           {"non_image_files", scan.nonImageFiles},
                           {"damaged_files", scan.damagedFiles},
                           {"warnings", scan.warnings},
                           {"default_series", preferred ? preferred->key : std::string()},
                           {"series", series}};
    return document.dump(2);
}

} // namespace vsim::app
