#include "DrugDeliveryPanel.h"

#include "TableHeaders.h"

#include "RunPlayer.h"

#include "NetworkProjectionView.h"
#include "vsim/app/ProjectionPicture.h"
#include "vsim/core/StoredText.h"
#include "vsim/core/Units.h"
#include "vsim/sim/network/NetworkBuild.h"
#include "vsim/sim/network/Tracers.h"
#include "vsim/viz/DecimalText.h"
#include "vsim/viz/VolumeView3D.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLineEdit>
#include <QPushButton>
#include <QSignalBlocker>
#include <QTableWidget>
#include <QTextBrowser>
#include <QVBoxLayout>

#include <algorithm>
#include <limits>
#include <set>

namespace vsim::gui {

std::optional<std::vector<double>> numbersInText(const QString& text, std::size_t count)
{
    std::vector<double> values;
    for (const QString& part : text.split(',', Qt::SkipEmptyParts))
    {
        bool ok = false;
        values.push_back(part.trimmed().toDouble(&ok));
        if (!ok)
            return std::nullopt;
    }
    if (!values.empty() && values.size() != count)
        return std::nullopt;
    return values;
}
namespace {

/// A figure shown (not parsed back) in the reader's decimal mark.
QString number(double value, int decimals) { return viz::decimalText(value, decimals); }

/// A branch's name in the reader's language (an anatomical name, or "unnamed (nodes a-b)").
QString branchText(const VesselNetwork& network, int segment)
{
    return QString::fromStdString(storedTextForPeople(sim::network::branchName(network, segment)));
}

/// `text` (segment numbers, "3, 7") with `segment` in it or out of it, ascending; what is not a number is dropped.
QString withSegment(const QString& text, int segment, bool in)
{
    std::set<int> segments;
    for (const QString& part : text.split(',', Qt::SkipEmptyParts))
        if (bool ok = false; part.trimmed().toInt(&ok), ok)
            segments.insert(part.trimmed().toInt());
    segments.erase(segment);
    if (in)
        segments.insert(segment);
    QStringList parts;
    for (int s : segments)
        parts << QString::number(s);
    return parts.join(", ");
}

} // namespace

DrugDeliveryPanel::DrugDeliveryPanel(viz::VolumeView3D* view, QWidget* parent)
    : QWidget(parent), m_view(view), m_summary(new QTextBrowser(this)), m_outlets(new QTableWidget(this)),
      m_projection(new NetworkProjectionView(this)), m_player(new RunPlayer(this)), m_tip(new QLineEdit(this)), m_tumour(new QLineEdit(this)), m_controls(new QLineEdit(this)),
      m_inlet(new QLineEdit(this)), m_feedersAdded(new QLineEdit(this)), m_feedersRemoved(new QLineEdit(this)),
      m_feeders(new QTableWidget(this)), m_dsa(new QCheckBox(tr("DSA-like view at the working angle"), this)),
      m_liverLabel(new QComboBox(this)), m_tumourLabel(new QComboBox(this)),
      m_keep(new QCheckBox(tr("Keep this run (the next one is added beside it)"), this)), m_tumourRadius(new QDoubleSpinBox(this))
{
    m_keep->setObjectName("drugKeep");
    m_liverLabel->setObjectName("drugLiverLabel");
    m_liverLabel->setToolTip(tr("The liver as a label: perfusion territories, coverage grade and feeders"));
    m_tumourLabel->setObjectName("drugTumourLabel");
    m_tumourLabel->setToolTip(tr("The tumour as a label (with a liver label): its lesions, margins and coverage"));
    setLabelChoices({});
    // The next run: fields to type in or pick on the tree.
    m_tip->setObjectName("drugTip");
    m_tip->setPlaceholderText(tr("x, y, z mm; empty: the root"));
    m_tumour->setObjectName("drugTumour");
    m_tumour->setPlaceholderText(tr("x, y, z, radius mm; empty: none"));
    m_controls->setObjectName("drugControls");
    m_controls->setPlaceholderText(tr("x, y, z; ... mm; empty: the first branches"));
    m_inlet->setObjectName("drugInlet");
    m_inlet->setPlaceholderText(tr("largest end; or a name, a segment number, or x, y, z mm on it"));
    m_inlet->setToolTip(tr("Blood enters through this segment; the tree beyond it is modelled"));
    m_feedersAdded->setObjectName("drugFeedersAdded");
    m_feedersAdded->setPlaceholderText(tr("segment numbers, e.g. 3, 7"));
    m_feedersRemoved->setObjectName("drugFeedersRemoved");
    m_feedersRemoved->setPlaceholderText(tr("segment numbers; or untick a feeder below"));
    m_tumourRadius->setRange(1.0, 100.0);
    m_tumourRadius->setValue(15.0);
    m_tumourRadius->setSuffix(tr(" mm"));
    auto* pickTip = new QPushButton(tr("Pick"), this);
    auto* pickTumour = new QPushButton(tr("Pick"), this);
    auto* pickControl = new QPushButton(tr("Add"), this);
    auto* pickFeeder = new QPushButton(tr("Pick"), this);
    pickFeeder->setToolTip(tr("Click a branch of the shown run in the 3D view to add it as a feeder"));
    auto* run = new QPushButton(tr("Run"), this);
    run->setObjectName("drugRun");
    auto* setup = new QFormLayout;
    auto row = [this](QLineEdit* edit, QWidget* button) {
        auto* line = new QHBoxLayout;
        line->addWidget(edit, 1);
        line->addWidget(button);
        return line;
    };
    setup->addRow(tr("Catheter tip"), row(m_tip, pickTip));
    setup->addRow(tr("Tumour"), row(m_tumour, pickTumour));
    setup->addRow(tr("Tumour radius (picked)"), m_tumourRadius);
    setup->addRow(tr("Control points"), row(m_controls, pickControl));
    setup->addRow(tr("Liver label"), m_liverLabel);
    setup->addRow(tr("Tumour label"), m_tumourLabel);
    setup->addRow(tr("Blood enters at"), m_inlet);
    setup->addRow(tr("Feeders added"), row(m_feedersAdded, pickFeeder));
    setup->addRow(tr("Feeders removed"), m_feedersRemoved);
    setup->addRow(QString(), m_keep);
    setup->addRow(QString(), run);
    connect(pickTip, &QPushButton::clicked, this, [this] { startPicking(Pick::Tip); });
    connect(pickTumour, &QPushButton::clicked, this, [this] { startPicking(Pick::TumourCentre); });
    connect(pickControl, &QPushButton::clicked, this, [this] { startPicking(Pick::ControlPoint); });
    connect(pickFeeder, &QPushButton::clicked, this, [this] { startPicking(Pick::Feeder); });
    connect(run, &QPushButton::clicked, this, [this] { emit runRequested(request()); });
    connect(m_view, &viz::VolumeView3D::pointPicked, this, &DrugDeliveryPanel::picked);

    m_summary->setObjectName("drugSummary");
    m_summary->setMaximumHeight(220);
    setColumnHeaders(m_outlets, {{tr("Outlet"), tr("The outlet's vessel (anatomical name when known)")},
                                 {tr("Drug share (%)"), tr("Share of the injected drug leaving through this outlet (%)")},
                                 {tr("Arrival (s)"), tr("Time for the drug front to reach the outlet from the catheter tip (s)")}});
    m_outlets->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_outlets->setObjectName("drugOutletTable");
    m_feeders->setObjectName("drugFeederTable");
    setColumnHeaders(m_feeders, {{tr("Feeder (tick: keep)"), tr("A branch entering the tumour or its margin; untick to remove it from the plan")},
                                 {tr("Segment"), tr("The feeder's segment number in the kept tree")},
                                 {tr("Radius (mm)"), tr("Lumen radius of the feeder (mm)")},
                                 {tr("Found"), tr("Found automatically, or added by hand")},
                                 {tr("Drug reaches it"), tr("Whether drug injected at the current tip reaches this feeder")}});
    m_feeders->setEditTriggers(QAbstractItemView::NoEditTriggers);
    connect(m_feeders, &QTableWidget::itemChanged, this, [this](QTableWidgetItem* item) {
        if (item->column() == 0)
            feederToggled(item->row());
    });
    m_dsa->setObjectName("drugDsa");
    m_dsa->setToolTip(tr("The projection as a DSA-like image (the opacified tree, the path to the tip denser)"));
    connect(m_dsa, &QCheckBox::toggled, m_projection, &NetworkProjectionView::setShowDsa);
    m_player->setObjectName("drugPlayer");
    m_player->setSpeed(4.0); // 40 filling steps a second
    auto* layout = new QVBoxLayout(this);
    layout->addLayout(setup);
    layout->addWidget(m_summary);
    layout->addWidget(m_player);
    layout->addWidget(m_dsa);
    layout->addWidget(m_projection, 2);
    layout->addWidget(m_feeders, 1);
    layout->addWidget(m_outlets, 1);
    connect(m_player, &RunPlayer::frameChanged, this, &DrugDeliveryPanel::showStep);
}

DrugDeliveryPanel::~DrugDeliveryPanel()
{
    if (m_pick != Pick::None)
        m_view->setPickEnabled(false);
}

void DrugDeliveryPanel::startPicking(Pick what)
{
    m_pick = what;
    m_view->setPickEnabled(what != Pick::None);
}

void DrugDeliveryPanel::picked(const Eigen::Vector3d& p)
{
    const QString xyz = QString("%1, %2, %3").arg(p.x(), 0, 'f', 1).arg(p.y(), 0, 'f', 1).arg(p.z(), 0, 'f', 1);
    switch (m_pick)
    {
    case Pick::Tip: m_tip->setText(xyz); break;
    case Pick::TumourCentre: m_tumour->setText(xyz + QString(", %1").arg(m_tumourRadius->value(), 0, 'f', 1)); break;
    case Pick::ControlPoint: m_controls->setText(m_controls->text().isEmpty() ? xyz : m_controls->text() + "; " + xyz); break;
    case Pick::Feeder:
        if (m_run)
            if (const int s = sim::network::nearestSegment(m_run->network, p).first; s >= 0)
            {
                m_feedersAdded->setText(withSegment(m_feedersAdded->text(), s, true));
                m_feedersRemoved->setText(withSegment(m_feedersRemoved->text(), s, false));
            }
        break;
    case Pick::None: return;
    }
    startPicking(Pick::None);
}

void DrugDeliveryPanel::showFeeders()
{
    const QSignalBlocker quiet(m_feeders);
    m_feeders->setRowCount(0);
    if (!m_run)
        return;
    m_feeders->setRowCount(int(m_run->feeders.size()));
    for (int row = 0; row < m_feeders->rowCount(); ++row)
    {
        const sim::network::Feeder& f = m_run->feeders[std::size_t(row)];
        auto* name = new QTableWidgetItem(branchText(m_run->network, f.segment));
        name->setFlags(Qt::ItemIsEnabled | Qt::ItemIsUserCheckable);
        name->setCheckState(Qt::Checked);
        name->setData(Qt::UserRole, f.segment);
        name->setData(Qt::UserRole + 1, f.byHand);
        m_feeders->setItem(row, 0, name);
        m_feeders->setItem(row, 1, new QTableWidgetItem(QString::number(f.segment)));
        m_feeders->setItem(row, 2, new QTableWidgetItem(number(f.radiusMm, 1)));
        m_feeders->setItem(row, 3, new QTableWidgetItem(f.byHand ? tr("added by hand")
                                                        : f.entersLesion ? tr("enters lesion + margin")
                                                                         : tr("feeds the lesion")));
        m_feeders->setItem(row, 4, new QTableWidgetItem(f.reached ? tr("yes") : tr("no")));
    }
}

void DrugDeliveryPanel::feederToggled(int row)
{
    const QTableWidgetItem* item = m_feeders->item(row, 0);
    const int segment = item->data(Qt::UserRole).toInt();
    const bool keep = item->checkState() == Qt::Checked;
    if (item->data(Qt::UserRole + 1).toBool()) // added by hand: unticked, it is no longer added
        m_feedersAdded->setText(withSegment(m_feedersAdded->text(), segment, keep));
    else
        m_feedersRemoved->setText(withSegment(m_feedersRemoved->text(), segment, !keep));
}

DrugDeliveryRequest DrugDeliveryPanel::request() const
{
    return {m_tip->text(),          m_tumour->text(),       m_controls->text(),
            m_liverLabel->currentData().toString(), m_tumourLabel->currentData().toString(),
            m_inlet->text().trimmed(), m_feedersAdded->text().trimmed(), m_feedersRemoved->text().trimmed()};
}

void DrugDeliveryPanel::setRequest(const DrugDeliveryRequest& request)
{
    m_tip->setText(request.tip);
    m_tumour->setText(request.tumour);
    m_controls->setText(request.controls);
    m_inlet->setText(request.inlet);
    m_feedersAdded->setText(request.feedersAdded);
    m_feedersRemoved->setText(request.feedersRemoved);
    m_liverLabel->setCurrentIndex(std::max(0, m_liverLabel->findData(request.liverLabel)));
    m_tumourLabel->setCurrentIndex(std::max(0, m_tumourLabel->findData(request.tumourLabel)));
}

bool DrugDeliveryPanel::keepsRun() const { return m_keep->isChecked(); }

void DrugDeliveryPanel::clearKeep() { m_keep->setChecked(false); }

void DrugDeliveryPanel::setLabelChoices(const std::vector<std::pair<QString, QString>>& labels)
{
    for (QComboBox* box : {m_liverLabel, m_tumourLabel})
    {
        const QString chosen = box->currentData().toString();
        box->clear();
        box->addItem(tr("(none)"), QString());
        for (const auto& [id, name] : labels)
            box->addItem(QString("%1 (%2)").arg(name, id), id);
        box->setCurrentIndex(std::max(0, box->findData(chosen)));
    }
}

void DrugDeliveryPanel::setRun(std::shared_ptr<const sim::network::NetworkRunResult> run, int fillingSteps)
{
    m_run = std::move(run);
    const sim::network::NetworkRunResult& r = *m_run;
    const auto& m = r.metrics;
    QString text = tr("Tip pressure %1 mmHg; last outlet reached after %2 s.")
                       .arg(number(m.at("tip_pressure_mmhg"), 1), number(m.at("last_arrival_s"), 1));
    for (const sim::network::ControlPoint& c : r.controls)
        text += tr("<br>Control point %1: drug %2 ml/min two-phase, %3 ml/min liquid (%4 % lower)")
                    .arg(QString::fromStdString(c.name), number(c.drugFlowTwoPhaseMlMin, 3), number(c.drugFlowLiquidMlMin, 3),
                         number(c.dropPercent, 1));
    if (r.blood)
        text += tr("<br>Blood: %1 ml/min at the root, %2 ml/min reaching the tip (own flow %3); the drug is %4 % of the "
                   "flow below it; the catheter fills %5 % of the lumen%6.")
                    .arg(number(units::m3PerSToMlPerMin(r.blood->inletFlow), 1), number(units::m3PerSToMlPerMin(r.blood->tipInflow), 1),
                         number(units::m3PerSToMlPerMin(r.blood->ownFlow), 1), number(m.at("tip_drug_percent"), 2),
                         number(100.0 * r.blood->occlusion, 0), r.blood->wedged ? tr(": WEDGED") : QString());
    if (r.coverage && !r.lesions.empty())
    {
        const char grade = r.coverage->grade;
        text += tr("<br><b>Coverage grade %1</b>: territory %2 ml (%3 ml of tumour); drug to tumour %4 %, non-tumour "
                   "liver %5 %, extrahepatic %6 %.")
                    .arg(QChar(grade))
                    .arg(number(r.perfused->volumeMl, 1), number(r.perfused->tumourVolumeMl, 1),
                         number(100.0 * r.perfused->drugToTumour, 1), number(100.0 * r.perfused->drugToLiver, 1),
                         number(100.0 * r.perfused->drugExtrahepatic, 1));
        for (std::size_t l = 0; l < r.lesions.size() && l < sim::network::kLesionsReported; ++l)
            text += tr("<br>Lesion %1: %2 mm, %3 mm margin; %4 % covered, margin %5 % (grade %6).")
                        .arg(l + 1)
                        .arg(number(r.lesions[l].diameterMm, 1), number(r.lesions[l].marginMm, 0),
                             number(r.coverage->lesions[l].coveredPercent, 1),
                             number(r.coverage->lesions[l].marginCoveredPercent, 1))
                        .arg(QChar(r.coverage->lesions[l].grade));
        QStringList feeders;
        for (const sim::network::Feeder& f : r.feeders)
            feeders << tr("%1 (segment %2, %3 mm)")
                           .arg(branchText(r.network, f.segment).toHtmlEscaped())
                           .arg(f.segment)
                           .arg(number(f.radiusMm, 1));
        text += tr("<br>Feeders: %1.").arg(feeders.isEmpty() ? tr("none found") : feeders.join("; "));
        QStringList nonTarget;
        const std::vector<std::vector<int>> incident = r.network.incidentSegments();
        for (const auto& [node, share] : r.perfused->extrahepaticDrug)
            if (share >= sim::network::kPerfusedShare)
                nonTarget << tr("%1 %2 %")
                                 .arg(branchText(r.network, incident[std::size_t(node)].front()).toHtmlEscaped())
                                 .arg(number(100.0 * share, 1));
        if (!nonTarget.isEmpty())
            text += tr("<br>Drug leaving the liver: %1.").arg(nonTarget.join("; "));
    }
    else if (m.count("tumour_fraction"))
        text += tr("<br>Tumour share %1 % (%2 outlets).").arg(number(100.0 * m.at("tumour_fraction"), 1)).arg(r.tumourOutlets.size());
    if (m.count("best_tip_node"))
        text += tr("<br>Best tip: node %1 delivers %2 % to the tumour.")
                    .arg(int(m.at("best_tip_node")))
                    .arg(number(100.0 * m.at("best_tip_fraction"), 1));
    if (r.workingAngle)
    {
        const sim::network::WorkingAngle& w = *r.workingAngle;
        text += tr("<br><b>Working angle %1 %2, %3 %4</b> (the projection below): the path foreshortened %5 %, "
                   "overlapped %6 % (from the front: %7 %, %8 %).")
                    .arg(w.angles.laoDeg >= 0.0 ? tr("LAO") : tr("RAO"))
                    .arg(number(std::abs(w.angles.laoDeg), 1))
                    .arg(w.angles.cranialDeg >= 0.0 ? tr("cranial") : tr("caudal"))
                    .arg(number(std::abs(w.angles.cranialDeg), 1))
                    .arg(number(100.0 * w.quality.foreshortening, 1), number(100.0 * w.quality.overlap, 1),
                         number(100.0 * w.frontal.foreshortening, 1), number(100.0 * w.frontal.overlap, 1));
    }
    for (const std::string& warning : r.warnings)
        text += "<br><i>" + QString::fromStdString(storedTextForPeople(warning)).toHtmlEscaped() + "</i>";
    m_summary->setHtml(text);

    showFeeders();
    m_outlets->setRowCount(int(r.twoPhase.outletFlow.size()));
    int row = 0;
    for (const auto& [node, flow] : r.twoPhase.outletFlow)
    {
        const double arrival = sim::network::arrivalAt(r.filling, node);
        m_outlets->setItem(row, 0, new QTableWidgetItem(QString::number(node)));
        m_outlets->setItem(row, 1, new QTableWidgetItem(number(100.0 * sim::network::deliveredFraction(r.twoPhase, {node}), 2)));
        m_outlets->setItem(row, 2, new QTableWidgetItem(arrival == sim::network::kNever ? tr("never") : number(arrival, 1)));
        ++row;
    }
    // The tree coloured by drug flow, in 3D (with the legend) and in the projection.
    std::vector<std::vector<Eigen::Vector3d>> lines;
    std::vector<double> values;
    std::vector<std::array<double, 2>> radii;
    const std::vector<double>& drug = r.network.segmentFields.at("drug_flow_ml_min");
    double high = 0.0;
    for (std::size_t s = 0; s < r.network.segments.size(); ++s) // grey (not a number): no drug, apart from little
    {
        const auto& segment = r.network.segments[s];
        lines.push_back(r.network.segmentPath(s));
        const bool carries = r.twoPhase.orientation.active(int(s)) && drug[s] > 0.0;
        values.push_back(carries ? drug[s] : std::numeric_limits<double>::quiet_NaN());
        radii.push_back({segment.startRadiusMm, segment.endRadiusMm});
        high = std::max(high, carries ? drug[s] : 0.0);
    }
    high = high > 0.0 ? high : 1.0;
    m_view->clearSurfaces(); // the tree coloured by drug flow over the CT's maximum intensity projection
    m_view->clearLines();
    m_view->setVolumeStyle(viz::VolumeView3D::VolumeStyle::MaximumIntensity);
    m_view->setVolumeVisible(true);
    m_view->showFieldLines(lines, values, 0.0, high, 5.0, tr("Drug flow (ml/min; grey: none)"), radii);
    Eigen::Vector3d low = Eigen::Vector3d::Constant(1e300), top = Eigen::Vector3d::Constant(-1e300);
    for (const auto& line : lines)
        for (const Eigen::Vector3d& p : line)
            low = low.cwiseMin(p), top = top.cwiseMax(p);
    if (!lines.empty()) // frame the tree from the front, left of the legend
        m_view->showAnteriorViewOf(low, top);
    m_projection->setNetwork(r.network, values, 0.0, high);
    const sim::network::CArmAngles angles = r.workingAngle ? r.workingAngle->angles : sim::network::CArmAngles{};
    m_projection->setViewDirection(sim::network::detectorDirection(angles));
    m_projection->setDsaPicture(r.workingAngle ? app::projectionPicture(sim::network::dsaProjection(r.network, r.tipNode, angles))
                                               : QImage());
    m_dsa->setEnabled(r.workingAngle.has_value());
    const int steps = std::max(1, fillingSteps);
    std::vector<double> times;
    for (int step = 0; step <= steps; ++step)
        times.push_back(r.filling.lastArrival * double(step) / double(steps));
    m_player->setFrames(times, tr("time"), tr("s"), {}); // shows step 0; no field to choose: the tracers' tubelets
}

void DrugDeliveryPanel::showStep(int step)
{
    if (!m_run)
        return;
    const double last = m_run->filling.lastArrival;
    m_timeS = last * double(step) / double(std::max(1, m_player->frameCount() - 1));
    // About 200 tracers over the filling, trails a fortieth of it long.
    sim::network::TracerSettings tracers;
    tracers.releaseEveryS = std::max(1e-3, last / 200.0);
    tracers.trailSpacingS = std::max(1e-3, last / 320.0);
    const auto trails = sim::network::tracerTrails(m_run->network, m_run->twoPhase, m_timeS, tracers);
    m_view->showTubelets(trails, 1.2, QColor(255, 235, 90));
    m_projection->setTrails(trails);
}

} // namespace vsim::gui
