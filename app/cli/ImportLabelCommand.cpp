// `import <mask> --study S --as-label`: a reference mask or another program's segmentation (NIfTI, NRRD,
// MetaImage, a DICOM SEG, or a DICOM mask series) as a label artifact on the study's image grid (study::maskOnImageGrid).

#include "CliCommands.h"
#include "CliSupport.h"
#include "CommandLine.h"
#include "vsim/app/MaskSource.h"
#include "vsim/study/LabelImport.h"
#include "vsim/core/StoredText.h"

#include <cmath>
#include <iostream>

namespace vsim::cli {
namespace fs = std::filesystem;

int importLabelIntoStudy(const Arguments& arguments, const Progress& progress)
{
    const fs::path input = arguments.positional.at(0);
    study::Study study = openStudyForWriting(arguments);
    const std::string imageId = chooseArtifact(study, arguments.option("image"), study::ArtifactKind::Image,
                                               "the study has no CT image for the label's grid: import the CT first");
    std::optional<std::uint8_t> value; // the mask's own labels unless one value is asked for
    if (arguments.hasOption("label-value"))
    {
        const double given = quantityOption(arguments, "label-value", "", 1.0);
        if (given < 1.0 || given > 255.0 || given != std::floor(given))
            throw Error("--label-value expects a whole number from 1 to 255");
        value = std::uint8_t(given);
    }
    app::MaskSource source = app::readMaskSource(input, arguments.option("series"), progress.subRange(0.0, 0.8));
    std::vector<std::string> warnings = source.warnings;
    const CtVolume& mask = source.mask;
    const LabelVolume label =
        study::maskOnImageGrid(mask, study.volumeGeometry(imageId), value, warnings);
    study::Provenance provenance;
    provenance.command = "import label";
    provenance.inputs = {input.filename().string(), imageId};
    provenance.parameters = {{"label_value", value ? std::to_string(int(*value)) : std::string("as in the mask")},
                             {"source", source.kind}};
    for (std::size_t n = 0; n < source.segmentLabels.size(); ++n) // a SEG's segment names by label value
        if (!source.segmentLabels[n].empty())
            provenance.parameters["segment_" + std::to_string(n + 1)] = source.segmentLabels[n];
    const std::string name = input.filename().string();
    const std::string id = study.addLabel(label, name.empty() ? storedText("Imported label") : name, provenance, warnings);
    study.save();
    progress.report(1.0, "saved");
    std::size_t voxels = 0;
    for (std::size_t v = 0; v < label.size(); ++v)
        voxels += label.data()[v] != 0;
    std::cout << "imported " << name << " as " << id << " on the grid of " << imageId << ": " << voxels
              << " labelled voxels\n";
    for (const std::string& warning : warnings)
        std::cout << "warning: " << warning << "\n";
    return 0;
}

} // namespace vsim::cli
