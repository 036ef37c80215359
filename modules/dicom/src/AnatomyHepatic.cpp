// The patient-like hepatic phantom, late arterial phase: aorta, celiac trunk, common hepatic, gastroduodenal,
// proper, right and left hepatic arteries and their segmental branches (Murray's law at branch points, 10 %
// taper per segment) down to tips under 0.7 mm, with the portal vein running beside them, touching (the
// separation problem of a real CT), hepatic veins barely brighter than the liver, the IVC, SMA and SMV, and a
// hypervascular tumour.
#include "AnatomyBuilder.h"
#include "AnatomyMeasures.h"

#include <Eigen/Geometry>

#include <cmath>
#include <numbers>

namespace vsim::dicom::detail {
namespace {

constexpr double kPortalPerArteryRadius = 2.6, kPortalMaxRadius = 7.0, kTouchGapMm = 0.1;
constexpr double kTaper = 0.9, kLengthRatio = 0.75, kBranchAngleDeg = 35.0;

/// Builds the portal branch beside an arterial segment: from `portalStart` to the artery's end offset sideways.
Vector3d portalOffset(const Vector3d& direction)
{
    Vector3d side = Vector3d::UnitY() - Vector3d::UnitY().dot(direction) * direction; // posterior, perpendicular
    if (side.norm() < 1e-3)
        side = Vector3d::UnitX();
    return side.normalized();
}

struct Builder
{
    ArterialTree& tree;
    std::vector<TubePiece> portal;
    double portalHu;
    std::vector<int> tips;
    int deepestTip = -1;
    Vector3d deepestDirection = Vector3d::UnitX();

    /// One hepatic artery of radius r0 at `node`, heading `direction`, then its binary subtree; the portal vein
    /// follows from `portalStart`.
    void grow(const std::string& name, int node, int parent, const Vector3d& direction, const Vector3d& plane,
              double r0, double length, int generationsLeft, const Vector3d& portalStart)
    {
        const Vector3d start = tree.model().nodes[std::size_t(node)].position;
        const Vector3d end = start + length * direction;
        const double r1 = r0 * kTaper;
        const SampledCurve curve = sampleCurve([&](double t) { return Vector3d(start + t * (end - start)); });
        const int segment = tree.addArtery(name, node, curve, [=](double s) { return r0 + (r1 - r0) * s / length; },
                                           0.0, 0.94 - 0.02 * (4 - generationsLeft), 0.92 - 0.02 * (4 - generationsLeft),
                                           parent);
        const double p1 = std::min(kPortalMaxRadius, kPortalPerArteryRadius * r1);
        const Vector3d portalEnd = end + (r1 + p1 + kTouchGapMm) * portalOffset(direction);
        const SampledCurve vein = sampleCurve([&](double t) { return Vector3d(portalStart + t * (portalEnd - portalStart)); });
        const double p0 = std::min(kPortalMaxRadius, kPortalPerArteryRadius * r0);
        for (std::size_t s = 1; s < vein.points.size(); ++s)
            portal.push_back({vein.points[s - 1], vein.points[s], p0 + (p1 - p0) * vein.arc[s - 1] / vein.length(),
                              p0 + (p1 - p0) * vein.arc[s] / vein.length(), portalHu, portalHu});
        if (generationsLeft == 0)
        {
            tips.push_back(segment);
            if (deepestTip < 0)
                deepestTip = segment, deepestDirection = direction;
            return;
        }
        const Vector3d nextPlane = direction.cross(plane).normalized();
        const double child = r1 * std::pow(2.0, -1.0 / 3.0);
        for (double side : {1.0, -1.0})
        {
            const Vector3d d = Eigen::AngleAxisd(side * kBranchAngleDeg * std::numbers::pi / 180.0, plane) * direction;
            grow("segmental hepatic artery", tree.segmentEndNode(segment), segment, d.normalized(), nextPlane, child,
                 length * kLengthRatio, generationsLeft - 1, portalEnd);
        }
    }
};

} // namespace

AnatomyPhantom buildAnatomyHepatic(const PhantomOptions& options, const ScannerSettings& scanner)
{
    std::mt19937_64 random = anatomyRandom(options.seed, 0x4E9);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    AnatomyPhantom phantom;
    phantom.kind = PhantomKind::HepaticTree;
    phantom.scanner = scanner;
    addAbdominalTorso(phantom, random, Vector3d(-50, -5, 60), Vector3d(98, 88, 80));
    const double portalHu = scanner.bloodHu * (0.45 + 0.1 * unit(random)); // late arterial: portal vein enhancing
    const double y0 = aortaCentreY();

    // Hepatic veins into the IVC at the top of the liver, barely enhanced.
    const Vector3d confluence = at(Vector3d(-22, 16, 128));
    for (const Vector3d& end : {Vector3d(-125, 10, 45), Vector3d(-65, -45, 35), Vector3d(-15, -50, 70)})
    {
        const SampledCurve vein = sampleCurve(bezier(confluence, 0.5 * (confluence + at(end)) + Vector3d(0, 0, 15), at(end)));
        phantom.layers.push_back(tube("hepatic vein", vein, [&](double s) { return 6.0 - 3.5 * s / vein.length(); },
                                      [](double) { return 105.0; }, label::kVein));
    }

    ArterialTree tree(scanner.bloodHu);
    const SampledCurve aortaCurve = sampleCurve([&](double t) { return at(Vector3d(kAortaX, y0, 330.0 - 630.0 * t)); });
    const double wall = kAortaOuterRadius - 10.5;
    const int aorta = tree.addArtery("aorta", -1, aortaCurve, [](double) { return 10.5; }, wall, 1.0, 0.97, -1);
    const auto aortaPoint = [&](double z) { return at(Vector3d(kAortaX, y0, z)); };
    const auto artery = [&](const std::string& name, int fromNode, int parent, const Vector3d& control,
                            const Vector3d& end, double r0, double r1) {
        const Vector3d start = fromNode < 0 ? aortaPoint(control.z()) : tree.model().nodes[std::size_t(fromNode)].position;
        const SampledCurve curve = sampleCurve(bezier(start, at(control), at(end)));
        const double length = curve.length();
        return tree.addArtery(name, fromNode, curve, [=](double s) { return r0 + (r1 - r0) * s / length; }, 0.6,
                              0.97, 0.95, parent);
    };
    const int celiac = artery("celiac trunk", -1, aorta, Vector3d(kAortaX, -6, 72), Vector3d(kAortaX - 2, -20, 78), 3.6, 3.4);
    artery("splenic artery", tree.segmentEndNode(celiac), celiac, Vector3d(40, -22, 85), Vector3d(72, 22, 120), 2.8, 2.5);
    const int hepatic = artery("common hepatic artery", tree.segmentEndNode(celiac), celiac, Vector3d(-18, -30, 80),
                               Vector3d(-36, -26, 82), 2.8, 2.6);
    artery("gastroduodenal artery", tree.segmentEndNode(hepatic), hepatic, Vector3d(-38, -36, 60),
           Vector3d(-34, -40, 35), 1.7, 1.5);
    const int proper = artery("proper hepatic artery", tree.segmentEndNode(hepatic), hepatic, Vector3d(-44, -24, 88),
                              Vector3d(-50, -18, 96), 2.4, 2.2);
    const int sma = artery("superior mesenteric artery", -1, aorta, Vector3d(kAortaX, -26, 50),
                           Vector3d(6, -34, -40), 3.4, 2.8);
    (void)sma;

    // Portal vein: the SMV beside the SMA up to the confluence, the main portal vein to the hilum behind the
    // proper hepatic artery, then one branch beside every hepatic artery.
    Builder builder{tree, {}, portalHu, {}};
    const Vector3d hilum = tree.model().nodes[std::size_t(tree.segmentEndNode(proper))].position;
    const Vector3d portalHilum = hilum + (2.2 + kPortalMaxRadius + kTouchGapMm) * Vector3d::UnitY();
    const SampledCurve smv = sampleCurve(bezier(at(Vector3d(-4, -30, -60)), at(Vector3d(-6, -22, 0)), at(Vector3d(-8, -5, 40))));
    const SampledCurve mainPortal = sampleCurve(bezier(smv.points.back(), at(Vector3d(-30, -2, 70)), portalHilum));
    for (const SampledCurve* curve : {&smv, &mainPortal})
        for (std::size_t s = 1; s < curve->points.size(); ++s)
            builder.portal.push_back({curve->points[s - 1], curve->points[s], 6.5, 6.5, portalHu, portalHu});
    const Vector3d rightDirection = Vector3d(-1.0, 0.15, 0.1).normalized();
    const Vector3d leftDirection = Vector3d(0.8, -0.45, 0.15).normalized();
    builder.grow("right hepatic artery", tree.segmentEndNode(proper), proper, rightDirection,
                 rightDirection.cross(Vector3d::UnitZ()).normalized(), 2.1, 30.0, 3, portalHilum);
    builder.grow("left hepatic artery", tree.segmentEndNode(proper), proper, leftDirection,
                 leftDirection.cross(Vector3d::UnitZ()).normalized(), 1.9, 24.0, 3, portalHilum);
    AnatomyLayer portalLayer{"portal vein", {}, 0.0, label::kPortalVein, false};
    portalLayer.solid.type = Solid::Type::Tubes;
    portalLayer.solid.pieces = builder.portal;
    phantom.layers.push_back(portalLayer);

    const VesselSegment& deepest = tree.model().segments[std::size_t(builder.deepestTip)];
    const Vector3d tumourCentre = deepest.points.back() + 8.0 * builder.deepestDirection;
    const double tumourRadius = 13.0 + 4.0 * unit(random);
    phantom.layers.push_back(ellipsoid("hypervascular tumour", tumourCentre, Vector3d::Constant(tumourRadius), 140.0,
                                       label::kTumour));
    tree.emitLayers(phantom.layers);

    phantom.arteries = tree.model();
    phantom.arteries.kind = PhantomKind::HepaticTree;
    phantom.arteries.bloodHu = scanner.bloodHu;
    double smallest = 1e9, sum = 0.0;
    for (int tip : builder.tips)
    {
        const double r = tree.model().segments[std::size_t(tip)].radii.back();
        smallest = std::min(smallest, r);
        sum += r;
    }
    auto& m = phantom.measures;
    m["tip_radius_min_mm"] = smallest;
    m["tip_radius_mean_mm"] = sum / double(builder.tips.size());
    m["hepatic_tips"] = double(builder.tips.size());
    m["portal_vein_hu"] = portalHu;
    m["tumour_radius_mm"] = tumourRadius;
    m["tumour_centre_x_mm"] = tumourCentre.x();
    m["tumour_centre_y_mm"] = tumourCentre.y();
    m["tumour_centre_z_mm"] = tumourCentre.z();
    phantom.definitions["tip_radius_min_mm"] = "smallest lumen radius at the end of a hepatic artery tip segment";
    phantom.definitions["hepatic_tips"] = "terminal segments of the right and left hepatic artery trees";
    return phantom;
}

} // namespace vsim::dicom::detail
