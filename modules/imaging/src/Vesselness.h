#pragma once

// Multi-scale Frangi vesselness of bright tubes (ITK's Hessian objectness): the shared filter of the automatic
// segmentation's thin-branch layer (VesselSegmentation.cpp) and of the minimal paths between points (VesselPaths.h).

#include <itkImage.h>

#include <vector>

namespace vsim::imaging::detail {

struct VesselnessScales
{
    double minSigmaMm = 0.5, maxSigmaMm = 1.5; ///< Gaussian scales of the Hessian (mm)
    unsigned steps = 2;                         ///< number of scales from min to max
    /// Frangi's c: the scale-normalised Hessian norm (HU) at which the structure term reaches 1 - exp(-1/2).
    double gammaHu = 5.0;
};

/// Frangi et al. (MICCAI 1998) vesselness, alpha = beta = 0.5, the largest over the scales (scale-normalised
/// Hessian), one value in 0..1 per voxel of `image` (x fastest). Not rescaled.
std::vector<float> frangiVesselness(itk::Image<float, 3>* image, const VesselnessScales& scales);

} // namespace vsim::imaging::detail
