#pragma once

// What the views looked like when the study was saved, kept in the study (metadata "view_state", JSON) so that a
// reopened study shows what was left: which artifacts were hidden, the MPR cursor, window/level and fields of view,
// and the 3D camera. Slicer keeps the same in its scene file; here it travels inside the study bundle.

#include "vsim/viz/SliceOrientation.h"
#include "vsim/viz/VtkView.h"

#include <Eigen/Core>

#include <array>
#include <optional>
#include <set>
#include <string>

namespace vsim::gui {

struct ViewState
{
    std::set<std::string> hiddenArtifacts;
    std::optional<Eigen::Vector3d> cursorMm;
    std::optional<viz::WindowLevel> windowLevel;
    std::optional<std::array<double, 3>> sliceFieldsOfViewMm; ///< axial, coronal, sagittal
    std::optional<std::array<Eigen::Vector3d, 3>> sliceViewCentresMm; ///< axial, coronal, sagittal (pan)
    std::optional<viz::CameraState> camera3d;

    /// The state as JSON text, and back; text that is not a view state reads as an empty state.
    std::string toJson() const;
    static ViewState fromJson(const std::string& text);
};

/// The study metadata key the view state is kept under.
inline constexpr const char* kViewStateKey = "view_state";

} // namespace vsim::gui
