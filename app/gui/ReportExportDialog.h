#pragma once

// File > Export Report: where the PDF goes, the paper, the report's language (the workstation's by default; a
// German reader may want an English report for a colleague), anonymization, whether the solvers' validation cases
// run into it, and whether a DICOM Encapsulated PDF and the metrics (CSV, JSON) go beside it.

#include "vsim/report/PdfReport.h"

#include <QDialog>
#include <QString>

class QCheckBox;
class QComboBox;
class QLineEdit;

namespace vsim::gui {

struct ReportExportRequest
{
    QString pdf;                                   ///< the PDF's path; the DICOM and metrics files go beside it
    report::PageSize page = report::PageSize::A4;
    bool anonymize = false;
    bool dicom = false;   ///< <name>.dcm: an Encapsulated PDF in a new series of the study
    bool metrics = false; ///< <name>-metrics.csv and <name>-metrics.json
    bool overwrite = false; ///< the user confirmed replacing files that exist (outputFiles())
    QString language = QStringLiteral("en"); ///< "en", "de", "zh_CN" (app TextLanguage.h)
    bool validate = true; ///< run the reported solvers' validation cases into the report (seconds to a minute)

    /// Every file the export writes: the PDF and, when asked, the DICOM and metrics files beside it.
    QStringList outputFiles() const;
};

class ReportExportDialog : public QDialog
{
    Q_OBJECT
public:
    ReportExportDialog(const QString& suggestedPdf, QWidget* parent = nullptr);
    ReportExportRequest request() const;

private:
    QLineEdit* m_path = nullptr;
    QComboBox* m_page = nullptr;
    QComboBox* m_language = nullptr;
    QCheckBox* m_anonymize = nullptr;
    QCheckBox* m_dicom = nullptr;
    QCheckBox* m_metrics = nullptr;
    QCheckBox* m_validate = nullptr;
};

} // namespace vsim::gui
