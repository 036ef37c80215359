#include "vsim/dicom/AnatomyPhantom.h"

#include "AnatomyPainter.h"
#include "ScannerModel.h"

#include "vsim/core/Localized.h"
#include "vsim/core/ParallelFor.h"

#include <algorithm>
#include <cmath>
#include <random>

namespace vsim::dicom {
namespace {

constexpr double kFwhmPerSigma = 2.3548200450309493; // 2 sqrt(2 ln 2)

/// The voxels of a slice; throws nothing.
std::size_t pixelsOf(const VolumeGeometry& geometry)
{
    return std::size_t(geometry.dims[0]) * std::size_t(geometry.dims[1]);
}

} // namespace

std::string label::labelName(std::uint8_t value)
{
    switch (value)
    {
    case kBackground: return "background";
    case kVesselLumen: return "lumen";
    case kTumour: return "tumour";
    case kBone: return "bone";
    case kThrombus: return "thrombus";
    case kWall: return "wall";
    case kCalcium: return "calcium";
    case kVein: return "vein";
    case kPortalVein: return "portal vein";
    case kLiver: return "liver";
    case kKidney: return "kidney";
    case kSpleen: return "spleen";
    case kBowel: return "bowel";
    case kHeart: return "heart";
    default: return {};
    }
}

ScannerSettings drawScanner(const PhantomOptions& options)
{
    // One stream per phantom seed, apart from the noise streams (those are seeded per slice).
    std::mt19937_64 random(options.seed * 0xD1B54A32D192ED03ull + 0x8CB92BA72F3D8DD7ull);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    ScannerSettings scanner;
    scanner.psfFwhmMm = 0.6 + 0.4 * unit(random);
    scanner.sliceThicknessMm = options.spacing.z() * (1.0 + 0.5 * unit(random));
    scanner.noiseHu = 10.0 + 20.0 * unit(random);
    scanner.bloodHu = 280.0 + 140.0 * unit(random);
    if (options.psfFwhmMm)
        scanner.psfFwhmMm = *options.psfFwhmMm;
    if (options.scannerNoiseHu)
        scanner.noiseHu = *options.scannerNoiseHu;
    return scanner;
}

CtVolume renderAnatomyCt(const AnatomyPhantom& phantom, const VolumeGeometry& geometry, std::uint64_t seed,
                         const Progress& progress)
{
    geometry.validate();
    const std::size_t pixels = pixelsOf(geometry), slices = std::size_t(geometry.dims[2]);
    detail::FloatVolume ideal{geometry.dims, std::vector<float>(geometry.voxelCount())};
    detail::FloatVolume bloom{geometry.dims, std::vector<float>(geometry.voxelCount())};
    const Progress painting = progress.subRange(0.0, 0.6);
    parallelFor(
        slices,
        [&](std::size_t k) {
            detail::SliceCanvas canvas(geometry, int(k));
            for (const AnatomyLayer& layer : phantom.layers)
                canvas.paint(layer);
            canvas.resolve(ideal.values.data() + k * pixels, bloom.values.data() + k * pixels);
        },
        [&](std::size_t done) { painting.report(double(done) / double(slices), localized("vsim::Progress", "painting the anatomy")); });

    const ScannerSettings& scanner = phantom.scanner;
    const double sigmaXy = scanner.psfFwhmMm / kFwhmPerSigma, sigmaZ = scanner.sliceThicknessMm / kFwhmPerSigma;
    const bool anyBloom = std::any_of(phantom.layers.begin(), phantom.layers.end(),
                                      [](const AnatomyLayer& layer) { return layer.blooms; });
    for (int axis = 0; axis < 3; ++axis)
    {
        const double sigma = (axis == 2 ? sigmaZ : sigmaXy) / geometry.spacing[axis];
        blurAlongAxis(ideal, axis, sigma, progress.subRange(0.6 + 0.05 * axis, 0.65 + 0.05 * axis));
        if (anyBloom)
            blurAlongAxis(bloom, axis, sigma * scanner.bloomFactor);
    }

    CtVolume volume(geometry);
    const double grain = sigmaXy / std::min(geometry.spacing.x(), geometry.spacing.y());
    const Progress noising = progress.subRange(0.8, 1.0);
    parallelFor(
        slices,
        [&](std::size_t k) {
            float* slice = ideal.values.data() + k * pixels;
            const float* excess = bloom.values.data() + k * pixels;
            for (std::size_t p = 0; p < pixels; ++p)
                slice[p] += excess[p];
            detail::addCorrelatedNoise(slice, geometry.dims[0], geometry.dims[1], scanner.noiseHu,
                                       std::max(0.6, grain), seed, k);
            std::int16_t* out = volume.data() + k * pixels;
            for (std::size_t p = 0; p < pixels; ++p)
                out[p] = std::int16_t(std::clamp(std::lround(slice[p]), long(hu::kMinimum), long(hu::kMaximum)));
        },
        [&](std::size_t done) { noising.report(double(done) / double(slices), localized("vsim::Progress", "scanner noise")); });
    return volume;
}

LabelVolume renderAnatomyLabels(const AnatomyPhantom& phantom, const VolumeGeometry& geometry,
                                const Progress& progress)
{
    LabelVolume labels(geometry);
    const std::size_t pixels = pixelsOf(geometry), slices = std::size_t(geometry.dims[2]);
    parallelFor(
        slices, [&](std::size_t k) { detail::labelSlice(phantom, geometry, int(k), labels.data() + k * pixels); },
        [&](std::size_t done) { progress.report(double(done) / double(slices), localized("vsim::Progress", "rendering truth labels")); });
    return labels;
}

} // namespace vsim::dicom
