#pragma once

#include "vsim/dicom/DicomScan.h"

#include <QDialog>
#include <QFutureWatcher>

#include <memory>

class QImage;
class QLabel;
class QLineEdit;
class QProgressBar;
class QPushButton;
class QTreeWidget;
class QTreeWidgetItem;

namespace vsim::gui {

/// File > Import DICOM: scans a folder (recursively) or a DICOMDIR in the background, lists patient > study >
/// series with a thumbnail of the middle slice, the slice count, the voxel spacing and the warnings, and lets the
/// user pick the series to import (the CT with most slices is preselected). The import itself runs in the main
/// window's task runner (progress and Cancel in the status bar).
class DicomImportDialog : public QDialog
{
    Q_OBJECT
public:
    explicit DicomImportDialog(QWidget* parent = nullptr);
    ~DicomImportDialog() override;

    /// Starts scanning `path` (a folder, a DICOMDIR or a file); the previous listing is cleared.
    void scan(const QString& path);
    /// True while a scan or the thumbnails are running.
    bool isBusy() const;
    QString scannedPath() const { return m_scannedPath; }
    /// The scan shown; null before the first scan has finished.
    std::shared_ptr<const dicom::DicomScanResult> scanResult() const { return m_scan; }
    /// The key of the selected series (empty when none is selected).
    QString selectedSeriesKey() const;
    QTreeWidget* seriesTree() const { return m_tree; }

signals:
    void scanFinished();
    void thumbnailsFinished();

private:
    void onScanFinished();
    void showScan();
    void startThumbnails();
    void cancelWork();
    void setThumbnail(const QString& key, const QImage& image);

    QLineEdit* m_path = nullptr;
    QTreeWidget* m_tree = nullptr;
    QLabel* m_summary = nullptr;
    QProgressBar* m_progress = nullptr;
    QPushButton* m_cancelScan = nullptr;
    QPushButton* m_import = nullptr;
    QString m_scannedPath;
    QString m_summaryText; ///< files and series found, scan warnings
    std::shared_ptr<const dicom::DicomScanResult> m_scan;
    QFutureWatcher<std::shared_ptr<const dicom::DicomScanResult>> m_scanWatcher;
    QFutureWatcher<void> m_thumbnailWatcher;
    CancellationToken m_token;
};

} // namespace vsim::gui
