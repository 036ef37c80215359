#include "Vesselness.h"

#include <itkHessianToObjectnessMeasureImageFilter.h>
#include <itkMultiScaleHessianBasedMeasureImageFilter.h>
#include <itkSymmetricSecondRankTensor.h>

namespace vsim::imaging::detail {

std::vector<float> frangiVesselness(itk::Image<float, 3>* image, const VesselnessScales& scales)
{
    using FloatImage = itk::Image<float, 3>;
    using HessianImage = itk::Image<itk::SymmetricSecondRankTensor<double, 3>, 3>;
    auto objectness = itk::HessianToObjectnessMeasureImageFilter<HessianImage, FloatImage>::New();
    objectness->SetBrightObject(true);
    objectness->SetObjectDimension(1);
    objectness->SetScaleObjectnessMeasure(false);
    objectness->SetAlpha(0.5);
    objectness->SetBeta(0.5);
    objectness->SetGamma(scales.gammaHu);
    auto multiScale = itk::MultiScaleHessianBasedMeasureImageFilter<FloatImage, HessianImage, FloatImage>::New();
    multiScale->SetInput(image);
    multiScale->SetHessianToMeasureFilter(objectness);
    multiScale->SetSigmaMinimum(scales.minSigmaMm);
    multiScale->SetSigmaMaximum(scales.maxSigmaMm);
    multiScale->SetNumberOfSigmaSteps(scales.steps);
    multiScale->Update();
    const FloatImage* out = multiScale->GetOutput();
    return {out->GetBufferPointer(), out->GetBufferPointer() + out->GetLargestPossibleRegion().GetNumberOfPixels()};
}

} // namespace vsim::imaging::detail
