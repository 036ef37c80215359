#pragma once

#include <Eigen/Geometry>

namespace vsim::viz {

/// The three MPR planes, displayed in the radiological convention.
enum class SliceOrientation { Axial, Coronal, Sagittal };

/// Screen axes of a plane in the LPS patient frame (unit vectors). Radiological display:
///   axial:    right = +x (patient left),  up = -y (anterior)   -> labels R | L, A on top, P below
///   coronal:  right = +x (patient left),  up = +z (superior)   -> labels R | L, S on top, I below
///   sagittal: right = -y (anterior),      up = +z (superior)   -> labels P | A, S on top, I below
struct ScreenAxes
{
    Eigen::Vector3d right;
    Eigen::Vector3d up;
    Eigen::Vector3d normal() const { return right.cross(up); }
};

/// Returns the screen axes of an orientation (see ScreenAxes).
ScreenAxes screenAxes(SliceOrientation orientation);

/// Window and level in HU.
struct WindowLevel
{
    double window = 700.0;
    double level = 200.0;
};

/// Presets (HU): contrast-enhanced CTA, soft tissue, bone, lung.
inline constexpr WindowLevel kCtaPreset{700.0, 200.0};
inline constexpr WindowLevel kSoftTissuePreset{400.0, 40.0};
inline constexpr WindowLevel kBonePreset{1800.0, 400.0};
inline constexpr WindowLevel kLungPreset{1500.0, -600.0};

/// The plane colours of the crosshair and view frames (RGB 0-1; Slicer's habit): axial red, coronal green,
/// sagittal yellow.
Eigen::Vector3d planeColour(SliceOrientation orientation);

} // namespace vsim::viz
