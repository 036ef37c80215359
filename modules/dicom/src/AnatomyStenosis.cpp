// The patient-like stenosis: a superficial femoral artery in the thigh, 8 degrees off the z axis, with an
// eccentric stenosis (the lumen pushed aside by plaque, the outer wall remodelled outwards), calcified plaque on
// the thick side, the femoral vein touching it and the femur beside them. The vessel's diameter, the stenosis's
// length and a second, milder blockage downstream are options (the thesis's hand and heart cases, ch. 5.5); the
// defaults draw what they always did.
#include "AnatomyBuilder.h"
#include "AnatomyMeasures.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace vsim::dicom::detail {
namespace {

double raisedCosine(double x, double halfLength)
{
    return std::abs(x) >= halfLength ? 0.0 : 0.5 * (1.0 + std::cos(std::numbers::pi * x / halfLength));
}

} // namespace

AnatomyPhantom buildAnatomyStenosis(const PhantomOptions& options, const ScannerSettings& scanner)
{
    std::mt19937_64 random = anatomyRandom(options.seed, 0x57E);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    AnatomyPhantom phantom;
    phantom.kind = PhantomKind::Stenosis;
    phantom.scanner = scanner;
    const Vector3d c = kPhantomCentre;
    phantom.layers.push_back(cylinder("subcutaneous fat", c, 80, 75, -100.0, label::kBackground));
    phantom.layers.push_back(cylinder("thigh muscles", c + Vector3d(0, 2, 0), 70, 64, 55.0, label::kBackground));
    phantom.layers.push_back(cylinder("femur cortex", c + Vector3d(-12, 18, 0), 14, 14, 1100.0, label::kBone));
    phantom.layers.push_back(cylinder("femur marrow", c + Vector3d(-12, 18, 0), 9, 9, -20.0, label::kBone));

    const double r0 = 0.5 * options.vesselDiameterMm, wall = 0.9 * (r0 / 3.0); // 0.9 mm at the default 6 mm
    const double fraction = options.stenosisPercent / 100.0;
    const double drawnHalfLength = 10.0 + 4.0 * unit(random);
    const double halfLength = options.stenosisLengthMm > 0.0 ? 0.5 * options.stenosisLengthMm : drawnHalfLength;
    const double reach = 0.5 * options.size[2] * options.spacing.z() + 30.0;
    // Blockage B (its own random stream, so that the default phantoms stay as they were): 12 mm of normal lumen
    // past the first's end.
    std::mt19937_64 secondRandom = anatomyRandom(options.seed, 0x57F);
    const double fraction2 = options.secondStenosisPercent / 100.0;
    const double halfLength2 = options.stenosisLengthMm > 0.0 ? halfLength : 10.0 + 4.0 * unit(secondRandom);
    const double reach2 = reach + halfLength + 12.0 + halfLength2;
    const Vector3d axis = Vector3d(0.15, 0.10, 1.0).normalized();
    const Vector3d centre = c + Vector3d(22, -14, 0);
    const double angle = 2.0 * std::numbers::pi * unit(random);
    Vector3d u = axis.cross(Vector3d::UnitZ()).normalized();
    u = (std::cos(angle) * u + std::sin(angle) * axis.cross(u)).normalized(); // the side the lumen is pushed to
    const auto lumenRadius = [=](double s) {
        return r0 * (1.0 - fraction * raisedCosine(s - reach, halfLength) -
                     fraction2 * raisedCosine(s - reach2, halfLength2));
    };
    const auto lumenOffset = [=](double s) { return 0.7 * (r0 - lumenRadius(s)); };
    const auto outerRadius = [=](double s) {
        return r0 + wall + 0.6 * fraction * r0 * raisedCosine(s - reach, halfLength * 1.3) +
               0.6 * fraction2 * r0 * raisedCosine(s - reach2, halfLength2 * 1.3);
    };
    const SampledCurve axisCurve = sampleCurve([&](double t) { return Vector3d(centre + (t - 0.5) * 2.0 * reach * axis); });
    const SampledCurve lumenCurve = sampleCurve([&](double t) {
        const double s = t * 2.0 * reach;
        return Vector3d(centre + (s - reach) * axis + lumenOffset(s) * u);
    });

    // The femoral vein behind and beside the artery, touching its outer wall.
    const Vector3d veinSide = (axis.cross(Vector3d::UnitX()).normalized() * -1.0 + 0.5 * u.cross(axis)).normalized();
    const double veinRadius = 5.5;
    const SampledCurve vein = sampleCurve([&](double t) {
        return Vector3d(centre + (t - 0.5) * 2.0 * reach * axis + (r0 + wall + veinRadius + 0.2) * veinSide);
    });
    phantom.layers.push_back(tube("femoral vein", vein, [=](double) { return veinRadius; },
                                  [](double) { return 95.0; }, label::kVein));

    ArterialTree tree(scanner.bloodHu);
    tree.addArtery("superficial femoral artery", -1, lumenCurve, lumenRadius, 0.0, 1.0, 0.95, -1);
    tree.addOuterContour(axisCurve, outerRadius, wall);
    tree.emitLayers(phantom.layers);
    // Calcified plaque on the thick side of the stenosis: it blooms.
    const int plaques = 2 + int(2.0 * unit(random));
    for (int p = 0; p < plaques; ++p)
    {
        const double s = reach + (unit(random) - 0.5) * halfLength;
        const double tilt = (unit(random) - 0.5) * 1.2; // radians around the axis from the thick side
        const Vector3d radial = (std::cos(tilt) * -u + std::sin(tilt) * axis.cross(u)).normalized();
        const double inner = lumenRadius(s) - lumenOffset(s);
        const double depth = inner + 0.5 * (outerRadius(s) - inner);
        Eigen::Matrix3d frame;
        frame.col(0) = radial;
        frame.col(1) = axis.cross(radial).normalized();
        frame.col(2) = axis;
        AnatomyLayer plaque = ellipsoid("calcified plaque", centre + (s - reach) * axis + depth * radial,
                                        std::min(1.0, r0 / 3.0) *
                                            Vector3d(0.8, 1.6 + unit(random), 2.0 + 2.0 * unit(random)),
                                        600.0 + 900.0 * unit(random), label::kCalcium, frame);
        plaque.blooms = true;
        phantom.layers.push_back(plaque);
    }
    phantom.arteries = tree.model();
    phantom.arteries.kind = PhantomKind::Stenosis;
    phantom.arteries.bloodHu = scanner.bloodHu;
    auto& m = phantom.measures;
    m["stenosis_percent"] = options.stenosisPercent;
    m["reference_diameter_mm"] = 2.0 * r0;
    m["minimal_diameter_mm"] = 2.0 * lumenRadius(reach);
    m["minimal_area_mm2"] = std::numbers::pi * std::pow(lumenRadius(reach), 2.0);
    const Vector3d narrowest = centre + lumenOffset(reach) * u;
    m["stenosis_centre_x_mm"] = narrowest.x();
    m["stenosis_centre_y_mm"] = narrowest.y();
    m["stenosis_centre_z_mm"] = narrowest.z();
    m["stenosis_length_mm"] = 2.0 * halfLength;
    if (fraction2 > 0.0)
    {
        m["second_stenosis_percent"] = options.secondStenosisPercent;
        m["second_minimal_diameter_mm"] = 2.0 * lumenRadius(reach2);
        m["second_stenosis_length_mm"] = 2.0 * halfLength2;
        const Vector3d second = centre + (reach2 - reach) * axis + lumenOffset(reach2) * u;
        m["second_stenosis_centre_x_mm"] = second.x();
        m["second_stenosis_centre_y_mm"] = second.y();
        m["second_stenosis_centre_z_mm"] = second.z();
    }
    phantom.definitions["stenosis_percent"] = "diameter stenosis 100 (1 - minimal lumen diameter / reference lumen "
                                              "diameter), the reference the normal lumen beyond the lesion (NASCET-style)";
    phantom.definitions["stenosis_length_mm"] = "length over which the lumen radius is below the reference";
    return phantom;
}

} // namespace vsim::dicom::detail
