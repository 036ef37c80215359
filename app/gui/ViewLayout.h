#pragma once

#include "vsim/core/ImageVolume.h"
#include "vsim/viz/SliceOrientation.h"

#include <QWidget>

#include <array>

namespace vsim::viz {
class SliceView;
class VolumeView3D;
} // namespace vsim::viz

namespace vsim::gui {

/// The three MPR views' orientations, in the layout's order.
inline constexpr std::array<viz::SliceOrientation, 3> kOrientations{viz::SliceOrientation::Axial, viz::SliceOrientation::Coronal,
                                                                   viz::SliceOrientation::Sagittal};

/// The 4-up layout: axial (top left), 3D (top right), coronal (bottom left), sagittal (bottom right), with a
/// linked cursor (clicking in one MPR moves the others) and shared window/level.
class ViewLayout : public QWidget
{
    Q_OBJECT
public:
    explicit ViewLayout(QWidget* parent = nullptr);

    viz::SliceView* sliceView(viz::SliceOrientation orientation) const;
    viz::VolumeView3D* volumeView() const { return m_volumeView; }
    /// Shows an image in all four views (or clears them when `image` is empty).
    void showImage(const CtVolume& image);
    void applyWindowLevel(const viz::WindowLevel& windowLevel);

private:
    std::array<viz::SliceView*, 3> m_sliceViews{};
    viz::VolumeView3D* m_volumeView = nullptr;
};

} // namespace vsim::gui
