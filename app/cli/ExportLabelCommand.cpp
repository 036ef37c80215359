// `export-label --study S [--label ID] --out FILE [--overwrite]`: a label as a DICOM SEG for PACS, 3D Slicer or a
// vendor workstation, in the CT's study and frame of reference (dicom/DicomSegmentation.h).

#include "CliCommands.h"
#include "CliSupport.h"
#include "CommandLine.h"
#include "vsim/core/OutputSafety.h"
#include "vsim/dicom/DicomSegmentation.h"
#include "vsim/study/Study.h"

#include <iostream>

namespace vsim::cli {

int exportLabelFromStudy(const Arguments& arguments, const Progress& progress)
{
    const study::Study study = openStudyForReading(arguments.option("study"));
    const std::string labelId = chooseArtifact(study, arguments.option("label"), study::ArtifactKind::Label,
                                               "the study has no label: run vascusim-cli segment first");
    const std::filesystem::path out = arguments.option("out");
    checkOutputFile(out, arguments.hasOption("overwrite"));
    const study::Artifact& label = study.artifact(labelId);
    // The CT the label was made on: its study and frame of reference (from its DICOM attributes).
    dicom::SegmentationDescription description;
    description.seriesDescription = "VascuSim " + label.name;
    const auto value = [](const std::map<std::string, std::string>& map, const char* key) {
        const auto found = map.find(key);
        return found == map.end() ? std::string() : found->second;
    };
    const std::string imageId = study.newestArtifact(study::ArtifactKind::Image);
    if (!imageId.empty())
    {
        const auto& attributes = study.artifact(imageId).attributes;
        description.frameOfReferenceUid = value(attributes, "frame_of_reference_uid");
        // The CT images slice by slice (recorded at import where the grid is the files' own): each frame then
        // names the image it was derived from.
        description.sourceSeriesUid = value(attributes, "series_instance_uid");
        description.sourceSopClassUid = value(attributes, "source_sop_class_uid");
        std::string uids = value(attributes, "source_sop_instance_uids");
        for (std::size_t start = 0; !uids.empty();)
        {
            const std::size_t end = uids.find('\\', start);
            description.sourceSopInstanceUids.push_back(uids.substr(start, end - start));
            if (end == std::string::npos)
                break;
            start = end + 1;
        }
    }
    description.studyInstanceUid = value(study.metadata(), "study_instance_uid");
    if (!value(study.metadata(), "patient_name").empty())
        description.patientName = value(study.metadata(), "patient_name");
    if (!value(study.metadata(), "patient_id").empty())
        description.patientId = value(study.metadata(), "patient_id");
    // The values VascuSim's labels use: 1 lumen; an AAA sac label also 4 thrombus and 5 wall.
    const std::vector<std::string> names{"vessel lumen", "", "", "thrombus", "aortic wall"};
    dicom::writeDicomSegmentation(study.loadLabel(labelId), names, description, out);
    progress.report(1.0, "written");
    std::cout << "wrote " << labelId << " (" << label.name << ") as a DICOM SEG: " << out.string() << "\n";
    return 0;
}

} // namespace vsim::cli
