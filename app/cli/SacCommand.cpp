// `sac --study S [--label ID] [--wall-thickness mm]`: the AAA sac from a lumen label (AneurysmSac.h): the outer
// contour, thrombus and assumed-thickness wall as a label artifact (1 lumen, 4 thrombus, 5 wall), and the figures
// by their clinical definitions.

#include "CliCommands.h"
#include "CliSupport.h"
#include "CommandLine.h"
#include "vsim/app/SacRecord.h"
#include "vsim/imaging/AneurysmSac.h"

#include <iostream>

namespace vsim::cli {

int sacStudy(const Arguments& arguments, const Progress& progress)
{
    study::Study study = openStudyForWriting(arguments);
    const std::string labelId = arguments.hasOption("label") ? arguments.option("label") : app::newestLumenLabel(study);
    if (labelId.empty())
        throw Error("the study has no lumen label: run vascusim-cli segment --target aorta");
    const std::string imageId = chooseArtifact(study, arguments.option("image"), study::ArtifactKind::Image,
                                               "the study has no CT image");
    const double wall = quantityOption(arguments, "wall-thickness", "mm", 1.8);
    const CtVolume ct = study.loadImage(imageId);
    const LabelVolume lumen = study.loadLabel(labelId);
    const imaging::AneurysmSac sac = imaging::measureAneurysmSac(ct, lumen, wall, progress.subRange(0.0, 0.9));
    const std::string id = app::recordAneurysmSac(study, sac, imageId, labelId, wall);
    study.save();
    progress.report(1.0, "saved");
    std::cout << "AAA sac of " << labelId << " as " << id << ":\n";
    for (const auto& [key, value] : sac.figures)
    {
        const auto definition = sac.definitions.find(key);
        std::cout << "  " << key << " " << numberText(value)
                  << (definition != sac.definitions.end() ? "  (" + definition->second + ")" : std::string()) << "\n";
    }
    for (const std::string& warning : sac.warnings)
        std::cout << "warning: " << warning << "\n";
    return 0;
}

} // namespace vsim::cli
