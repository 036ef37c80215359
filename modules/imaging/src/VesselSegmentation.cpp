#include "vsim/imaging/VesselSegmentation.h"

#include "LevelSetRefinement.h"
#include "MaskOps.h"
#include "Vesselness.h"
#include "vsim/core/Hounsfield.h"
#include "vsim/core/Localized.h"
#include "vsim/core/Median.h"
#include "vsim/core/StoredText.h"
#include "vsim/interop/ItkImage.h"

#include <itkBinaryThresholdImageFilter.h>
#include <itkCastImageFilter.h>
#include <itkConnectedThresholdImageFilter.h>
#include <itkSmoothingRecursiveGaussianImageFilter.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace vsim::imaging {
namespace {

using FloatImage = itk::Image<float, 3>;
using MaskImage = itk::Image<std::uint8_t, 3>;
using Mask = std::vector<std::uint8_t>;

struct Box
{
    Dims start{0, 0, 0};
    Dims size{0, 0, 0};
};

std::string number(double value, const char* format = "%.0f")
{
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, format, value);
    return buffer;
}

/// The import's test (Hounsfield.h): a crop without air passes, stored values without their rescale and MR do not.
void requireHounsfieldUnits(const CtVolume& ct)
{
    if (const std::string why = whyNotHounsfield(ct); !why.empty())
        throw Error(Pattern{"the intensities are not CT Hounsfield units (%1): import the CT rescaled to HU "
                            "(vascusim-cli import --rescale SLOPE,INTERCEPT), not MR",
                            {why}});
}

/// The largest component (26-connected) of `mask`; returns its voxels' linear indices.
std::vector<std::size_t> largestComponent(const Dims& dims, const Mask& mask)
{
    Mask visited(mask.size(), 0);
    std::vector<std::size_t> best;
    for (std::size_t index = 0; index < mask.size(); ++index)
    {
        if (!mask[index] || visited[index])
            continue;
        std::vector<std::size_t> members;
        floodFill(dims, {index}, [&](std::size_t i) { return mask[i] != 0; }, visited, false, &members);
        if (members.size() > best.size())
            best = std::move(members);
    }
    return best;
}

Dims indexOf(const Dims& dims, std::size_t linear)
{
    const std::size_t nx = std::size_t(dims[0]), slice = nx * std::size_t(dims[1]);
    return {int(linear % nx), int((linear % slice) / nx), int(linear / slice)};
}

std::size_t linearOf(const Dims& dims, const Dims& index)
{
    return std::size_t(index[0]) + std::size_t(dims[0]) * (std::size_t(index[1]) + std::size_t(dims[1]) * std::size_t(index[2]));
}

/// Bounding box of the voxels set in `mask`, grown by `margin` voxels per axis and clipped to the grid.
Box boundingBox(const Dims& dims, const Mask& mask, const Dims& margin)
{
    Dims low{dims[0], dims[1], dims[2]}, high{-1, -1, -1};
    for (std::size_t index = 0; index < mask.size(); ++index)
        if (mask[index])
        {
            const Dims v = indexOf(dims, index);
            for (int a = 0; a < 3; ++a)
                low[a] = std::min(low[a], v[a]), high[a] = std::max(high[a], v[a]);
        }
    Box box;
    for (int a = 0; a < 3; ++a)
    {
        box.start[a] = std::max(0, low[a] - margin[a]);
        box.size[a] = std::min(dims[a] - 1, high[a] + margin[a]) - box.start[a] + 1;
    }
    return box;
}

CtVolume crop(const CtVolume& ct, const Box& box)
{
    VolumeGeometry geometry = ct.geometry();
    geometry.origin = ct.geometry().indexToPatient(Eigen::Vector3d(box.start[0], box.start[1], box.start[2]));
    geometry.dims = box.size;
    CtVolume out = CtVolume::uninitialized(geometry);
    for (int k = 0; k < box.size[2]; ++k)
        for (int j = 0; j < box.size[1]; ++j)
            std::copy_n(ct.data() + ct.geometry().linearIndex(box.start[0], box.start[1] + j, box.start[2] + k), box.size[0],
                        &out.at(0, j, k));
    return out;
}

FloatImage::Pointer smoothedFloat(const CtVolume& ct, double sigmaMm)
{
    auto cast = itk::CastImageFilter<interop::ItkImage3<std::int16_t>, FloatImage>::New();
    cast->SetInput(interop::toItk(ct));
    if (sigmaMm <= 0.0)
    {
        cast->Update();
        return cast->GetOutput();
    }
    auto smooth = itk::SmoothingRecursiveGaussianImageFilter<FloatImage, FloatImage>::New();
    smooth->SetInput(cast->GetOutput());
    smooth->SetSigma(sigmaMm);
    smooth->Update();
    return smooth->GetOutput();
}

/// Multi-scale Frangi vesselness of bright tubes (Vesselness.h), normalised to its maximum in the region.
std::vector<float> vesselness(const FloatImage::Pointer& image, const ParameterSet& p)
{
    detail::VesselnessScales scales;
    scales.minSigmaMm = p.get("vesselness_min_sigma_mm");
    scales.maxSigmaMm = p.get("vesselness_max_sigma_mm");
    scales.steps = static_cast<unsigned>(p.get("vesselness_scales"));
    std::vector<float> values = detail::frangiVesselness(image.GetPointer(), scales);
    const float peak = *std::max_element(values.begin(), values.end());
    if (peak > 0.0f)
        for (float& v : values)
            v /= peak;
    return values;
}

Mask refine(const Mask& mask, const VolumeGeometry& geometry, double sigmaMm)
{
    if (sigmaMm <= 0.0)
        return mask;
    RealVolume field = RealVolume::uninitialized(geometry);
    std::transform(mask.begin(), mask.end(), field.data(), [](std::uint8_t v) { return float(v); });
    auto smooth = itk::SmoothingRecursiveGaussianImageFilter<FloatImage, FloatImage>::New();
    smooth->SetInput(interop::toItk(field));
    smooth->SetSigma(sigmaMm);
    smooth->Update();
    const float* smoothed = smooth->GetOutput()->GetBufferPointer();
    Mask out(mask.size());
    for (std::size_t i = 0; i < mask.size(); ++i)
        out[i] = smoothed[i] >= 0.5f;
    return out;
}

} // namespace

std::vector<ParameterSpec> segmentationParameters()
{
    const std::string window = "Layer 1: window and region growing", hessian = "Layer 2: vesselness",
                      levelSet = "Layer 3: level set", cleanup = "Layer 4: refinement and clean-up";
    return {
        {"min_contrast_hu", "Lowest contrast HU", "HU", 200, 50, 1000, window,
         "Lowest HU of contrast-filled blood; kidneys and tumour blush (about 150 HU) stay below."},
        {"max_contrast_hu", "Highest contrast HU", "HU", 650, 200, 3000, window,
         "Highest HU of contrast-filled blood; bone and calcium above it are excluded."},
        {"smoothing_sigma_mm", "Denoising sigma", "mm", 0.35, 0, 3, window,
         "Recursive Gaussian applied before thresholding (noise and partial volume)."},
        {"threshold_fraction", "Boundary level", "", 0.5, 0.1, 0.9, window,
         "Boundary HU = tissue + fraction x (blood - tissue); 0.5 is the partial-volume half level."},
        {"seed_erosion_mm", "Automatic seed erosion", "mm", 1.5, 0, 10, window,
         "The automatic seed lies in the largest bright component left after eroding this much (thick tubes)."},
        {"roi_margin_mm", "Region margin", "mm", 6, 1, 50, window,
         "Margin around the vessels found coarsely, inside which the fine layers work."},
        {"vesselness_threshold", "Vesselness threshold", "", 0.15, 0, 1, hessian,
         "Relative Frangi vesselness above which thin branches are added (0 turns layer 2 off)."},
        {"vesselness_min_sigma_mm", "Smallest vessel scale", "mm", 0.5, 0.1, 5, hessian, "Smallest Hessian scale."},
        {"vesselness_max_sigma_mm", "Largest vessel scale", "mm", 1.5, 0.2, 10, hessian, "Largest Hessian scale."},
        {"vesselness_scales", "Vesselness scales", "", 2, 1, 8, hessian, "Number of Hessian scales.", ParameterSpec::Kind::Integer},
        {"level_set_iterations", "Level-set steps", "", 20, 0, 500, levelSet,
         "Steps of the threshold level set that moves the boundary onto the boundary level (0 turns layer 3 off).",
         ParameterSpec::Kind::Integer},
        {"level_set_curvature", "Level-set curvature weight", "", 0.01, 0, 2, levelSet,
         "Weight of the curvature (smoothing) term against the contrast term; large values shrink thin vessels."},
        {"bone_margin_mm", "Bone margin", "mm", 1.0, 0, 5, cleanup,
         "Voxels this close to bone or calcium (above the highest contrast HU) are removed."},
        {"refine_sigma_mm", "Refinement sigma", "mm", 0.35, 0, 3, cleanup,
         "Recursive Gaussian refinement of the label boundary (thesis ch. 4.1); 0 turns it off."},
    };
}

SegmentationResult segmentVessels(const CtVolume& ct, const ParameterSet& p,
                                  const std::optional<Eigen::Vector3d>& seedMm, const Progress& progress)
{
    if (ct.isEmpty())
        throw Error("no CT image to segment");
    requireHounsfieldUnits(ct);
    const VolumeGeometry& geometry = ct.geometry();
    const Dims dims = geometry.dims;
    const double minHu = p.get("min_contrast_hu"), maxHu = p.get("max_contrast_hu");
    if (minHu >= maxHu)
        throw Error("min_contrast_hu must be below max_contrast_hu");
    SegmentationResult result;

    // Layer 1a, whole volume: the contrast window on the raw HU, the seed, the coarse region.
    progress.report(0.0, localized("vsim::Progress", "finding contrast-filled vessels"));
    Mask window(ct.size());
    std::transform(ct.data(), ct.data() + ct.size(), window.begin(),
                   [=](std::int16_t hu) { return std::uint8_t(hu >= minHu && hu <= maxHu); });
    std::size_t seedIndex = 0;
    if (seedMm)
    {
        const Eigen::Vector3d continuous = geometry.patientToIndex(*seedMm);
        const Dims voxel{int(std::lround(continuous.x())), int(std::lround(continuous.y())), int(std::lround(continuous.z()))};
        if (!geometry.contains(voxel[0], voxel[1], voxel[2]))
            throw Error(Pattern{"the seed (%1, %2, %3) mm lies outside the image: click inside a vessel",
                                {number(seedMm->x(), "%.1f"), number(seedMm->y(), "%.1f"),
                                 number(seedMm->z(), "%.1f")}});
        seedIndex = linearOf(dims, voxel);
        if (!window[seedIndex])
            throw Error(Pattern{"the seed is not in a contrast-filled vessel: %1 HU there, outside %2..%3 HU; click "
                                "inside a bright vessel or change min_contrast_hu / max_contrast_hu",
                                {std::to_string(ct.data()[seedIndex]), number(minHu), number(maxHu)}});
        result.seedMm = *seedMm;
    }
    else
    {
        Mask core = window;
        const int erosions = int(std::lround(p.get("seed_erosion_mm") / geometry.spacing.minCoeff()));
        for (int e = 0; e < erosions; ++e)
            core = erode6(dims, core);
        progress.throwIfCancelled();
        const std::vector<std::size_t> component = largestComponent(dims, core);
        const double voxelMl = geometry.spacing.prod() / 1000.0;
        if (component.empty() || double(component.size()) * voxelMl < 0.05)
            throw Error(Pattern{"no contrast-filled vessel found (no thick region of %1..%2 HU): is this a "
                                "contrast-enhanced CTA? Give a seed inside a vessel or lower min_contrast_hu",
                                {number(minHu), number(maxHu)}});
        Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
        for (std::size_t index : component)
        {
            const Dims v = indexOf(dims, index);
            centroid += Eigen::Vector3d(v[0], v[1], v[2]);
        }
        centroid /= double(component.size());
        seedIndex = *std::min_element(component.begin(), component.end(), [&](std::size_t a, std::size_t b) {
            const Dims va = indexOf(dims, a), vb = indexOf(dims, b);
            return (Eigen::Vector3d(va[0], va[1], va[2]) - centroid).squaredNorm() <
                   (Eigen::Vector3d(vb[0], vb[1], vb[2]) - centroid).squaredNorm();
        });
        const Dims v = indexOf(dims, seedIndex);
        result.seedMm = geometry.indexToPatient(Eigen::Vector3d(v[0], v[1], v[2]));
        result.seedFound = true;
    }
    Mask coarse(ct.size(), 0);
    floodFill(dims, {seedIndex}, [&](std::size_t index) { return window[index] != 0; }, coarse);
    window.clear();
    window.shrink_to_fit();
    progress.report(0.2, localized("vsim::Progress", "segmenting vessels"));

    // Layers 1b-4 in the region around the coarse vessels.
    Dims margin;
    for (int a = 0; a < 3; ++a)
        margin[a] = int(std::ceil(p.get("roi_margin_mm") / geometry.spacing[a]));
    const Box box = boundingBox(dims, coarse, margin);
    const CtVolume roi = crop(ct, box);
    const Dims roiDims = box.size;
    Mask roiCoarse(roi.size());
    for (int k = 0; k < roiDims[2]; ++k)
        for (int j = 0; j < roiDims[1]; ++j)
            for (int i = 0; i < roiDims[0]; ++i)
                roiCoarse[linearOf(roiDims, {i, j, k})] =
                    coarse[linearOf(dims, {box.start[0] + i, box.start[1] + j, box.start[2] + k})];
    coarse.clear();
    coarse.shrink_to_fit();
    const FloatImage::Pointer smooth = smoothedFloat(roi, p.get("smoothing_sigma_mm"));
    const float* hu = smooth->GetBufferPointer();
    progress.report(0.35, localized("vsim::Progress", "segmenting vessels"));

    // Blood inside the coarse region, tissue in a shell 2-3 voxels outside it.
    const Mask interior = erode6(roiDims, roiCoarse);
    Mask near = dilate6(roiDims, roiCoarse), far = near;
    for (int d = 0; d < 2; ++d)
        far = dilate6(roiDims, far);
    std::vector<float> bloodSamples, tissueSamples;
    for (std::size_t i = 0; i < roiCoarse.size(); ++i)
    {
        if (interior[i])
            bloodSamples.push_back(hu[i]);
        else if (far[i] && !near[i])
            tissueSamples.push_back(hu[i]);
    }
    const double blood = median(bloodSamples.empty() ? std::vector<float>{float(minHu)} : bloodSamples);
    const double tissue = median(tissueSamples.empty() ? std::vector<float>{40.0f} : tissueSamples);
    const double threshold = tissue + p.get("threshold_fraction") * (blood - tissue);
    result.figures["blood_hu"] = blood;
    result.figures["tissue_hu"] = tissue;
    result.figures["threshold_hu"] = threshold;
    if (blood - tissue < 100.0)
        result.warnings.push_back(storedText(Pattern{
            "weak contrast: blood %1 HU against tissue %2 HU; the boundary may be unreliable", {number(blood), number(tissue)}}));

    const Dims seedVoxel = indexOf(dims, seedIndex);
    const Dims roiSeed{seedVoxel[0] - box.start[0], seedVoxel[1] - box.start[1], seedVoxel[2] - box.start[2]};
    Mask vessel(roi.size(), 0);
    floodFill(roiDims, {linearOf(roiDims, roiSeed)}, [&](std::size_t i) { return hu[i] >= threshold && hu[i] <= maxHu; },
              vessel);
    if (vessel[linearOf(roiDims, roiSeed)] == 0)
        throw Error(Pattern{"the seed lies where the smoothed image is below the vessel boundary (%1 HU): click "
                            "nearer the centre of the vessel",
                            {number(threshold)}});
    progress.report(0.5, localized("vsim::Progress", "vesselness"));

    // Layer 2: thin branches the window lost. Candidates are tubular (vesselness) with some contrast; only
    // candidates beyond a 2-voxel band around the region count, so the layer extends branches and never
    // thickens the vessels already found; the band is bridged where a kept branch meets the region.
    if (p.get("vesselness_threshold") > 0.0)
    {
        const std::vector<float> tubes = vesselness(smooth, p);
        // Thin vessels keep over 40 % of the contrast at their centre; blushing tissue (tumour, kidney
        // cortex) does not, and its edges are plate-like rather than tubular.
        const double low = tissue + 0.4 * (blood - tissue), relative = p.get("vesselness_threshold");
        auto candidate = [&](std::size_t i) { return !vessel[i] && tubes[i] >= relative && hu[i] >= low && hu[i] <= maxHu; };
        const Mask band = dilate6(roiDims, dilate6(roiDims, vessel));
        Mask branches(vessel.size(), 0);
        std::vector<std::size_t> bandEdge; // candidates just outside the band, where a branch would leave it
        const Mask beyond = dilate6(roiDims, band);
        for (std::size_t i = 0; i < vessel.size(); ++i)
            if (beyond[i] && !band[i] && candidate(i))
                bandEdge.push_back(i);
        floodFill(roiDims, bandEdge, [&](std::size_t i) { return !band[i] && candidate(i); }, branches);
        const Mask bridge = dilate6(roiDims, dilate6(roiDims, branches));
        std::size_t added = 0;
        for (std::size_t i = 0; i < vessel.size(); ++i)
            if (branches[i] || (band[i] && bridge[i] && candidate(i)))
                vessel[i] = 1, ++added;
        result.figures["vesselness_added_voxels"] = double(added);
    }
    progress.throwIfCancelled();
    progress.report(0.65, localized("vsim::Progress", "level set"));

    // Layer 3: the level set moves the voxel boundary onto the boundary level, smoothed by curvature.
    {
        RealVolume contrast = RealVolume::uninitialized(roi.geometry());
        const double scale = 1.0 / std::max(blood - tissue, 1.0);
        std::transform(hu, hu + roi.size(), contrast.data(), [=](float v) { return float((v - tissue) * scale); });
        LevelSetSettings settings;
        settings.lowerContrast = p.get("threshold_fraction");
        settings.upperContrast = std::max((maxHu - tissue) * scale, settings.lowerContrast + 0.1);
        settings.curvatureWeight = p.get("level_set_curvature");
        settings.iterations = int(p.get("level_set_iterations"));
        int steps = 0;
        vessel = refineWithLevelSet(contrast, vessel, settings, &steps);
        result.figures["level_set_steps"] = double(steps);
    }
    progress.report(0.8, localized("vsim::Progress", "clean-up"));

    // Clean-up: bone exclusion, then hole filling (background not reachable from the region's border).
    const int boneSteps = int(std::lround(p.get("bone_margin_mm") / roi.geometry().spacing.minCoeff()));
    Mask bone(roi.size());
    for (std::size_t i = 0; i < bone.size(); ++i)
        bone[i] = hu[i] > maxHu;
    for (int s = 0; s < boneSteps; ++s)
        bone = dilate6(roiDims, bone);
    std::size_t boneRemoved = 0;
    for (std::size_t i = 0; i < vessel.size(); ++i)
        if (vessel[i] && bone[i])
            vessel[i] = 0, ++boneRemoved;
    if (boneRemoved > 0)
        result.warnings.push_back(
            storedText(Pattern{"%1 voxels next to bone or calcium excluded", {std::to_string(boneRemoved)}}));
    std::vector<std::size_t> border;
    for (int k = 0; k < roiDims[2]; ++k)
        for (int j = 0; j < roiDims[1]; ++j)
            for (int i = 0; i < roiDims[0]; ++i)
                if (i == 0 || j == 0 || k == 0 || i + 1 == roiDims[0] || j + 1 == roiDims[1] || k + 1 == roiDims[2])
                    border.push_back(linearOf(roiDims, {i, j, k}));
    Mask outside(vessel.size(), 0);
    floodFill(roiDims, border, [&](std::size_t i) { return vessel[i] == 0; }, outside, true);
    for (std::size_t i = 0; i < vessel.size(); ++i)
        vessel[i] = !outside[i];

    // Layer 4: recursive Gaussian refinement, then the seed's component.
    vessel = refine(vessel, roi.geometry(), p.get("refine_sigma_mm"));
    Mask kept(vessel.size(), 0);
    floodFill(roiDims, {linearOf(roiDims, roiSeed)}, [&](std::size_t i) { return vessel[i] != 0; }, kept);
    if (!kept[linearOf(roiDims, roiSeed)])
        kept = vessel; // the refinement thinned the seed away: keep what there is
    progress.throwIfCancelled();

    result.label = LabelVolume(geometry);
    std::size_t voxels = 0;
    for (int k = 0; k < roiDims[2]; ++k)
        for (int j = 0; j < roiDims[1]; ++j)
            for (int i = 0; i < roiDims[0]; ++i)
                if (kept[linearOf(roiDims, {i, j, k})])
                {
                    result.label.at(box.start[0] + i, box.start[1] + j, box.start[2] + k) = 1;
                    ++voxels;
                }
    if (voxels == 0)
        throw Error("the segmentation is empty: try a seed inside a vessel or a lower min_contrast_hu");
    result.figures["voxels"] = double(voxels);
    result.figures["volume_ml"] = double(voxels) * geometry.spacing.prod() / 1000.0;
    progress.report(1.0, localized("vsim::Progress", "segmented"));
    return result;
}

double diceCoefficient(const LabelVolume& a, std::uint8_t valueA, const LabelVolume& b, std::uint8_t valueB)
{
    if (!a.geometry().isClose(b.geometry(), 1e-6))
        throw Error("Dice needs two labels on the same grid");
    std::size_t inA = 0, inB = 0, both = 0;
    for (std::size_t i = 0; i < a.size(); ++i)
    {
        const bool x = a.data()[i] == valueA, y = b.data()[i] == valueB;
        inA += x;
        inB += y;
        both += x && y;
    }
    return inA + inB == 0 ? 1.0 : 2.0 * double(both) / double(inA + inB);
}

} // namespace vsim::imaging
