#pragma once

// The drug network in a 2D projection (thesis ch. 6 shows the filling in 2D): the tree seen from the front
// (coronal: patient left on the right, superior up) or from a C-arm position (the working angle), each segment as
// wide as its vessel and coloured by a value, and the filling's virtual tubelets (quads along each tracer's trail,
// fading from head to tail); or a DSA-like picture of the same view. Drawn with QPainter.

#include "vsim/core/VesselNetwork.h"

#include <QImage>
#include <QWidget>

#include <vector>

namespace vsim::gui {

class NetworkProjectionView : public QWidget
{
    Q_OBJECT
public:
    explicit NetworkProjectionView(QWidget* parent = nullptr);

    /// The network and one value per segment, coloured blue -> red over [low, high], grey where not a number.
    void setNetwork(const VesselNetwork& network, const std::vector<double>& values, double low, double high);
    /// Seen along the C-arm's detector direction (sim::network::detectorDirection); the front view by default.
    void setViewDirection(const Eigen::Vector3d& direction);
    /// Tracer trails (mm, head first).
    void setTrails(std::vector<std::vector<Eigen::Vector3d>> trails);
    int trailCount() const { return int(m_trails.size()); }
    /// A DSA-like picture of the same view (app::projectionPicture); shown instead of the coloured tree while
    /// `showDsa` is on, fitted to the view (the tubelets are left out then).
    void setDsaPicture(const QImage& picture);
    void setShowDsa(bool show);
    bool showsDsa() const { return m_showDsa && !m_dsa.isNull(); }

protected:
    void paintEvent(QPaintEvent* event) override;

private:
    QPointF project(const Eigen::Vector3d& pointMm) const;
    void fitBounds();

    VesselNetwork m_network;
    std::vector<double> m_values;
    double m_low = 0.0, m_high = 1.0;
    std::vector<std::vector<Eigen::Vector3d>> m_trails;
    QImage m_dsa;
    bool m_showDsa = false;
    Eigen::Vector2d m_min{0, 0}, m_max{1, 1}; // projected bounds (mm): right, up
    Eigen::Vector3d m_right = Eigen::Vector3d::UnitX(), m_up = Eigen::Vector3d::UnitZ(); // the image's axes (LPS)
};

} // namespace vsim::gui
