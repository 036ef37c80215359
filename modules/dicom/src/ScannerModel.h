#pragma once

// The scanner half of the patient-like phantoms: the point-spread function and CT-like correlated noise applied
// to an ideal (sub-voxel averaged) HU volume. Separate from the anatomy so that each can be tested alone.

#include "vsim/core/Progress.h"

#include <array>
#include <cstdint>
#include <vector>

namespace vsim::dicom::detail {

/// A float volume, columns fastest.
struct FloatVolume
{
    std::array<int, 3> dims{0, 0, 0};
    std::vector<float> values;
    std::size_t pixelsPerSlice() const { return std::size_t(dims[0]) * std::size_t(dims[1]); }
};

/// The normalised sampled Gaussian of standard deviation `sigma` (voxels), taps out to 3 sigma (at least 1).
std::vector<float> gaussianKernel(double sigmaVoxels);

/// Convolves `volume` along `axis` (0, 1, 2) with a Gaussian of `sigmaVoxels`, edges clamped; no-op for sigma 0.
void blurAlongAxis(FloatVolume& volume, int axis, double sigmaVoxels, const Progress& progress = {});

/// Adds noise of standard deviation `noiseHu` with a CT-like in-plane noise power spectrum to slice `slice`:
/// white Gaussian noise (seeded by seed and slice: the same on any thread count) filtered by the difference of
/// two Gaussians of `grainVoxels` and 3 x `grainVoxels` (zero power at zero frequency, a mid-frequency peak, as
/// filtered back-projection gives), scaled by the filter's exact norm.
void addCorrelatedNoise(float* slice, int columns, int rows, double noiseHu, double grainVoxels, std::uint64_t seed,
                        std::uint64_t sliceIndex);

} // namespace vsim::dicom::detail
