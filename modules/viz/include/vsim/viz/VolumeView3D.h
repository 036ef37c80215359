#pragma once

#include "vsim/core/ImageVolume.h"
#include "vsim/core/SkeletonGraph.h"
#include "vsim/core/TriangleMesh.h"
#include "vsim/viz/Callout.h"
#include "vsim/viz/VtkView.h"

#include <QColor>
#include <QString>
#include <QStringList>

#include <array>
#include <optional>

#include <string>
#include <vector>

class vtkScalarsToColors;

namespace vsim::viz {

/// The 3D view: GPU volume rendering of the CT with a CTA transfer function (contrast blood and bone opaque,
/// soft tissue and air transparent) and surfaces, placed in the LPS patient frame (mm). The camera rotates with
/// the mouse (VTK trackball); showAnteriorView() is the standard front view.
class VolumeView3D : public VtkView
{
    Q_OBJECT
public:
    explicit VolumeView3D(QWidget* parent = nullptr);
    ~VolumeView3D() override;

    /// Volume-renders `image` (the view keeps a reference to its voxels) and shows the anterior view.
    void setImage(const CtVolume& image);
    void clearImage();
    /// Adds a surface (mm, LPS) drawn in `colour`; returns nothing, surfaces stay until clearSurfaces().
    void addSurface(const TriangleMesh& surface, const QColor& colour);
    void clearSurfaces();
    /// Shows a surface coloured by its point field `field` (blue -> red over [low, high], grey where not finite) with
    /// its colour legend on the left titled `legendTitle` (units included); replaces any earlier coloured surface.
    /// Points and lines shown with it keep their own legend on the right.
    void showFieldSurface(const TriangleMesh& surface, const std::string& field, double low, double high,
                          const QString& legendTitle);
    /// Calls out places (Callout.h: the wall's peak stress and rupture index), replacing earlier callouts; cleared
    /// with the surfaces.
    void showCallouts(const std::vector<Callout>& callouts);
    std::size_t calloutCount() const;
    /// The newest legend's title (surface, lines or points), empty when none is shown.
    QString legendTitle() const;
    /// The coloured surface's legend title, empty when none is shown.
    QString surfaceLegendTitle() const;
    /// The numbers on the legend on the right (lines, points, volumes) or, with `surface`, on the left, bottom to
    /// top, in the reader's decimal mark (DecimalText.h); empty when that legend is not shown.
    QStringList legendLabels(bool surface = false) const;
    /// The lines of the title on the legend on the right or, with `surface`, on the left, as drawn; empty when that
    /// legend is not shown.
    QStringList legendTitleLines(bool surface = false) const;
    /// Whether every line of that legend's title, centred over its bar and measured by VTK's text renderer, lies
    /// within the view's width (false when the legend is not shown).
    bool legendTitleWithinView(bool surface = false) const;
    /// Opacity of the coloured surface (0..1): lowered so that particles inside show through.
    void setFieldSurfaceOpacity(double opacity);
    /// Opacity of every surface (0..1): lowered so that skeletons and centerlines inside show through.
    void setSurfaceOpacity(double opacity);
    /// Draws the edges of a skeleton or centerline graph (mm, LPS) as lines `widthPixels` wide, on top of the
    /// surfaces; they stay until clearLines().
    void addLines(const SkeletonGraph& graph, const QColor& colour, double widthPixels);
    void clearLines();
    /// Number of polylines drawn (all graphs).
    int lineCount() const;
    /// Polylines (mm, LPS) each coloured by one value (blue -> red over [low, high]) with the colour legend titled
    /// `legendTitle`; drawn as tubes when `radiiMm` gives each line's radius at its start and end (mm), else as
    /// lines `widthPixels` wide. Replaces earlier field lines.
    void showFieldLines(const std::vector<std::vector<Eigen::Vector3d>>& lines, const std::vector<double>& values,
                        double low, double high, double widthPixels, const QString& legendTitle,
                        const std::vector<std::array<double, 2>>& radiiMm = {});
    /// Points (mm, LPS: particles) each coloured by one value over [low, high], `sizePixels` wide, with the legend;
    /// they replace earlier field lines and clearFieldLines() removes them.
    void showFieldPoints(const std::vector<Eigen::Vector3d>& points, const std::vector<double>& values, double low,
                         double high, double sizePixels, const QString& legendTitle);
    void clearFieldLines();
    /// Virtual tubelets (thesis ch. 6.3, after Schirski et al.): along every trail (mm, head first), quads of
    /// `widthMm` turned to face the camera, opaque at the head and fading to clear at the tail; replaces earlier
    /// ones. Returns the number of quads drawn.
    int showTubelets(const std::vector<std::vector<Eigen::Vector3d>>& trails, double widthMm, const QColor& colour);
    int tubeletQuadCount() const;
    void setVolumeVisible(bool visible);
    /// Volume-renders a scalar field on a grid (mm, LPS: a smoke run's density) as smoke: grey-white, clear at or
    /// below `low` and denser towards `high`, with its legend on the right titled `legendTitle`; replaces an earlier
    /// field volume (the view keeps a copy of the voxels). The camera frames it when its box differs from the last
    /// one shown (a new run).
    void showFieldVolume(const RealVolume& field, double low, double high, const QString& legendTitle);
    void clearFieldVolume();
    bool hasFieldVolume() const;
    /// How the CT is drawn: rendered (CTA colours, bone and contrast opaque) or as a maximum intensity projection in
    /// grey (the habit of angiography: the opacified vessels and bone the brightest), behind a tree drawn over it.
    enum class VolumeStyle
    {
        Rendered,
        MaximumIntensity,
    };
    void setVolumeStyle(VolumeStyle style);
    VolumeStyle volumeStyle() const;
    /// Front view: the camera looks at the volume centre from anterior (-y), superior (+z) up, patient left (+x)
    /// on the screen's right; parallel projection with `heightMm` mm across the view's height (<= 0: fit the volume).
    void showAnteriorView(double heightMm = 0.0);
    /// The same front view centred on `centreMm` (e.g. a vessel tree).
    void showAnteriorView(const Eigen::Vector3d& centreMm, double heightMm);
    /// The same front view framing the box [lowMm, highMm] in the left kFramedShare of the view's width, so that the
    /// legend on the right never covers what it frames.
    void showAnteriorViewOf(const Eigen::Vector3d& lowMm, const Eigen::Vector3d& highMm);
    static constexpr double kFramedShare = 0.78;
    /// Centre of the volume in the patient frame (mm).
    Eigen::Vector3d volumeCentre() const;

    /// With dragging on, the left button grabs the shown surface (pointGrabbed), moving drags the point in the
    /// plane through it facing the camera (pointDragged) and releasing lets go (pointReleased); other buttons
    /// still turn the camera.
    void setDragEnabled(bool enabled) { m_dragEnabled = enabled; }
    /// With picking on, a left click on a surface or a tube emits pointPicked (the point, mm); the camera keeps
    /// the other buttons.
    void setPickEnabled(bool enabled) { m_pickEnabled = enabled; }
    bool isPickEnabled() const { return m_pickEnabled; }
    /// The surface point (mm) under a widget position (logical pixels), if any surface or tube is there.
    std::optional<Eigen::Vector3d> surfacePointAt(const QPointF& widgetPosition) const;
    /// The point (mm) under a widget position at the depth of `reference` (the drag plane).
    Eigen::Vector3d pointAtDepthOf(const QPointF& widgetPosition, const Eigen::Vector3d& reference) const;

signals:
    void pointGrabbed(const Eigen::Vector3d& pointMm);
    void pointDragged(const Eigen::Vector3d& pointMm);
    void pointReleased();
    void pointPicked(const Eigen::Vector3d& pointMm);

protected:
    void mousePressEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    void mouseReleaseEvent(QMouseEvent* event) override;

private:
    void showLegend(vtkScalarsToColors* table, const QString& title);
    struct Scene;
    std::unique_ptr<Scene> m_scene;
    CtVolume m_image;
    bool m_dragEnabled = false;
    bool m_pickEnabled = false;
    std::optional<Eigen::Vector3d> m_grabbed;
};

} // namespace vsim::viz
