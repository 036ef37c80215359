// The import steps of the workstation: DICOM (the Import DICOM dialog or a folder), volume files and label masks, in
// the background, each undoable; values that are not HU are refused unless the user gives the rescale.

#include "ArtifactCommands.h"
#include "DicomImportDialog.h"
#include "MainWindow.h"
#include "ViewLayout.h"
#include "vsim/app/DicomStudyImport.h"
#include "vsim/app/MaskSource.h"
#include "vsim/dicom/DicomSegmentation.h"
#include "vsim/dicom/DicomImport.h"
#include "vsim/study/LabelImport.h"
#include "vsim/study/VolumeFileImport.h"

#include <QFileInfo>
#include <QInputDialog>

namespace vsim::gui {

bool MainWindow::importVolume(const QString& file)
{
    if (!m_document.hasStudy())
        return false;
    auto imported = std::make_shared<study::ImportedVolume>();
    return m_tasks.run(
        tr("Import volume"),
        [path = file.toStdString(), imported](const Progress& progress) { *imported = study::readVolumeFile(path, progress); },
        [this, file, imported] {
            const std::string id = addWithRescaleIfAsked(tr("Import volume"), [&](const std::optional<HounsfieldRescale>& rescale) {
                return study::addImportedVolume(m_document.study(), *imported, file.toStdString(), rescale);
            });
            if (id.empty())
                return;
            m_document.undoStack()->push(new AddedArtifactCommand(m_document, id, tr("Import %1").arg(QFileInfo(file).fileName())));
            m_views->showImage(m_document.study().loadImage(id));
        });
}

bool MainWindow::importLabel(const QString& file)
{
    if (!m_document.hasStudy())
        return false;
    const std::string imageId = newestArtifact(study::ArtifactKind::Image);
    if (imageId.empty())
    {
        showError(tr("Import label"), tr("The study has no CT image for the label's grid: import the CT first."));
        return false;
    }
    auto label = std::make_shared<LabelVolume>();
    auto warnings = std::make_shared<std::vector<std::string>>();
    auto kind = std::make_shared<std::string>();
    const VolumeGeometry grid = m_document.study().volumeGeometry(imageId);
    return m_tasks.run(
        tr("Import label"),
        [path = file.toStdString(), grid, label, warnings, kind](const Progress& progress) {
            // A DICOM mask slice stands for its folder's series (as the CLI's import of a folder).
            const std::filesystem::path source = app::isVolumeFile(path) || dicom::isDicomSegmentation(path)
                                                     ? std::filesystem::path(path)
                                                     : std::filesystem::path(path).parent_path();
            app::MaskSource mask = app::readMaskSource(source, {}, progress);
            *warnings = mask.warnings;
            *kind = mask.kind;
            *label = study::maskOnImageGrid(mask.mask, grid, std::nullopt, *warnings);
        },
        [this, file, imageId, label, warnings, kind] {
            study::Provenance provenance;
            provenance.command = "import label";
            provenance.inputs = {QFileInfo(file).fileName().toStdString(), imageId};
            provenance.parameters = {{"label_value", "as in the mask"}, {"source", *kind}};
            const std::string id =
                m_document.study().addLabel(*label, QFileInfo(file).fileName().toStdString(), provenance, *warnings);
            m_scene.labels[id] = *label;
            m_document.undoStack()->push(new AddedArtifactCommand(m_document, id, tr("Import %1").arg(QFileInfo(file).fileName())));
        });
}

std::string MainWindow::addWithRescaleIfAsked(const QString& title,
                                              const std::function<std::string(const std::optional<HounsfieldRescale>&)>& add)
{
    std::optional<HounsfieldRescale> rescale;
    for (;;)
    {
        try
        {
            return add(rescale);
        }
        catch (const Error& error)
        {
            if (error.contextValue("option") != "--rescale")
            {
                showError(title, QString::fromStdString(error.messageForPeople()));
                return {};
            }
            // Not HU: the user may know the rescale (a volume of stored values); nothing was added.
            bool ok = false;
            const QString text = QInputDialog::getText(
                this, tr("Not Hounsfield units"),
                tr("%1\n\nRescale to HU (HU = slope x stored value + intercept):")
                    .arg(QString::fromStdString(error.messageForPeople())),
                QLineEdit::Normal, rescale ? QString("%1, %2").arg(rescale->slope).arg(rescale->intercept) : "1, -1024", &ok);
            const auto numbers = numbersInText(text, 2);
            if (!ok || !numbers || numbers->size() != 2)
                return {};
            rescale = HounsfieldRescale{(*numbers)[0], (*numbers)[1]};
        }
    }
}

bool MainWindow::importDicom(const QString& path, const QString& seriesKey,
                             std::shared_ptr<const dicom::DicomScanResult> scan)
{
    if (!m_document.hasStudy())
        return false;
    auto volume = std::make_shared<dicom::DicomVolume>();
    return m_tasks.run(
        tr("Import DICOM"),
        [input = path.toStdString(), wanted = seriesKey.toStdString(), scan, volume](const Progress& progress) {
            std::shared_ptr<const dicom::DicomScanResult> scanned = scan;
            if (!scanned)
                scanned = std::make_shared<const dicom::DicomScanResult>(dicom::scanDicom(input, progress.subRange(0.0, 0.2)));
            *volume = dicom::importDicomSeries(app::chooseSeries(*scanned, wanted), {}, progress.subRange(0.2, 1.0));
        },
        [this, path, volume] {
            const std::string id = addWithRescaleIfAsked(tr("Import DICOM"), [&](const std::optional<HounsfieldRescale>& rescale) {
                return app::addDicomVolumeToStudy(m_document.study(), *volume, path.toStdString(), rescale);
            });
            if (id.empty())
                return;
            const QString name = QString::fromStdString(m_document.study().artifact(id).name);
            m_document.undoStack()->push(new AddedArtifactCommand(m_document, id, tr("Import %1").arg(name)));
            m_views->showImage(m_document.study().loadImage(id));
        });
}

void MainWindow::showDicomImportDialog()
{
    auto* dialog = new DicomImportDialog(this);
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    connect(dialog, &QDialog::accepted, this, [this, dialog] {
        importDicom(dialog->scannedPath(), dialog->selectedSeriesKey(), dialog->scanResult());
    });
    dialog->open();
}

} // namespace vsim::gui
