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

/// Which views show and where (View > Layout): 2 x 2 (axial top left, 3D top right, coronal bottom left, sagittal
/// bottom right), 1 x 1 (one view filling the area: the one chosen with setMainView, axial by default), 1 x 3 (the
/// three MPRs side by side), 3D + MPR (the 3D view large, the three MPRs stacked on its right), 3D + CPR (the 3D view
/// and the vessel view: curved reformation, cross-section and diameter plot along a centerline).
enum class LayoutMode
{
    TwoByTwo,
    OneByOne,
    OneByThree,
    VolumePlusSlices,
    VolumePlusCpr,
};

class VesselViewPanel;

/// The views of a study: three MPRs and the 3D view, arranged by LayoutMode. Linked (the
/// default) the MPRs share the cursor (a click in one moves the others' slices and crosshairs) and window/level;
/// unlinked each keeps its own.
class ViewLayout : public QWidget
{
    Q_OBJECT
public:
    explicit ViewLayout(QWidget* parent = nullptr);

    viz::SliceView* sliceView(viz::SliceOrientation orientation) const;
    viz::VolumeView3D* volumeView() const { return m_volumeView; }
    VesselViewPanel* vesselPanel() const { return m_vesselPanel; }
    /// Shows an image in all four views (or clears them when `image` is empty).
    void showImage(const CtVolume& image);
    void applyWindowLevel(const viz::WindowLevel& windowLevel);

    void setLayoutMode(LayoutMode mode);
    LayoutMode layoutMode() const { return m_mode; }
    /// The view a 1 x 1 layout shows (a slice view or the 3D view; default the axial).
    void setMainView(QWidget* view);
    QWidget* mainView() const { return m_mainView; }
    /// The view the user last clicked or focused (for capture); the axial when none yet.
    QWidget* activeView() const;

    void setLinked(bool linked) { m_linked = linked; }
    bool isLinked() const { return m_linked; }
    /// Moves every MPR's cursor to `pointMm` and centres the views that do not show it (a "go to").
    void jumpTo(const Eigen::Vector3d& pointMm);
    /// Every MPR: the volume centred and whole.
    void resetViews();
    void setSlabThickness(double thicknessMm);
    void setCrosshairShown(bool shown);
    /// Patient, study and series, drawn in the MPRs' top-left corners.
    void setPatientText(const QString& text);

private:
    std::array<viz::SliceView*, 3> m_sliceViews{};
    viz::VolumeView3D* m_volumeView = nullptr;
    VesselViewPanel* m_vesselPanel = nullptr;
    bool m_linked = true;
    LayoutMode m_mode = LayoutMode::TwoByTwo;
    QWidget* m_mainView = nullptr;

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    QWidget* m_activeView = nullptr;
};

} // namespace vsim::gui
