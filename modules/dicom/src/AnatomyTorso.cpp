#include "AnatomyBuilder.h"

#include <cmath>

namespace vsim::dicom::detail {
namespace {

// Offsets from kPhantomCentre (mm, LPS: +x patient left, +y posterior, +z superior).
const Vector3d kSpineCentre(0.0, 45.0, 0.0);
constexpr double kSpineSemiX = 24.0, kSpineSemiY = 20.0;
constexpr double kVertebraPeriod = 32.0, kDiscHeight = 6.0;
const Vector3d kIvc(-22.0, 18.0, 0.0);
constexpr double kIvcRadius = 10.0, kIvcBottomZ = -65.0;

// Tissue HU in a late arterial phase.
constexpr double kFatHu = -100.0, kMuscleHu = 50.0, kCorticalBoneHu = 650.0, kCancellousBoneHu = 220.0;
constexpr double kDiscHu = 85.0, kCsfHu = 15.0, kLiverHu = 95.0, kSpleenHu = 115.0, kKidneyCortexHu = 190.0;
constexpr double kKidneyMedullaHu = 95.0, kBowelWallHu = 45.0, kGasHu = -950.0, kFluidHu = 15.0;
constexpr double kVenaCavaHu = 95.0, kRenalVeinHu = 170.0;

void addSpine(AnatomyPhantom& phantom)
{
    auto& layers = phantom.layers;
    layers.push_back(cylinder("intervertebral discs", at(kSpineCentre), kSpineSemiX - 0.5, kSpineSemiY - 0.5,
                              kDiscHu, label::kBackground));
    layers.push_back(cylinder("posterior arches", at(Vector3d(0, 80, 0)), 20.0, 14.0, 500.0, label::kBone));
    layers.push_back(cylinder("spinal canal", at(Vector3d(0, 74, 0)), 9.0, 8.0, kCsfHu, label::kBackground));
    for (double z = -260.0; z < 320.0; z += kVertebraPeriod)
    {
        const double zMin = kPhantomCentre.z() + z, zMax = zMin + kVertebraPeriod - kDiscHeight;
        layers.push_back(cylinder("vertebral body cortex", at(kSpineCentre), kSpineSemiX, kSpineSemiY,
                                  kCorticalBoneHu, label::kBone, zMin, zMax));
        layers.push_back(cylinder("vertebral body", at(kSpineCentre), kSpineSemiX - 2.0, kSpineSemiY - 2.0,
                                  kCancellousBoneHu, label::kBone, zMin + 1.5, zMax - 1.5));
    }
}

void addKidney(AnatomyPhantom& phantom, double side, const Vector3d& centre)
{
    const Eigen::Matrix3d rotation = rotationZx(side * 20.0, side * 8.0);
    const std::string name = side < 0 ? "right kidney" : "left kidney";
    phantom.layers.push_back(ellipsoid(name + " cortex", at(centre), Vector3d(24, 22, 52), kKidneyCortexHu,
                                       label::kKidney, rotation));
    phantom.layers.push_back(ellipsoid(name + " medulla", at(centre + Vector3d(-side * 3, 0, 0)), Vector3d(14, 13, 40),
                                       kKidneyMedullaHu, label::kKidney, rotation));
}

/// A bowel loop along a wavy transverse path: wall, then gas or fluid inside.
void addBowelLoop(AnatomyPhantom& phantom, double z, double y, double radius, double contentHu, double phase)
{
    const SampledCurve path = sampleCurve([=](double t) {
        const double x = -95.0 + 190.0 * t;
        return at(Vector3d(x, y + 8.0 * std::sin(0.05 * x + phase), z + 12.0 * std::sin(0.035 * x + 2 * phase)));
    });
    phantom.layers.push_back(tube("bowel wall", path, [=](double) { return radius; },
                                  [](double) { return kBowelWallHu; }, label::kBowel));
    phantom.layers.push_back(tube("bowel content", path, [=](double) { return radius - 2.5; },
                                  [=](double) { return contentHu; }, label::kBowel));
}

} // namespace

double aortaCentreY()
{
    const double anterior = kSpineCentre.y() - kSpineSemiY * std::sqrt(1.0 - std::pow(kAortaX / kSpineSemiX, 2.0));
    return anterior - kAortaOuterRadius - 0.3;
}

void addAbdominalTorso(AnatomyPhantom& phantom, std::mt19937_64& random, const Vector3d& liverCentre,
                       const Vector3d& liverSemiAxes)
{
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    auto& layers = phantom.layers;
    layers.push_back(cylinder("subcutaneous fat", at(Vector3d(0, 5, 0)), 162, 118, kFatHu, label::kBackground));
    layers.push_back(cylinder("abdominal wall", at(Vector3d(0, 5, 0)), 150, 106, kMuscleHu, label::kBackground));
    layers.push_back(cylinder("intra-abdominal fat", at(Vector3d(0, 3, 0)), 140, 96, kFatHu + 5.0, label::kBackground));
    for (double side : {-1.0, 1.0})
    {
        layers.push_back(cylinder("paraspinal muscle", at(Vector3d(side * 32, 90, 0)), 24, 15, kMuscleHu,
                                  label::kBackground));
        layers.push_back(cylinder("psoas", at(Vector3d(side * 45, 50, 0)), 13, 11, kMuscleHu, label::kBackground,
                                  kPhantomCentre.z() - 300.0, kPhantomCentre.z() + 120.0));
    }
    addSpine(phantom);
    layers.push_back(ellipsoid("liver", at(liverCentre), liverSemiAxes, kLiverHu, label::kLiver, rotationZx(-10, 0)));
    layers.push_back(ellipsoid("spleen", at(Vector3d(90, 45, 175)), Vector3d(28, 45, 50), kSpleenHu, label::kSpleen,
                               rotationZx(30, 0)));
    addKidney(phantom, -1.0, Vector3d(-80, 38, 92));
    addKidney(phantom, 1.0, Vector3d(80, 34, 108));
    // Small bowel: a gas-filled loop, a fluid-filled one and a colon with stool and gas; the phase from the seed.
    addBowelLoop(phantom, -40.0, -60.0, 13.0, kGasHu, 6.0 * unit(random));
    addBowelLoop(phantom, 20.0, -62.0, 12.0, kFluidHu, 6.0 * unit(random));
    addBowelLoop(phantom, -115.0, -55.0, 14.0, kGasHu, 6.0 * unit(random));
    // The IVC right of the aorta, unopacified below the renal veins, mixed above; the common iliac veins.
    const SampledCurve ivc = sampleCurve([&](double t) {
        return at(Vector3d(kIvc.x(), kIvc.y(), kIvcBottomZ + t * (330.0 - kIvcBottomZ)));
    });
    layers.push_back(tube("inferior vena cava", ivc, [](double) { return kIvcRadius; },
                          [](double s) { return s < 170.0 ? kVenaCavaHu : kVenaCavaHu + 30.0; }, label::kVein));
    for (double side : {-1.0, 1.0})
    {
        const SampledCurve iliac = sampleCurve(bezier(at(Vector3d(kIvc.x(), kIvc.y() + 4, kIvcBottomZ + 5)),
                                                      at(Vector3d(side * 25, 34, -150)),
                                                      at(Vector3d(side * 62, 36, -280))));
        layers.push_back(tube(side < 0 ? "right common iliac vein" : "left common iliac vein", iliac,
                              [](double) { return 8.0; }, [](double) { return kVenaCavaHu; }, label::kVein));
    }
}

void addRenalVeins(AnatomyPhantom& phantom, double aortaAnteriorY)
{
    constexpr double kRadius = 5.0;
    const double y = aortaAnteriorY - kRadius - 0.3; // touching the aorta's anterior wall
    const std::vector<Vector3d> left{at(Vector3d(56, 24, 110)), at(Vector3d(kAortaX + 18, y, 110.5)),
                                     at(Vector3d(kAortaX, y, 110)), at(Vector3d(kAortaX - 16, y, 109.5)),
                                     at(Vector3d(kIvc.x(), kIvc.y() - 4, 109))};
    const SampledCurve leftCurve = sampleCurve([&](double t) {
        const double u = t * double(left.size() - 1);
        const std::size_t i = std::min(left.size() - 2, std::size_t(u));
        return Vector3d(left[i] + (u - double(i)) * (left[i + 1] - left[i]));
    });
    phantom.layers.push_back(tube("left renal vein", leftCurve, [=](double) { return kRadius; },
                                  [](double) { return kRenalVeinHu; }, label::kVein));
    const SampledCurve right = sampleCurve(bezier(at(Vector3d(-56, 32, 94)), at(Vector3d(-40, 26, 97)),
                                                  at(Vector3d(kIvc.x(), kIvc.y(), 100))));
    phantom.layers.push_back(tube("right renal vein", right, [=](double) { return kRadius; },
                                  [](double) { return kRenalVeinHu; }, label::kVein));
}

} // namespace vsim::dicom::detail
