// The vessel steps of the workflow: segmentation, skeleton and centerlines, run in the task runner with the
// parameters of Vessels > Parameters and added to the study as undoable artifacts; the measurement dock.

#include "ArtifactCommands.h"
#include "MainWindow.h"
#include "ParameterForm.h"
#include "StudyDocument.h"
#include "TableHeaders.h"
#include "ViewLayout.h"
#include "vsim/app/SacRecord.h"
#include "vsim/app/SegmentNames.h"
#include "vsim/imaging/AneurysmSac.h"
#include "vsim/imaging/Centerlines.h"
#include "vsim/imaging/Skeletonization.h"
#include "vsim/imaging/VesselMeasurements.h"
#include "vsim/imaging/VesselSegmentation.h"
#include "vsim/mesh/VesselSurface.h"
#include "vsim/viz/DecimalText.h"
#include "vsim/viz/SliceView.h"
#include "vsim/viz/VolumeView3D.h"
#include "vsim/core/StoredText.h"

#include <QDockWidget>
#include <QInputDialog>
#include <QHeaderView>
#include <QMenu>
#include <QMenuBar>
#include <QTableWidget>

#include <QVector3D>

#include <algorithm>

namespace vsim::gui {
namespace {

constexpr int kPositionRole = Qt::UserRole + 1;
constexpr int kSegmentRole = Qt::UserRole + 2; // the segment's index, on the rows of segments

QTableWidgetItem* number(double value, int decimals)
{
    auto* item = new QTableWidgetItem(viz::decimalText(value, decimals));
    item->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
    return item;
}

/// The section where a row should take the cursor: the narrowest valid one, or the widest for the maximum row.
const imaging::CrossSection* sectionOf(const imaging::SegmentMeasurements& segment, bool widest)
{
    const imaging::CrossSection* chosen = nullptr;
    for (const imaging::CrossSection& section : segment.sections)
        if (!section.nearJunction && section.areaMm2 > 0 &&
            (!chosen || (widest ? section.equivalentDiameterMm > chosen->equivalentDiameterMm
                                : section.equivalentDiameterMm < chosen->equivalentDiameterMm)))
            chosen = &section;
    return chosen;
}

} // namespace

void MainWindow::createMeasurementDock()
{
    m_measurementTable = new QTableWidget(0, 8, this);
    m_measurementTable->setObjectName("measurementTable");
    setColumnHeaders(m_measurementTable,
                     {{tr("Segment", "a vessel segment (noun)"), tr("The segment's anatomical name (double-click to rename) or its end nodes")},
                      {tr("Length (mm)"), tr("Length along the centerline (mm)")},
                      {tr("Start r (mm)"), tr("Lumen radius at the segment's start (mm)")},
                      {tr("End r (mm)"), tr("Lumen radius at the segment's end (mm)")},
                      {tr("Reference \u00d8 (mm)"), tr("Reference lumen diameter: the median equivalent diameter of the segment's sections (mm)")},
                      {tr("Minimal \u00d8 (mm)"), tr("Minimal lumen diameter (equivalent) along the segment, in sections perpendicular to the centerline (mm)")},
                      {tr("Stenosis (%)"), tr("Diameter stenosis: 100 (1 - minimal / reference diameter) (%)")},
                      {tr("Max \u00d8 (mm)"), tr("Largest lumen caliper width along the segment (mm); the AAA diameter outer wall to outer wall (SVS) is the sac's row")}});
    m_measurementTable->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_measurementTable->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_measurementTable->verticalHeader()->hide();
    connect(m_measurementTable, &QTableWidget::cellDoubleClicked, this, [this](int row, int column) {
        const QVariant segment = m_measurementTable->item(row, 0)->data(kSegmentRole);
        if (column != 0 || !segment.isValid() || m_measuredCenterlines.empty() || m_tasks.isBusy())
            return;
        bool ok = false;
        const QString name = QInputDialog::getText(this, tr("Name Segment"), tr("Anatomical name of the segment:"),
                                                   QLineEdit::Normal, m_measurementTable->item(row, 0)->text(), &ok)
                                 .trimmed();
        if (ok && !name.isEmpty())
            m_document.undoStack()->push(new RenameSegmentCommand(m_document, m_measuredCenterlines,
                                                                  std::size_t(segment.toULongLong()), name.toStdString()));
    });
    connect(m_measurementTable, &QTableWidget::cellClicked, this, [this](int row, int) {
        const QVariant position = m_measurementTable->item(row, 0)->data(kPositionRole);
        if (position.isValid())
        {
            const QVector3D p = position.value<QVector3D>();
            m_views->jumpTo(Eigen::Vector3d(p.x(), p.y(), p.z()));
        }
    });
    auto* dock = new QDockWidget(tr("Measurements"), this);
    dock->setObjectName("measurementDock");
    dock->setWidget(m_measurementTable);
    addDockWidget(Qt::BottomDockWidgetArea, dock);
}

void MainWindow::showMeasurements(const imaging::VesselMeasurements& measurements, const std::vector<std::string>& names,
                                  const std::string& centerlinesId)
{
    m_measuredCenterlines = centerlinesId;
    m_measurementTable->setRowCount(0);
    auto addRow = [&](const QString& name, const imaging::SegmentMeasurements& s, const imaging::CrossSection* jump,
                      int segment) {
        const int row = m_measurementTable->rowCount();
        m_measurementTable->insertRow(row);
        auto* label = new QTableWidgetItem(name);
        if (segment >= 0)
        {
            label->setData(kSegmentRole, segment);
            label->setToolTip(tr("Segment %1 (nodes %2-%3); double-click to rename").arg(segment).arg(s.from).arg(s.to));
        }
        if (jump)
            label->setData(kPositionRole, QVector3D(float(jump->centre.x()), float(jump->centre.y()), float(jump->centre.z())));
        m_measurementTable->setItem(row, 0, label);
        m_measurementTable->setItem(row, 1, number(s.lengthMm, 1));
        m_measurementTable->setItem(row, 2, number(s.startRadiusMm, 2));
        m_measurementTable->setItem(row, 3, number(s.endRadiusMm, 2));
        m_measurementTable->setItem(row, 4, number(s.referenceDiameterMm, 2));
        m_measurementTable->setItem(row, 5, number(s.minimalDiameterMm, 2));
        m_measurementTable->setItem(row, 6, number(s.diameterStenosisPercent, 1));
        m_measurementTable->setItem(row, 7, number(s.maxDiameterMm, 2));
    };
    // First the sac's figures (when the study has one), each with its definition as the tooltip; the maximum outer
    // diameter's row takes the cursor to its section.
    const std::map<std::string, double> sac = app::newestSacFigures(m_document.study());
    const std::pair<const char*, QString> sacRows[] = {
        {"max_outer_diameter_mm", tr("AAA maximum diameter, outer wall to outer wall (SVS): %1 mm")},
        {"lumen_diameter_at_max_mm", tr("Lumen diameter there (equivalent): %1 mm")},
        {"max_thrombus_thickness_mm", tr("Largest thrombus thickness: %1 mm")},
        {"sac_volume_ml", tr("Sac volume: %1 ml")},
        {"neck_diameter_mm", tr("Neck diameter (outer, at the lowest renal artery): %1 mm")},
        {"neck_length_mm", tr("Neck length: %1 mm")},
        {"neck_angulation_deg", tr("Neck angulation: %1 degrees")},
        {"right_common_iliac_diameter_mm", tr("Right common iliac diameter (outer): %1 mm")},
        {"left_common_iliac_diameter_mm", tr("Left common iliac diameter (outer): %1 mm")},
        {"wall_thickness_mm", tr("Wall thickness (assumed): %1 mm")}};
    for (const auto& [key, format] : sacRows)
    {
        const auto value = sac.find(key);
        if (value == sac.end())
            continue;
        const int row = m_measurementTable->rowCount();
        m_measurementTable->insertRow(row);
        auto* item = new QTableWidgetItem(format.arg(viz::decimalText(value->second, 1)));
        const auto definitions = imaging::aneurysmSacDefinitions(true);
        if (const auto definition = definitions.find(key); definition != definitions.end())
            item->setToolTip(QString::fromStdString(definition->second));
        if (std::string(key) == "max_outer_diameter_mm" && sac.count("max_outer_diameter_z_mm"))
            item->setData(kPositionRole, QVector3D(float(sac.at("max_outer_diameter_x_mm")),
                                                   float(sac.at("max_outer_diameter_y_mm")),
                                                   float(sac.at("max_outer_diameter_z_mm"))));
        m_measurementTable->setItem(row, 0, item);
    }
    // Then the segment holding the maximum lumen diameter, jumping to its widest section.
    const auto widest = std::max_element(measurements.segments.begin(), measurements.segments.end(),
                                         [](const auto& a, const auto& b) { return a.maxDiameterMm < b.maxDiameterMm; });
    if (widest != measurements.segments.end())
        addRow(tr("Maximum lumen diameter %1 mm (equivalent, perpendicular)")
            .arg(viz::decimalText(measurements.maxDiameterMm, 1)),
               *widest, sectionOf(*widest, true), -1);
    for (std::size_t index = 0; index < measurements.segments.size(); ++index)
    {
        const imaging::SegmentMeasurements& s = measurements.segments[index];
        addRow(QString::fromStdString(app::segmentTitle(index < names.size() ? names[index] : "unnamed", s.from, s.to)),
               s, sectionOf(s, false), int(index));
    }
    m_measurementTable->resizeColumnsToContents();
}

void MainWindow::createVesselMenu()
{
    // The parameters the vessel steps run with start at the declared defaults.
    m_segmentationParameters = ParameterSet(imaging::segmentationParameters());
    m_guidedParameters = ParameterSet(imaging::guidedSegmentationParameters());
    m_skeletonParameters = ParameterSet(imaging::skeletonParameters());
    m_centerlineParameters = ParameterSet(imaging::centerlineParameters());
    createLabelEditToolBar();

    QMenu* vessels = menuBar()->addMenu(tr("V&essels"));
    // The guided segmentation (target aorta / hepatic / all from include and exclude points) in its dock.
    m_documentActions << vessels->addAction(tr("Segment from &Points..."), this, [this] { showSegmentationPoints(); });
    m_documentActions << vessels->addAction(tr("&Segment Vessels"), this, [this] { segmentVessels(); });
    // Click a vessel in any MPR view (the linked cursor goes there), then segment from that seed.
    m_documentActions << vessels->addAction(tr("Segment from the &Cursor"), this, [this] {
        segmentVessels(m_views->sliceView(viz::SliceOrientation::Axial)->cursor());
    });
    m_documentActions << vessels->addAction(tr("S&keleton and Centerlines"), this,
                                            [this] { extractSkeletonAndCenterlines(); });
    m_documentActions << vessels->addAction(tr("AAA &Sac (Outer Wall, Thrombus)"), this, [this] { measureSac(); });
    m_documentActions << vessels->addAction(tr("&Along the Vessel (3D + CPR)"), this, [this] { showVesselView(); });
    QAction* endoscope = vessels->addAction(tr("Virtual &Endoscope"), this, [this] { showEndoscope(); });
    endoscope->setObjectName("endoscopeAction");
    endoscope->setToolTip(tr("A camera inside the lumen flying along a centerline, with focal length and focus"));
    m_documentActions << endoscope;
    vessels->addSeparator();
    m_documentActions << vessels->addAction(tr("&Edit Label (Brush)"), this, [this] { startLabelEditing(); });
    m_documentActions << vessels->addAction(tr("&Parameters..."), this, [this] { editVesselParameters(); });
}

void MainWindow::editVesselParameters()
{
    editParametersInDialog(this, tr("Vessel parameters"),
                           {{tr("Segmentation"), &m_segmentationParameters},
                            {tr("Segmentation from points"), &m_guidedParameters},
                            {tr("Skeleton"), &m_skeletonParameters},
                            {tr("Centerlines"), &m_centerlineParameters}});
}

std::string MainWindow::newestArtifact(study::ArtifactKind kind) const
{
    return m_document.study().newestArtifact(kind);
}

std::string MainWindow::newestImageOrSay(const QString& step)
{
    const std::string imageId = m_document.hasStudy() ? newestArtifact(study::ArtifactKind::Image) : std::string();
    if (imageId.empty() && m_document.hasStudy())
        showError(step, tr("The study has no CT image: import one first."));
    return imageId;
}

bool MainWindow::segmentVessels(const std::optional<Eigen::Vector3d>& seedMm)
{
    const std::string imageId = newestImageOrSay(tr("Segment vessels"));
    if (imageId.empty())
        return false;
    struct Outcome
    {
        imaging::SegmentationResult segmentation;
        TriangleMesh surface;
        std::map<std::string, std::string> parameters;
    };
    auto outcome = std::make_shared<Outcome>();
    discardLabelEdits();
    return m_tasks.run(
        tr("Segment vessels"),
        [this, imageId, seedMm, outcome, parameters = m_segmentationParameters](const Progress& progress) {
            const CtVolume ct = m_document.study().loadImage(imageId); // the study is not edited while a task runs
            outcome->segmentation = imaging::segmentVessels(ct, parameters, seedMm, progress.subRange(0.0, 0.8));
            outcome->parameters = parameters.valuesAsText();
            outcome->surface = displaySurface(outcome->segmentation.label, progress.subRange(0.8, 1.0));
        },
        [this, imageId, outcome] {
            study::Provenance provenance;
            provenance.command = "segment";
            provenance.inputs = {imageId};
            provenance.parameters = outcome->parameters;
            const Eigen::Vector3d& seed = outcome->segmentation.seedMm;
            provenance.parameters["seed_mm"] = QString("%1,%2,%3").arg(seed.x()).arg(seed.y()).arg(seed.z()).toStdString();
            provenance.parameters["seed_found_automatically"] = outcome->segmentation.seedFound ? "yes" : "no";
            const std::string id = m_document.study().addLabel(outcome->segmentation.label, storedText("Vessel lumen"), provenance,
                                                               outcome->segmentation.warnings);
            m_scene.labels[id] = outcome->segmentation.label; // what the views draw, before they are redrawn
            m_scene.lumenSurfaces[id] = outcome->surface;
            m_document.undoStack()->push(new AddedArtifactCommand(m_document, id, tr("Segment vessels")));
        });
}

bool MainWindow::measureSac()
{
    if (!m_document.hasStudy())
        return false;
    const std::string imageId = newestArtifact(study::ArtifactKind::Image);
    const std::string labelId = app::newestLumenLabel(m_document.study());
    if (imageId.empty() || labelId.empty())
    {
        showError(tr("AAA sac"), tr("The study needs a CT image and an aortic lumen label: segment the aorta first."));
        return false;
    }
    constexpr double kWallThicknessMm = 1.8; // assumed, as the CLI's default
    auto sac = std::make_shared<imaging::AneurysmSac>();
    discardLabelEdits();
    return m_tasks.run(
        tr("AAA sac"),
        [this, imageId, labelId, sac](const Progress& progress) {
            *sac = imaging::measureAneurysmSac(m_document.study().loadImage(imageId),
                                               m_document.study().loadLabel(labelId), kWallThicknessMm, progress);
        },
        [this, imageId, labelId, sac] {
            const std::string id = app::recordAneurysmSac(m_document.study(), *sac, imageId, labelId, kWallThicknessMm);
            m_document.undoStack()->push(new AddedArtifactCommand(m_document, id, tr("AAA sac")));
        });
}

bool MainWindow::extractSkeletonAndCenterlines()
{
    if (!m_document.hasStudy())
        return false;
    const std::string labelId = app::newestLumenLabel(m_document.study()); // not a sac's labels nor a grown organ
    if (labelId.empty())
    {
        showError(tr("Skeleton and centerlines"), tr("The study has no vessel label: segment the vessels first."));
        return false;
    }
    struct Outcome
    {
        imaging::SkeletonResult skeleton;
        SkeletonGraph centerlines;
        imaging::VesselMeasurements measurements;
        std::map<std::string, std::string> skeletonParameters, centerlineParameters;
    };
    auto outcome = std::make_shared<Outcome>();
    discardLabelEdits();
    return m_tasks.run(
        tr("Skeleton and centerlines"),
        [this, labelId, outcome, skeleton = m_skeletonParameters,
         centerline = m_centerlineParameters](const Progress& progress) {
            const LabelVolume label = m_document.study().loadLabel(labelId);
            outcome->skeleton = imaging::extractSkeleton(label, 1, skeleton, progress.subRange(0.0, 0.6));
            outcome->centerlines = imaging::extractCenterlines(label, 1, outcome->skeleton.graph, centerline, std::nullopt,
                                                               progress.subRange(0.6, 0.9));
            outcome->measurements = imaging::measureVessels(label, outcome->centerlines,
                                                            ParameterSet(imaging::measurementParameters()),
                                                            progress.subRange(0.9, 1.0));
            outcome->skeletonParameters = skeleton.valuesAsText();
            outcome->centerlineParameters = centerline.valuesAsText();
        },
        [this, labelId, outcome] {
            study::Provenance skeleton;
            skeleton.command = "skeleton";
            skeleton.inputs = {labelId};
            skeleton.parameters = outcome->skeletonParameters;
            const std::string skeletonId =
                m_document.study().addSkeleton(outcome->skeleton.graph, storedText("Vessel skeleton"), skeleton);
            study::Provenance centerline;
            centerline.command = "centerline";
            centerline.inputs = {skeletonId, labelId};
            centerline.parameters = outcome->centerlineParameters;
            const std::string centerlineId =
                m_document.study().addSkeleton(outcome->centerlines, storedText("Centerlines"), centerline);
            m_scene.skeletons[skeletonId] = outcome->skeleton.graph;
            m_scene.skeletons[centerlineId] = outcome->centerlines;
            m_scene.measurements[centerlineId] = outcome->measurements;
            m_document.undoStack()->beginMacro(tr("Skeleton and centerlines"));
            m_document.undoStack()->push(new AddedArtifactCommand(m_document, skeletonId, tr("Skeleton")));
            m_document.undoStack()->push(new AddedArtifactCommand(m_document, centerlineId, tr("Centerlines")));
            m_document.undoStack()->endMacro();
        });
}

} // namespace vsim::gui
