// File > Query/Retrieve (PACS): the dialog, then the fetch (C-GET) of the study or series into VascuSim's PACS folder
// and the import of its CT, one after the other in the task runner (progress and Cancel in the status bar).
// File > Send to PACS: the study's report and label as DICOM objects, stored on a node in the background.

#include "MainWindow.h"
#include "PacsDialog.h"
#include "PacsSendDialog.h"
#include "vsim/app/DicomResults.h"
#include "vsim/core/Error.h"

#include <QDateTime>
#include <QDir>
#include <QFile>
#include <QTimeZone>
#include <QStandardPaths>
#include <QStatusBar>

#include <filesystem>

namespace vsim::gui {
namespace {

constexpr const char* kFetchTime = "yyyyMMddTHHmmsszzz"; ///< UTC, the end of a retrieve folder's name
constexpr qint64 kKeepFetchedS = 24 * 3600;               ///< how long fetched files stay for a re-import (s)

/// The clean-up policy of VascuSim's PACS folder: a retrieve's files are there to be imported (the study keeps its
/// own copy of the volume), then kept a day for a re-import; each new retrieve removes the older ones. Only what
/// VascuSim made is touched: folders named <study UID>-<UTC time> holding plain files only.
void pruneFetchedStudies(const QDir& pacsFolder)
{
    const QDateTime now = QDateTime::currentDateTimeUtc();
    for (const QFileInfo& entry : pacsFolder.entryInfoList(QDir::Dirs | QDir::NoDotAndDotDot))
    {
        const QString name = entry.fileName();
        const qsizetype dash = name.lastIndexOf('-');
        QDateTime fetched = QDateTime::fromString(name.mid(dash + 1), kFetchTime);
        fetched.setTimeZone(QTimeZone::utc());
        if (dash <= 0 || !fetched.isValid() || fetched.secsTo(now) < kKeepFetchedS)
            continue;
        const QDir folder(entry.absoluteFilePath());
        if (!folder.entryList(QDir::Dirs | QDir::NoDotAndDotDot | QDir::System).isEmpty())
            continue; // not what a retrieve writes
        for (const QString& file : folder.entryList(QDir::Files | QDir::Hidden))
            QFile::remove(folder.filePath(file));
        pacsFolder.rmdir(name);
    }
}

} // namespace

void MainWindow::showPacsDialog()
{
    auto* dialog = new PacsDialog(this);
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    connect(dialog, &QDialog::accepted, this, [this, dialog] {
        retrieveFromPacs(dialog->node(), dialog->selectedTarget(), dialog->selectedLabel());
    });
    dialog->open();
}

bool MainWindow::retrieveFromPacs(const dicom::PacsNode& node, const dicom::RetrieveTarget& target, const QString& label)
{
    if (!m_document.hasStudy())
    {
        showError(tr("Retrieve from PACS"), tr("Open or create a study first: the retrieved CT is imported into it."));
        return false;
    }
    // VascuSim's own folder for what it fetches (a new one each time: a retrieve needs a new or empty folder).
    const QDir pacsFolder(QDir(QStandardPaths::writableLocation(QStandardPaths::AppDataLocation)).filePath("pacs"));
    pruneFetchedStudies(pacsFolder);
    const QString folder = pacsFolder.filePath(QString::fromStdString(target.studyInstanceUid) + "-" +
                                               QDateTime::currentDateTimeUtc().toString(kFetchTime));
    return m_tasks.run(
        label.isEmpty() ? tr("Retrieve from PACS") : tr("Retrieve %1 from PACS").arg(label),
        [node, target, path = folder.toStdString()](const Progress& progress) {
            dicom::retrieveStudy(node, target, path, progress);
        },
        [this, folder] { importDicom(folder); });
}

void MainWindow::showPacsSendDialog()
{
    if (!m_document.hasStudy())
        return;
    auto* dialog = new PacsSendDialog(m_document.study(), this);
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    connect(dialog, &QDialog::accepted, this, [this, dialog] { sendToPacs(dialog->request()); });
    dialog->open();
}

bool MainWindow::sendToPacs(const PacsSendRequest& request)
{
    if (!m_document.hasStudy() || (request.reportId.empty() && request.labelId.empty()))
        return false;
    // VascuSim's own outbox, a new folder each time: the files it writes there are removed after the send.
    const std::filesystem::path outbox =
        QDir(QStandardPaths::writableLocation(QStandardPaths::AppDataLocation))
            .filePath("pacs-outbox/" + QDateTime::currentDateTimeUtc().toString("yyyyMMddTHHmmsszzz"))
            .toStdString();
    auto stored = std::make_shared<std::vector<dicom::StoredObject>>();
    return m_tasks.run(
        tr("Send to PACS %1").arg(request.nodeName),
        [this, request, outbox, stored](const Progress& progress) {
            if (std::filesystem::exists(outbox))
                throw Error(Pattern{"the outbox folder exists already: %1", {outbox.string()}});
            std::filesystem::create_directories(outbox);
            std::vector<std::filesystem::path> files;
            const auto removeOurs = [&] {
                std::error_code ignored;
                for (const std::filesystem::path& file : files)
                    std::filesystem::remove(file, ignored);
                std::filesystem::remove(outbox, ignored); // empty now: only ours were there
            };
            try
            {
                const study::Study& study = m_document.study();
                if (!request.reportId.empty())
                {
                    files.push_back(outbox / "report.dcm");
                    app::writeReportEncapsulatedPdf(study, request.reportId, files.back());
                }
                if (!request.labelId.empty())
                {
                    files.push_back(outbox / "label-seg.dcm");
                    app::writeLabelSegmentation(study, request.labelId, files.back());
                }
                *stored = dicom::storeFiles(request.node, files, request.anonymized, progress);
            }
            catch (...)
            {
                removeOurs();
                throw;
            }
            removeOurs();
        },
        [this, request, stored] {
            statusBar()->showMessage(tr("Sent %1 objects to %2.").arg(stored->size()).arg(request.nodeName), 10000);
        });
}

} // namespace vsim::gui
