// `segment-organ --study S --seed x,y,z [--seed ...] [--organ liver|tumour|NAME] [--within LIVER] [--image ID]
// [--param ...]`: a label of the organ grown from the points (imaging/OrganGrowing.h), or with --within of a lesion
// in that liver label (imaging/LesionGrowing.h), for the liver and tumour labels that drug runs read (`simulate
// network --liver-label --tumour-label`). Editable afterwards like any label.

#include "CliCommands.h"
#include "CliSupport.h"
#include "CommandLine.h"
#include "vsim/imaging/LesionGrowing.h"
#include "vsim/imaging/OrganGrowing.h"
#include "vsim/core/StoredText.h"

#include <iostream>

namespace vsim::cli {

int segmentOrgan(const Arguments& arguments, const Progress& progress)
{
    study::Study study = openStudyForWriting(arguments);
    const std::string imageId = chooseArtifact(study, arguments.option("image"), study::ArtifactKind::Image,
                                               "the study has no CT image: import one first");
    std::vector<ParameterSpec> specs = imaging::organGrowingParameters();
    for (const ParameterSpec& spec : imaging::lesionGrowingParameters())
        specs.push_back(spec);
    ParameterSet parameters(specs);
    applyParameters(arguments, parameters);
    std::vector<Eigen::Vector3d> points;
    std::string pointsText;
    for (const auto& [name, value] : arguments.options)
        if (name == "seed")
        {
            const std::vector<double> p = parseNumbers(value, ',', 3, "seed");
            points.emplace_back(p[0], p[1], p[2]);
            pointsText += (pointsText.empty() ? "" : "; ") + value;
        }
    if (points.empty())
        throw UsageError("segment-organ: give the points inside the organ with --seed x,y,z (mm, repeatable)");
    const std::string organ = arguments.hasOption("organ") ? arguments.option("organ") : "liver";
    // A lesion within a liver label: its boundary against the parenchyma (LesionGrowing.h); else the organ window.
    const bool lesion = arguments.hasOption("within");
    if (lesion && organ == "liver")
        throw UsageError("segment-organ: --within is the liver a lesion grows in; give --organ tumour (or its name)");
    imaging::OrganGrowing grown;
    std::string figures;
    if (lesion)
    {
        const LabelVolume liver = study.loadLabel(chooseArtifact(study, arguments.option("within"), study::ArtifactKind::Label, ""));
        imaging::LesionGrowing found = imaging::growLesion(study.loadImage(imageId), points, liver, parameters, progress.subRange(0.0, 0.9));
        grown.label = std::move(found.label);
        grown.warnings = found.warnings;
        grown.figures["volume_ml"] = found.figures.at("volume_ml");
        figures = ", boundary " + numberText(found.figures.at("threshold_hu")) + " HU (liver " +
                  numberText(found.figures.at("parenchyma_hu")) + " +/- " + numberText(found.figures.at("parenchyma_sd_hu")) +
                  " HU, lesion " + numberText(found.figures.at("lesion_hu")) + " HU near the points)";
    }
    else
    {
        grown = imaging::growOrgan(study.loadImage(imageId), points, parameters, progress.subRange(0.0, 0.9));
        figures = ", window " + numberText(grown.figures.at("window_low_hu")) + " to " +
                  numberText(grown.figures.at("window_high_hu")) + " HU (median " +
                  numberText(grown.figures.at("seed_median_hu")) + " HU near the points)";
        if (organ == "tumour")
            grown.warnings.push_back(storedText("a tumour grown in its own window holds its darkest part only: give the "
                                                "liver label with --within for the lesion's boundary against the "
                                                "parenchyma"));
    }
    study::Provenance provenance;
    provenance.command = "segment-organ";
    provenance.inputs = {imageId};
    if (lesion)
        provenance.inputs.push_back(arguments.option("within"));
    provenance.parameters = parameters.valuesAsText();
    provenance.parameters["organ"] = organ;
    provenance.parameters["points_mm"] = pointsText;
    const std::string organName = organ == "tumour" ? storedText("tumour") : storedText("liver"); // translated when shown
    const std::string name = points.size() == 1
                                 ? storedText(Pattern{"%1 (grown from one point)", {organName}})
                                 : storedText(Pattern{"%1 (grown from %2 points)", {organName, std::to_string(points.size())}});
    const std::string id = study.addLabel(grown.label, name, provenance, grown.warnings);
    study.save();
    progress.report(1.0, "saved");
    std::cout << organ << " grown from " << points.size() << " point(s) of " << imageId << " as " << id << ": "
              << numberText(grown.figures.at("volume_ml")) << " ml" << figures << "\n";
    for (const std::string& warning : grown.warnings)
        std::cout << "warning: " << warning << "\n";
    return 0;
}

} // namespace vsim::cli
