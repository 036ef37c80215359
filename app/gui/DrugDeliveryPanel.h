#pragma once

// The Drug Delivery dock: a run's key figures (tip pressure, tumour share, best tip, control points two-phase
// against liquid), the outlets' shares and arrival times in a table, and the filling player: a time slider and
// Play, drawing the virtual tubelets in the 3D view and in the 2D projection beside the table.

#include "vsim/sim/network/NetworkRun.h"

#include <QWidget>

#include <memory>

class QLabel;
class QPushButton;
class QSlider;
class QTableWidget;
class QTextBrowser;
class QTimer;

namespace vsim::viz {
class VolumeView3D;
}

namespace vsim::gui {

class NetworkProjectionView;

class DrugDeliveryPanel : public QWidget
{
    Q_OBJECT
public:
    DrugDeliveryPanel(viz::VolumeView3D* view, QWidget* parent = nullptr);
    ~DrugDeliveryPanel() override;

    /// Shows a run: the network coloured by drug flow in 3D and in the projection, the tables, the player at 0.
    void setRun(std::shared_ptr<const sim::network::NetworkRunResult> run, int fillingSteps);
    /// Moves the player to filling step `step` (0 .. the run's filling steps): tubelets in both views.
    void showStep(int step);
    double currentTimeS() const { return m_timeS; }
    QTableWidget* outletTable() const { return m_outlets; }
    NetworkProjectionView* projection() const { return m_projection; }
    QSlider* timeSlider() const { return m_slider; }
    QPushButton* playButton() const { return m_play; }

private:
    viz::VolumeView3D* m_view;
    std::shared_ptr<const sim::network::NetworkRunResult> m_run;
    QTextBrowser* m_summary;
    QTableWidget* m_outlets;
    NetworkProjectionView* m_projection;
    QSlider* m_slider;
    QPushButton* m_play;
    QLabel* m_time;
    QTimer* m_timer;
    double m_timeS = 0.0;
};

} // namespace vsim::gui
