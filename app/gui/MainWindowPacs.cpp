// File > Query/Retrieve (PACS): the dialog, then the fetch (C-GET) into VascuSim's PACS folder and the import of its
// CT, one after the other in the task runner (progress and Cancel in the status bar).

#include "MainWindow.h"
#include "PacsDialog.h"

#include <QDateTime>
#include <QDir>
#include <QStandardPaths>

namespace vsim::gui {

void MainWindow::showPacsDialog()
{
    auto* dialog = new PacsDialog(this);
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    connect(dialog, &QDialog::accepted, this, [this, dialog] {
        retrieveFromPacs(dialog->node(), dialog->selectedStudyUid(), dialog->selectedStudyLabel());
    });
    dialog->open();
}

bool MainWindow::retrieveFromPacs(const dicom::PacsNode& node, const QString& studyUid, const QString& label)
{
    if (!m_document.hasStudy())
    {
        showError(tr("Retrieve from PACS"), tr("Open or create a study first: the retrieved CT is imported into it."));
        return false;
    }
    // VascuSim's own folder for what it fetches (a new one each time: a retrieve needs a new or empty folder).
    const QString folder = QDir(QStandardPaths::writableLocation(QStandardPaths::AppDataLocation))
                               .filePath("pacs/" + studyUid + "-" +
                                         QDateTime::currentDateTimeUtc().toString("yyyyMMddTHHmmsszzz"));
    return m_tasks.run(
        label.isEmpty() ? tr("Retrieve from PACS") : tr("Retrieve %1 from PACS").arg(label),
        [node, uid = studyUid.toStdString(), path = folder.toStdString()](const Progress& progress) {
            dicom::retrieveStudy(node, uid, path, progress);
        },
        [this, folder] { importDicom(folder); });
}

} // namespace vsim::gui
