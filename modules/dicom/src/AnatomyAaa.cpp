// The patient-like AAA: an infrarenal aneurysm bulging forwards off the spine, eccentric lumen, crescent thrombus
// (thickest anteriorly), a wall of 1.5..2 mm, calcified plaques in the wall, renal, celiac, mesenteric and common
// iliac arteries, the left renal vein crossing in front of the aorta, the IVC beside it.
#include "AnatomyBuilder.h"
#include "AnatomyMeasures.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace vsim::dicom::detail {
namespace {

constexpr double kTopZ = 330.0, kLeftRenalZ = 115.0, kRightRenalZ = 105.0, kCeliacZ = 150.0, kSmaZ = 135.0;
constexpr double kBifurcationZ = -60.0;

/// Raised cosine with different half-lengths above and below the peak: 1 at the peak, 0 beyond.
double skewedBump(double z, double peak, double above, double below)
{
    const double u = (z - peak) / (z >= peak ? above : below);
    return std::abs(u) >= 1.0 ? 0.0 : 0.5 * (1.0 + std::cos(std::numbers::pi * u));
}

} // namespace

AnatomyPhantom buildAnatomyAaa(const PhantomOptions& options, const ScannerSettings& scanner)
{
    std::mt19937_64 random = anatomyRandom(options.seed, 0xAAA);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    AnatomyPhantom phantom;
    phantom.kind = PhantomKind::Aaa;
    phantom.scanner = scanner;
    addAbdominalTorso(phantom, random, Vector3d(-70, -5, 185), Vector3d(90, 80, 80));

    const double wall = 1.5 + 0.5 * unit(random);                 // mm
    const double outerNeck = kAortaOuterRadius, lumenNeck = outerNeck - wall;
    const double outerMax = 0.5 * options.aneurysmDiameterMm;
    const double lumenMax = lumenNeck + 0.55 * (outerMax - outerNeck); // thrombus fills the rest
    const double peakZ = 15.0 + 10.0 * unit(random), above = 60.0 + 10.0 * unit(random), below = 45.0 + 10.0 * unit(random);
    const double lateral = unit(random) < 0.5 ? -0.25 : 0.25;      // the sac also leans left or right
    const double lumenAngle = (-35.0 + 70.0 * unit(random)) * std::numbers::pi / 180.0;
    const Vector3d lumenDirection(std::sin(lumenAngle), std::cos(lumenAngle), 0.0); // posterior, turned
    const double y0 = aortaCentreY();

    AaaProfile profile;
    profile.outerRadius = [=](double z) { return outerNeck + (outerMax - outerNeck) * skewedBump(z - kPhantomCentre.z(), peakZ, above, below); };
    profile.lumenRadius = [=](double z) { return lumenNeck + (lumenMax - lumenNeck) * skewedBump(z - kPhantomCentre.z(), peakZ, above, below); };
    profile.outerCentre = [=](double z) {
        const double bulge = profile.outerRadius(z) - outerNeck; // forwards, the posterior wall stays on the spine
        return Vector3d(kPhantomCentre.x() + kAortaX + lateral * bulge, kPhantomCentre.y() + y0 - bulge, z);
    };
    profile.lumenCentre = [=](double z) {
        const double offset = 0.6 * (profile.outerRadius(z) - wall - profile.lumenRadius(z));
        return Vector3d(profile.outerCentre(z) + offset * lumenDirection);
    };
    profile.wallMm = wall;
    profile.topZ = kPhantomCentre.z() + kTopZ;
    profile.bottomZ = kPhantomCentre.z() + kBifurcationZ;
    profile.lowestRenalZ = kPhantomCentre.z() + kRightRenalZ;

    ArterialTree tree(scanner.bloodHu);
    const auto alongZ = [&](const std::function<Vector3d(double)>& centre) {
        return sampleCurve([&](double t) { return centre(profile.topZ + t * (profile.bottomZ - profile.topZ)); });
    };
    const SampledCurve lumenCurve = alongZ(profile.lumenCentre), outerCurve = alongZ(profile.outerCentre);
    const auto zOf = [&](const SampledCurve& curve) {
        return [&curve](double s) {
            const auto it = std::lower_bound(curve.arc.begin(), curve.arc.end(), s);
            return curve.points[std::size_t(std::min<long>(it - curve.arc.begin(), long(curve.arc.size()) - 1))].z();
        };
    };
    const auto lumenZ = zOf(lumenCurve), outerZ = zOf(outerCurve);
    const int aorta = tree.addArtery("aorta", -1, lumenCurve, [&](double s) { return profile.lumenRadius(lumenZ(s)); },
                                     0.0, 1.0, 0.97, -1);
    tree.addOuterContour(outerCurve, [&](double s) { return profile.outerRadius(outerZ(s)); }, wall);

    const auto branch = [&](const std::string& name, const std::function<Vector3d(double)>& curve, double r0,
                            double r1, double branchWall) {
        const SampledCurve sampled = sampleCurve(curve);
        return tree.addArtery(name, -1, sampled, [=, length = sampled.length()](double s) { return r0 + (r1 - r0) * s / length; },
                              branchWall, 0.97, 0.9, aorta);
    };
    const auto lumenAt = [&](double z) { return profile.lumenCentre(kPhantomCentre.z() + z); };
    branch("left renal artery",
           bezier(lumenAt(kLeftRenalZ), at(Vector3d(35, 20, 116)), at(Vector3d(54, 30, 112))), 3.0, 2.6, 0.8);
    branch("right renal artery",
           bezier(lumenAt(kRightRenalZ), at(Vector3d(-22, 40, 103)), at(Vector3d(-54, 33, 97))), 3.0, 2.6, 0.8);
    const int celiac = branch("celiac trunk",
                              bezier(lumenAt(kCeliacZ), at(Vector3d(kAortaX, -8, 152)), at(Vector3d(kAortaX - 2, -20, 157))),
                              3.5, 3.3, 1.0);
    const Vector3d celiacEnd = tree.model().nodes[std::size_t(tree.segmentEndNode(celiac))].position;
    for (const auto& [name, control, end] :
         {std::tuple{"common hepatic artery", Vector3d(-20, -28, 160), Vector3d(-48, -22, 165)},
          std::tuple{"splenic artery", Vector3d(40, -22, 160), Vector3d(70, 12, 168)}})
    {
        const SampledCurve sampled = sampleCurve(bezier(celiacEnd, at(control), at(end)));
        tree.addArtery(name, tree.segmentEndNode(celiac), sampled, [](double) { return 2.7; }, 0.8, 0.92, 0.88, celiac);
    }
    branch("superior mesenteric artery",
           bezier(lumenAt(kSmaZ), at(Vector3d(kAortaX, -28, 126)), at(Vector3d(6, -32, 55))), 3.6, 2.8, 1.0);

    // Common iliac arteries from the bifurcation, tapering after 55 mm.
    const Vector3d bifurcation = profile.lumenCentre(profile.bottomZ);
    for (double side : {-1.0, 1.0})
    {
        const SampledCurve sampled =
            sampleCurve(bezier(bifurcation, at(Vector3d(kAortaX + side * 16, 12, -115)), at(Vector3d(side * 58, 12, -290))));
        tree.addArtery(side < 0 ? "right common iliac artery" : "left common iliac artery",
                       tree.segmentEndNode(aorta), sampled,
                       [](double s) { return s < 55.0 ? 5.6 : 5.6 - 0.8 * std::min(1.0, (s - 55.0) / 100.0); }, 1.2,
                       0.97, 0.92, aorta);
    }
    addRenalVeins(phantom, y0 - outerNeck);
    tree.emitLayers(phantom.layers);

    // Calcified plaques in the wall of the sac and neck, and at the iliac origins; they bloom.
    const int plaques = 4 + int(4.0 * unit(random));
    for (int p = 0; p < plaques; ++p)
    {
        const double z = kPhantomCentre.z() + peakZ - below + (above + below + 20.0) * unit(random);
        const double angle = 2.0 * std::numbers::pi * unit(random);
        const Vector3d radial(std::cos(angle), std::sin(angle), 0.0);
        const double r = profile.outerRadius(z);
        AnatomyLayer plaque = ellipsoid("calcified plaque", profile.outerCentre(z) + (r - wall + 0.3) * radial,
                                        Vector3d(1.0, 2.0 + 1.5 * unit(random), 2.5 + 2.0 * unit(random)),
                                        600.0 + 900.0 * unit(random), label::kCalcium, rotationZx(angle * 180.0 / std::numbers::pi, 0.0));
        plaque.blooms = true;
        phantom.layers.push_back(plaque);
    }
    phantom.arteries = tree.model();
    phantom.arteries.kind = PhantomKind::Aaa;
    phantom.arteries.bloodHu = scanner.bloodHu;
    measureAaa(profile, phantom);
    return phantom;
}

} // namespace vsim::dicom::detail
