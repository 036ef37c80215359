// `export-label --study S [--label ID] --out FILE [--overwrite]`: a label as a DICOM SEG for PACS, 3D Slicer or a
// vendor workstation, in the CT's study and frame of reference (app/DicomResults.h).

#include "CliCommands.h"
#include "CliSupport.h"
#include "CommandLine.h"
#include "vsim/core/OutputSafety.h"
#include "vsim/app/DicomResults.h"
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
    app::writeLabelSegmentation(study, labelId, out);
    progress.report(1.0, "written");
    std::cout << "wrote " << labelId << " (" << label.name << ") as a DICOM SEG: " << out.string() << "\n";
    return 0;
}

} // namespace vsim::cli
