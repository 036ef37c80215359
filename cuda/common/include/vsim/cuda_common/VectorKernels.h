#pragma once

#include <vector>

namespace vsim::cuda {

/// Returns a * x + y computed on the GPU (double precision); throws vsim::Error when the sizes differ or a
/// CUDA call fails (e.g. no device).
std::vector<double> scaledSum(double a, const std::vector<double>& x, const std::vector<double>& y);

} // namespace vsim::cuda
