#include "vsim/dicom/AnatomyPhantom.h"

#include "AnatomyMeasures.h"

#include "vsim/core/Error.h"

#include <nlohmann/json.hpp>

namespace vsim::dicom {

AnatomyPhantom buildAnatomyPhantom(PhantomKind kind, const PhantomOptions& options)
{
    options.validate();
    const ScannerSettings scanner = drawScanner(options);
    switch (kind)
    {
    case PhantomKind::Aaa: return detail::buildAnatomyAaa(options, scanner);
    case PhantomKind::HepaticTree: return detail::buildAnatomyHepatic(options, scanner);
    case PhantomKind::Stenosis: return detail::buildAnatomyStenosis(options, scanner);
    case PhantomKind::Bifurcation: break;
    }
    throw Error(Pattern{"the %1 phantom exists in the analytic style only (--style analytic)",
                        {phantomKindName(kind)}});
}

std::string anatomyTruthJson(const AnatomyPhantom& phantom, const PhantomOptions& options)
{
    using nlohmann::json;
    json document = json::parse(phantomTruthJson(phantom.arteries, options));
    document["style"] = "patient";
    document.erase("tissues");
    document["options"].erase("noise_hu");
    document["options"].erase("blur_sigma_mm");
    json labels = json::object();
    for (int value = 1; value < 256; ++value)
        if (const std::string name = label::labelName(std::uint8_t(value)); !name.empty())
            labels[std::to_string(value)] = name;
    document["labels"] = labels;
    json layers = json::array();
    for (const AnatomyLayer& layer : phantom.layers)
    {
        json entry = {{"name", layer.name}, {"label", layer.label}, {"blooms", layer.blooms}};
        if (layer.solid.type == Solid::Type::Tubes)
            entry["tube_pieces"] = layer.solid.pieces.size();
        else
            entry["hu"] = layer.hu;
        layers.push_back(entry);
    }
    document["layers"] = layers;
    document["scanner"] = {{"psf_fwhm_mm", phantom.scanner.psfFwhmMm},
                           {"slice_thickness_mm", phantom.scanner.sliceThicknessMm},
                           {"noise_hu", phantom.scanner.noiseHu},
                           {"aortic_blood_hu", phantom.scanner.bloodHu},
                           {"blooming_psf_factor", phantom.scanner.bloomFactor},
                           {"sub_voxels_per_axis", 4},
                           {"noise_power_spectrum", "white noise through a difference of Gaussians in-plane"}};
    document["measures"] = phantom.measures;
    document["definitions"] = phantom.definitions;
    document["note"] = "Truth of a patient-like phantom. Centerlines and radii are the arterial lumen's; a branch "
                       "starts on its parent's centerline. Labels are decided at voxel centres, the last layer "
                       "containing the centre winning. Estimators must not read the scanner block: it is the "
                       "truth against which blur and noise estimates are checked.";
    return document.dump(2) + "\n";
}

} // namespace vsim::dicom
