// `segment-organ --study S --seed x,y,z [--seed ...] [--organ liver|tumour|NAME] [--image ID] [--param ...]`: a
// label of the organ grown from the points (imaging/OrganGrowing.h), for the liver and tumour labels that drug
// runs read (`simulate network --liver-label --tumour-label`). Editable afterwards like any label.

#include "CliCommands.h"
#include "CliSupport.h"
#include "CommandLine.h"
#include "vsim/imaging/OrganGrowing.h"

#include <iostream>

namespace vsim::cli {

int segmentOrgan(const Arguments& arguments, const Progress& progress)
{
    study::Study study = openStudyForWriting(arguments);
    const std::string imageId = chooseArtifact(study, arguments.option("image"), study::ArtifactKind::Image,
                                               "the study has no CT image: import one first");
    ParameterSet parameters(imaging::organGrowingParameters());
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
    const imaging::OrganGrowing grown = imaging::growOrgan(study.loadImage(imageId), points, parameters, progress.subRange(0.0, 0.9));
    study::Provenance provenance;
    provenance.command = "segment-organ";
    provenance.inputs = {imageId};
    provenance.parameters = parameters.valuesAsText();
    provenance.parameters["organ"] = organ;
    provenance.parameters["points_mm"] = pointsText;
    const std::string name = organ + " (grown from " + std::to_string(points.size()) + " point" + (points.size() > 1 ? "s" : "") + ")";
    const std::string id = study.addLabel(grown.label, name, provenance, grown.warnings);
    study.save();
    progress.report(1.0, "saved");
    std::cout << organ << " grown from " << points.size() << " point(s) of " << imageId << " as " << id << ": "
              << grown.figures.at("volume_ml") << " ml, window " << grown.figures.at("window_low_hu") << " to "
              << grown.figures.at("window_high_hu") << " HU (median " << grown.figures.at("seed_median_hu")
              << " HU near the points)\n";
    for (const std::string& warning : grown.warnings)
        std::cout << "warning: " << warning << "\n";
    return 0;
}

} // namespace vsim::cli
