#include "MainWindow.h"

#include "ArtifactCommands.h"
#include "FileLocations.h"
#include "ReportExportDialog.h"
#include "vsim/app/StudyReport.h"
#include "vsim/app/TextLanguage.h"
#include "vsim/core/OutputSafety.h"
#include "vsim/report/EncapsulatedPdf.h"
#include "vsim/report/MetricsExport.h"

#include <QApplication>
#include <QDate>
#include <QDesktopServices>
#include <QDir>
#include <QStandardPaths>
#include <QUrl>
#include <QFileInfo>
#include <QMessageBox>
#include <QStatusBar>
#include <QThread>

#include <optional>

namespace vsim::gui {
namespace {

/// Runs a snapshot's OpenGL rendering on the GUI thread and waits for the picture (the report is built in the
/// background; the 3D views' contexts live on the GUI thread).
QImage renderOnGuiThread(const std::function<QImage()>& render)
{
    if (QThread::currentThread() == qApp->thread())
        return render();
    QImage image;
    QString failure;
    QMetaObject::invokeMethod(
        qApp,
        [&] {
            try
            {
                image = render();
            }
            catch (const std::exception& error)
            {
                failure = QString::fromUtf8(error.what());
            }
        },
        Qt::BlockingQueuedConnection);
    if (!failure.isEmpty())
        throw Error(failure.toStdString());
    return image;
}

/// <folder>/<name><suffix> beside the PDF.
std::string beside(const QString& pdf, const QString& suffix)
{
    const QFileInfo info(pdf);
    return (info.absolutePath() + "/" + info.completeBaseName() + suffix).toStdString();
}

/// A file name in the temporary folder that nothing uses yet: "<stem>.pdf", else "<stem>-2.pdf", ...
QString unusedTemporaryFile(const QString& stem)
{
    const QDir folder(QStandardPaths::writableLocation(QStandardPaths::TempLocation));
    QString file = folder.filePath(stem + ".pdf");
    for (int n = 2; QFileInfo::exists(file); ++n)
        file = folder.filePath(QStringLiteral("%1-%2.pdf").arg(stem).arg(n));
    return file;
}

} // namespace

void MainWindow::openReportArtifact(const std::string& id)
{
    try
    {
        const std::string pdf = m_document.study().loadReport(id);
        const QString file = unusedTemporaryFile(QString::fromStdString(m_document.study().name() + "-" + id));
        report::writeText(pdf, file.toStdString());
        if (!QDesktopServices::openUrl(QUrl::fromLocalFile(file)))
            showError(tr("Report"), tr("No PDF viewer opened %1.").arg(file));
    }
    catch (const Error& error)
    {
        showError(tr("Report"), QString::fromStdString(error.messageForPeople()));
    }
}

void MainWindow::showReportExportDialog()
{
    if (!m_document.hasStudy())
        return;
    const QString name = portableFileName(QString::fromStdString(m_document.study().name()) + " report " +
                                          QDate::currentDate().toString(Qt::ISODate));
    ReportExportDialog dialog(QDir(startFolder("report")).filePath(name + ".pdf"), this);
    if (dialog.exec() != QDialog::Accepted)
        return;
    ReportExportRequest request = dialog.request();
    rememberFolder("report", request.pdf);
    QStringList existing;
    for (const QString& file : request.outputFiles())
        if (QFileInfo::exists(file))
            existing << file;
    if (!existing.isEmpty())
    {
        if (QMessageBox::question(this, tr("Replace files"),
                                  tr("These files exist already:\n%1\nReplace them?").arg(existing.join('\n')),
                                  QMessageBox::Yes | QMessageBox::No, QMessageBox::No) != QMessageBox::Yes)
            return;
        request.overwrite = true;
    }
    exportReport(request);
}

bool MainWindow::exportReport(const ReportExportRequest& request)
{
    if (!m_document.hasStudy() || request.pdf.isEmpty())
        return false;
    app::ReportOptions options;
    options.anonymize = request.anonymize;
    options.language = request.language.toStdString();
    options.validate = request.validate;
    std::optional<app::TextLanguage> loaded; // the report's own, whatever the window's; loaded once
    try
    {
        loaded.emplace(options.language);
    }
    catch (const Error& error)
    {
        showError(tr("Report"), QString::fromStdString(error.messageForPeople()));
        return false;
    }
    const app::TextLanguage language = *loaded;
    options.renderSnapshot = [language](const std::function<QImage()>& render) {
        return renderOnGuiThread([&] {
            const app::ScopedTextLanguage snapshotLanguage(language);
            return render();
        });
    };
    auto built = std::make_shared<std::pair<report::Report, QByteArray>>();
    return m_tasks.run(
        tr("Report"),
        [this, request, options, built, language](const Progress& progress) {
            for (const QString& file : request.outputFiles()) // before the work: a refusal costs no time
                checkOutputFile(file.toStdString(), request.overwrite);
            const study::Study& study = m_document.study();
            const app::ScopedTextLanguage reportLanguage(language);
            const report::Report report = app::buildStudyReport(study, options, progress.subRange(0.0, 0.9));
            const QByteArray pdf = report::renderPdf(report, request.page);
            *built = {report, pdf};
            report::writeText(std::string(pdf.constData(), std::size_t(pdf.size())), request.pdf.toStdString());
            if (request.dicom)
                report::writeEncapsulatedPdf(pdf, app::documentIdentity(study, request.anonymize), beside(request.pdf, ".dcm"));
            if (request.metrics)
            {
                report::writeText(report::metricsCsv(report), beside(request.pdf, "-metrics.csv"));
                report::writeText(report::metricsJson(report), beside(request.pdf, "-metrics.json"));
            }
        },
        [this, request, options, built] {
            // The report goes into the study too (undoable; saved with it).
            const std::string id = app::addReport(m_document.study(), built->first,
                                                  std::string(built->second.constData(), std::size_t(built->second.size())),
                                                  options, request.page == report::PageSize::A4 ? "a4" : "letter");
            m_document.undoStack()->push(new AddedArtifactCommand(m_document, id, tr("Report")));
            statusBar()->showMessage(tr("Report written to %1").arg(request.pdf), 8000);
        });
}

} // namespace vsim::gui
