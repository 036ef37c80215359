#include "LevelSetRefinement.h"

#include "vsim/core/Error.h"
#include "vsim/interop/ItkImage.h"

#include <itkThresholdSegmentationLevelSetImageFilter.h>

#include <algorithm>

namespace vsim::imaging {

std::vector<std::uint8_t> refineWithLevelSet(const RealVolume& contrast, const std::vector<std::uint8_t>& mask,
                                             const LevelSetSettings& settings, int* elapsedIterations)
{
    if (mask.size() != contrast.size())
        throw Error("level set: the mask and the contrast image differ in size");
    if (elapsedIterations)
        *elapsedIterations = 0;
    if (settings.iterations <= 0)
        return mask;

    // ITK's convention: the model is negative inside. A step of -0.5 / +0.5 puts the initial front half-way
    // between the inside and the outside voxels; the sparse field re-distances it from there.
    RealVolume model = RealVolume::uninitialized(contrast.geometry());
    std::transform(mask.begin(), mask.end(), model.data(), [](std::uint8_t v) { return v ? -0.5f : 0.5f; });

    using Image = itk::Image<float, 3>;
    auto filter = itk::ThresholdSegmentationLevelSetImageFilter<Image, Image, float>::New();
    filter->SetInput(interop::toItk(model));
    filter->SetFeatureImage(interop::toItk(contrast));
    // Speed = contrast - lower below the mid-point, upper - contrast above it: positive in the blood, zero at
    // the boundary level, negative in the tissue and in bone; no Laplacian edge term (edge weight 0).
    filter->SetLowerThreshold(settings.lowerContrast);
    filter->SetUpperThreshold(settings.upperContrast);
    filter->SetEdgeWeight(0.0);
    filter->SetPropagationScaling(1.0);
    filter->SetCurvatureScaling(settings.curvatureWeight);
    filter->SetAdvectionScaling(0.0);
    filter->SetNumberOfIterations(static_cast<unsigned>(settings.iterations));
    filter->SetMaximumRMSError(settings.maxRmsChange);
    filter->SetIsoSurfaceValue(0.0);
    filter->Update();

    const Image* level = filter->GetOutput();
    const float* phi = level->GetBufferPointer();
    std::vector<std::uint8_t> out(mask.size());
    for (std::size_t i = 0; i < out.size(); ++i)
        out[i] = phi[i] <= 0.0f;
    if (elapsedIterations)
        *elapsedIterations = static_cast<int>(filter->GetElapsedIterations());
    return out;
}

} // namespace vsim::imaging
