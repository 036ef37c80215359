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
        description.frameOfReferenceUid = value(study.artifact(imageId).attributes, "frame_of_reference_uid");
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
