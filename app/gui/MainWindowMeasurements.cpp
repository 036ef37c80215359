// Measurement tools (Measure menu and toolbar): a ruler, an angle or an elliptical ROI drawn on any slice view
// becomes a measurement artifact of the study (undoable, listed in the study tree with its figure and unit, hidden
// with its tick box, saved with the study), drawn in the views whose slice holds it; marked "in report", it is
// listed in the report's measurements section.
#include "ArtifactCommands.h"
#include "MainWindow.h"
#include "ViewLayout.h"
#include "vsim/imaging/ViewMeasurements.h"
#include "vsim/viz/SliceView.h"
#include "vsim/core/StoredText.h"

#include <QActionGroup>
#include <QMenuBar>
#include <QStatusBar>
#include <QToolBar>
#include <QTreeWidget>

namespace vsim::gui {
namespace {

QString kindTitle(ViewMeasurement::Kind kind)
{
    switch (kind)
    {
    case ViewMeasurement::Kind::Ruler: return MainWindow::tr("Ruler");
    case ViewMeasurement::Kind::Angle: return MainWindow::tr("Angle");
    case ViewMeasurement::Kind::Roi: return MainWindow::tr("ROI");
    }
    return {};
}

} // namespace

void MainWindow::createMeasureMenu()
{
    QMenu* menu = menuBar()->addMenu(tr("&Measure"));
    QToolBar* bar = addToolBar(tr("Measure"));
    bar->setObjectName("measureToolBar");
    auto* tools = new QActionGroup(this);
    tools->setExclusionPolicy(QActionGroup::ExclusionPolicy::ExclusiveOptional); // a second click puts it down
    const std::tuple<viz::MeasureTool, QString, QString, QString> entries[] = {
        {viz::MeasureTool::Ruler, tr("&Ruler"), "measureRulerAction", tr("Distance (mm): press at one end in a slice view, drag to the other, release")},
        {viz::MeasureTool::Angle, tr("&Angle"), "measureAngleAction", tr("Angle (degrees): click the first arm's end, the vertex, then the second arm's end")},
        {viz::MeasureTool::Roi, tr("Elliptical R&OI"), "measureRoiAction", tr("HU mean, SD and area (mm2) inside an ellipse: press at a corner of its box, drag, release")},
    };
    for (const auto& [tool, title, name, tip] : entries)
    {
        QAction* action = menu->addAction(title);
        action->setObjectName(name);
        action->setCheckable(true);
        action->setToolTip(tip + tr(" (Escape drops a drawing; the tool stays until clicked again)"));
        action->setStatusTip(tip);
        tools->addAction(action);
        bar->addAction(action);
        m_documentActions << action;
        connect(action, &QAction::toggled, this, [this, tool = tool](bool on) {
            for (viz::SliceOrientation orientation : kOrientations)
                m_views->sliceView(orientation)->setMeasureTool(on ? tool : viz::MeasureTool::Off);
        });
    }
    menu->addSeparator();
    m_measurementInReport = menu->addAction(tr("&Include the Selected Measurement in the Report"));
    m_measurementInReport->setObjectName("measurementInReportAction");
    m_measurementInReport->setCheckable(true);
    m_measurementInReport->setEnabled(false);
    connect(m_measurementInReport, &QAction::triggered, this, [this](bool on) {
        QTreeWidgetItem* item = m_artifactTree->currentItem();
        if (item && m_document.hasStudy())
            setMeasurementInReport(item->data(0, Qt::UserRole).toString().toStdString(), on);
    });
    connect(m_artifactTree, &QTreeWidget::currentItemChanged, this, [this](QTreeWidgetItem* item) {
        const std::string id = item ? item->data(0, Qt::UserRole).toString().toStdString() : std::string();
        const bool measurement = m_document.hasStudy() && m_document.study().hasArtifact(id) &&
                                 m_document.study().artifact(id).kind == study::ArtifactKind::Measurement;
        m_measurementInReport->setEnabled(measurement);
        const QSignalBlocker quiet(m_measurementInReport);
        m_measurementInReport->setChecked(measurement && m_document.study().artifact(id).attributes.count("in_report") &&
                                          m_document.study().artifact(id).attributes.at("in_report") == "1");
    });
    for (viz::SliceOrientation orientation : kOrientations)
        connect(m_views->sliceView(orientation), &viz::SliceView::measurementDrawn, this,
                [this](const ViewMeasurement& drawn) { addMeasurement(drawn); });
}

std::string MainWindow::addMeasurement(const ViewMeasurement& drawn)
{
    const std::string imageId = newestArtifact(study::ArtifactKind::Image);
    const viz::SliceView* axial = m_views->sliceView(viz::SliceOrientation::Axial);
    if (!m_document.hasStudy() || imageId.empty() || !axial->hasImage() || m_tasks.isBusy())
        return {};
    try
    {
        ViewMeasurement measured = drawn;
        imaging::measure(measured, axial->image());
        int number = 1;
        for (const study::Artifact& a : m_document.study().artifacts())
            if (a.kind == study::ArtifactKind::Measurement && a.provenance.parameters.count("kind") &&
                a.provenance.parameters.at("kind") == kindName(drawn.kind))
                ++number;
        // Kept in English like every name VascuSim gives (core StoredText.h), shown in the reader's language.
        const std::vector<std::string> values{std::to_string(number), measurementText(measured)};
        const std::string name = drawn.kind == ViewMeasurement::Kind::Ruler   ? storedText(Pattern{"Ruler %1: %2", values})
                                 : drawn.kind == ViewMeasurement::Kind::Angle ? storedText(Pattern{"Angle %1: %2", values})
                                                                              : storedText(Pattern{"ROI %1: %2", values});
        study::Provenance provenance;
        provenance.command = "measure";
        provenance.inputs = {imageId};
        provenance.parameters = {{"kind", kindName(drawn.kind)}, {"definition", measurementDefinition(drawn.kind)}};
        const std::string id = m_document.study().addMeasurement(measured, name, provenance);
        m_document.undoStack()->push(new AddedArtifactCommand(m_document, id, tr("Measure %1").arg(kindTitle(drawn.kind))));
        statusBar()->showMessage(QString::fromStdString(storedTextForPeople(name)), 8000);
        return id;
    }
    catch (const std::exception& error)
    {
        showError(tr("Measure"), QString::fromStdString(textForPeople(error)));
        return {};
    }
}

void MainWindow::setMeasurementInReport(const std::string& id, bool inReport)
{
    const study::Artifact& artifact = m_document.study().artifact(id);
    m_document.undoStack()->push(new SetArtifactAttributeCommand(
        m_document, id, "in_report", inReport ? "1" : "0",
        (inReport ? tr("Include \"%1\" in the report") : tr("Leave \"%1\" out of the report")).arg(QString::fromStdString(storedTextForPeople(artifact.name)))));
}

void MainWindow::refreshViewMeasurements()
{
    std::vector<viz::ShownMeasurement> shown;
    if (m_document.hasStudy())
        for (const study::Artifact& a : m_document.study().artifacts())
            if (a.kind == study::ArtifactKind::Measurement && !a.damaged && !m_hiddenArtifacts.count(a.id))
                shown.push_back({m_document.study().loadMeasurement(a.id), storedTextForPeople(a.name)});
    for (viz::SliceOrientation orientation : kOrientations)
        m_views->sliceView(orientation)->setMeasurements(shown);
}

} // namespace vsim::gui
