#pragma once

// The Drug Delivery dock: the next run's tip, tumour and control points (typed, or picked on the tree in the 3D
// view), where blood enters, the liver and tumour labels and the feeders corrected by hand; a run's key figures
// (blood, coverage, feeders, working angle, control points two-phase against liquid), its feeders and the outlets'
// shares and arrival times in tables, and the filling player: a time slider and Play, drawing the virtual tubelets
// in the 3D view and in the 2D projection.

#include "vsim/sim/network/NetworkRun.h"

#include <Eigen/Core>
#include <QString>
#include <QWidget>

#include <memory>
#include <optional>
#include <vector>

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QLineEdit;
class QPushButton;
class QTableWidget;
class QTextBrowser;

namespace vsim::viz {
class VolumeView3D;
}

namespace vsim::gui {

class NetworkProjectionView;
class RunPlayer;

/// Where the next run injects and what it looks at: the tip ("x, y, z" mm; empty: the root), the tumour sphere
/// ("x, y, z, r"; empty: none) and control points ("x, y, z; ..."; empty: the first junction's branches).
struct DrugDeliveryRequest
{
    QString tip, tumour, controls;
    QString liverLabel, tumourLabel; ///< label artifact ids for territories and coverage ("" for none)
    QString inlet; ///< the segment blood enters through: a name or number ("" : the tree's largest end)
    QString feedersAdded, feedersRemoved; ///< the user's feeder corrections: segment numbers, "3, 7"
};

/// "x, y, z[, r]" (mm) as `count` numbers; empty text gives none; nullopt for a malformed entry.
std::optional<std::vector<double>> numbersInText(const QString& text, std::size_t count);

class DrugDeliveryPanel : public QWidget
{
    Q_OBJECT
public:
    DrugDeliveryPanel(viz::VolumeView3D* view, QWidget* parent = nullptr);
    ~DrugDeliveryPanel() override;

    /// What the next click on the tree in the 3D view sets.
    enum class Pick
    {
        None,
        Tip,
        TumourCentre,
        ControlPoint,
        Feeder, ///< the shown run's segment nearest the click is added as a feeder
    };
    /// Turns picking on in the 3D view for `what` (None: off).
    void startPicking(Pick what);
    Pick picking() const { return m_pick; }
    DrugDeliveryRequest request() const;
    void setRequest(const DrugDeliveryRequest& request);
    /// "Keep this run": the next run adds to it instead of replacing it; cleared by each run.
    bool keepsRun() const;
    void clearKeep();
    /// The label artifacts (id, name) the liver and tumour may be chosen from; keeps the choices still offered.
    void setLabelChoices(const std::vector<std::pair<QString, QString>>& labels);

    /// Shows a run: the network coloured by drug flow in 3D and in the projection, the tables, the player at 0.
    void setRun(std::shared_ptr<const sim::network::NetworkRunResult> run, int fillingSteps);
    /// Moves the player to filling step `step` (0 .. the run's filling steps): tubelets in both views.
    void showStep(int step);
    double currentTimeS() const { return m_timeS; }
    QTableWidget* outletTable() const { return m_outlets; }
    /// The shown run's feeders, one a row; unchecking a row removes that feeder in the next run (checking it keeps it).
    QTableWidget* feederTable() const { return m_feeders; }
    NetworkProjectionView* projection() const { return m_projection; }
    /// The filling's player: the workstation's one time player (RunPlayer) over the run's filling steps.
    RunPlayer* player() const { return m_player; }

signals:
    /// Run pressed: the request as typed or picked.
    void runRequested(const DrugDeliveryRequest& request);

private:
    void picked(const Eigen::Vector3d& pointMm);
    void showFeeders();
    void feederToggled(int row);

    viz::VolumeView3D* m_view;
    Pick m_pick = Pick::None;
    QLineEdit *m_tip, *m_tumour, *m_controls, *m_inlet, *m_feedersAdded, *m_feedersRemoved;
    QComboBox *m_liverLabel, *m_tumourLabel;
    QCheckBox* m_keep;
    QCheckBox* m_dsa;
    QDoubleSpinBox* m_tumourRadius;
    std::shared_ptr<const sim::network::NetworkRunResult> m_run;
    QTextBrowser* m_summary;
    QTableWidget* m_outlets;
    QTableWidget* m_feeders;
    NetworkProjectionView* m_projection;
    RunPlayer* m_player;
    double m_timeS = 0.0;
};

} // namespace vsim::gui
