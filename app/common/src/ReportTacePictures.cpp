#include "ReportTacePictures.h"

#include "ReportSupport.h"

#include "vsim/app/NetworkPipeline.h"
#include "vsim/app/ProjectionPicture.h"
#include "vsim/core/Error.h"
#include "vsim/sim/network/Lesions.h"
#include "vsim/sim/network/WorkingAngle.h"
#include "vsim/viz/LabelPalette.h"

#include <QImage>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace vsim::app::detail {
namespace {

constexpr double kWindowLowHu = 40.0 - 200.0, kWindowHighHu = 40.0 + 200.0; // abdominal window W 400, L 40

/// `image` scaled to `pixels` wide (nearest voxel: the voxels stay visible as they are).
QImage widened(const QImage& image, int pixels)
{
    return image.scaled(pixels, pixels * image.height() / std::max(1, image.width()), Qt::KeepAspectRatio,
                        Qt::FastTransformation);
}

} // namespace

report::Block territoryPicture(const study::Study& study, const study::Artifact& run, int pixels)
{
    if (!run.provenance.parameters.count("liver_label"))
        return report::Paragraph{
            localized("Report", "Perfused territory: the run had no liver label (simulate network --liver-label).")};
    try
    {
        std::vector<std::string> warnings;
        sim::network::NetworkRunSetup setup = recordedNetworkSetup(study, run, warnings);
        setup.rankTips = false;
        setup.parameters.set("working_angle", 0);
        const sim::network::NetworkRunResult again = sim::network::runNetwork(setup);
        if (!again.territories || !again.perfused)
            return report::Paragraph{localized("Report", "Perfused territory: the run again gave no territory.")};
        const LabelVolume territory = sim::network::territoryLabel(*again.territories, *again.perfused, again.lesions);
        const VolumeGeometry& g = territory.geometry();
        Eigen::Vector3d centre = Eigen::Vector3d::Zero();
        if (!again.lesions.empty())
            centre = again.lesions.front().centreMm;
        else
        {
            for (std::size_t v = 0; v < again.territories->voxels.size(); ++v)
                centre += again.territories->position(v);
            centre /= double(std::max<std::size_t>(1, again.territories->voxels.size()));
        }
        const int k = std::clamp(int(std::lround(g.patientToIndex(centre).z())), 0, g.dims[2] - 1);
        const std::string imageId = study.newestArtifact(study::ArtifactKind::Image);
        const CtVolume ct = imageId.empty() ? CtVolume() : study.loadImage(imageId);
        QImage picture(g.dims[0], g.dims[1], QImage::Format_RGB32);
        for (int j = 0; j < g.dims[1]; ++j)
            for (int i = 0; i < g.dims[0]; ++i)
            {
                double hu = kWindowLowHu;
                if (!ct.isEmpty())
                {
                    const Eigen::Vector3d index = ct.geometry().patientToIndex(g.indexToPatient(Eigen::Vector3d(i, j, k)));
                    const int a = int(std::lround(index.x())), b = int(std::lround(index.y())), c = int(std::lround(index.z()));
                    if (ct.geometry().contains(a, b, c))
                        hu = ct.at(a, b, c);
                }
                const int grey = int(std::lround(255.0 * std::clamp((hu - kWindowLowHu) / (kWindowHighHu - kWindowLowHu), 0.0, 1.0)));
                const viz::LabelColour& over = viz::kTerritoryPalette[std::min<std::size_t>(territory.at(i, j, k), 5)];
                auto mix = [&](double top) { return int(std::lround((1.0 - over[3]) * grey + over[3] * 255.0 * top)); };
                picture.setPixel(i, j, qRgb(mix(over[0]), mix(over[1]), mix(over[2])));
            }
        const std::string caption = withArguments(
            localized("Report",
                      "Perfused territory from the tip on the axial CT slice through the largest lesion (W 400 "
                      "/ L 40 HU; patient right on the left; the workstation's colours): green perfused liver, "
                      "blue perfused tumour, red tumour not perfused, yellow margin not perfused, the liver not "
                      "perfused unmarked (slice z = %1 mm)"),
            {std::to_string(int(std::lround(g.indexToPatient(Eigen::Vector3d(0, 0, k)).z())))});
        return report::Figure{caption, widened(picture, pixels)};
    }
    catch (const Error& error)
    {
        return report::Paragraph{
            withArguments(localized("Report", "Perfused territory: not drawn (%1)."), {error.what()})};
    }
}

report::Block workingViewPicture(const VesselNetwork& network, const study::Artifact& run, int pixels)
{
    const auto lao = run.attributes.find("working_lao_deg"), cranial = run.attributes.find("working_cranial_deg");
    const auto tip = run.attributes.find("tip_node");
    if (lao == run.attributes.end() || cranial == run.attributes.end() || tip == run.attributes.end())
        return report::Paragraph{
            localized("Report", "Working angle: none for this run (the tip at the root, or working_angle 0).")};
    const sim::network::CArmAngles angles{std::stod(lao->second), std::stod(cranial->second)};
    const sim::network::ProjectionImage view = sim::network::dsaProjection(network, int(std::stod(tip->second)), angles);
    auto side = [](double degrees, const std::string& plus, const std::string& minus)
    { return (degrees >= 0.0 ? plus : minus) + " " + fixed(std::abs(degrees), 1); };
    return report::Figure{
        withArguments(localized("Report",
                                "DSA-like view at the working angle (%1, %2 deg; patient supine, the head up): "
                                "the tree the contrast opacifies, the path to the tip twice as dense (%3 mm "
                                "pixels)"),
                      {side(angles.laoDeg, "LAO", "RAO"),
                       side(angles.cranialDeg, localized("Report", "cranial"), localized("Report", "caudal")),
                       fixed(view.pixelMm, 2)}),
        widened(projectionPicture(view), pixels)};
}

} // namespace vsim::app::detail
