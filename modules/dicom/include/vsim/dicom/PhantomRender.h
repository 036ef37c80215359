#pragma once

#include "vsim/core/ImageVolume.h"
#include "vsim/core/Progress.h"
#include "vsim/dicom/PhantomModel.h"
#include "vsim/dicom/SliceStack.h"

namespace vsim::dicom {

/// Renders the phantom's CT on the planes of `stack`: tissues painted in order, then the vessels, each boundary
/// blurred by a Gaussian of sigma options.effectiveBlurMm() (partial volume: the occupancy of a voxel is
/// Phi(-d / sigma) with d the signed distance to the surface), plus Gaussian noise of options.noiseHu seeded per
/// slice from options.seed (the same on any thread count), rounded and clamped to -1024..3071 HU.
/// The volume's geometry is stack.nominalGeometry(); pixels are in stack order. Throws vsim::Cancelled.
CtVolume renderPhantomCt(const PhantomModel& model, const SliceStack& stack, const PhantomOptions& options,
                         const Progress& progress = {});

/// The truth labels on a volume grid, decided at voxel centres: label::kVesselLumen inside a vessel, else the
/// label of the last tissue shape containing the voxel (tumour, bone), else 0.
LabelVolume renderPhantomLabels(const PhantomModel& model, const VolumeGeometry& geometry,
                                const Progress& progress = {});

/// Signed distance (mm) from `p` to the model's vessel lumen surface (negative inside): the ground truth for
/// surfaces and centerlines extracted from the phantom. Brute force over every cone piece.
double vesselSurfaceDistance(const PhantomModel& model, const Eigen::Vector3d& p);

} // namespace vsim::dicom
