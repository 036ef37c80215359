#include "ReportExportDialog.h"

#include "Languages.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLineEdit>
#include <QPushButton>

#include <algorithm>

namespace vsim::gui {

ReportExportDialog::ReportExportDialog(const QString& suggestedPdf, QWidget* parent) : QDialog(parent)
{
    setWindowTitle(tr("Export Report"));
    m_path = new QLineEdit(suggestedPdf, this);
    auto* browse = new QPushButton(tr("Browse..."), this);
    connect(browse, &QPushButton::clicked, this, [this] {
        const QString file = QFileDialog::getSaveFileName(this, tr("Report"), m_path->text(), tr("PDF (*.pdf)"));
        if (!file.isEmpty())
            m_path->setText(file.endsWith(".pdf", Qt::CaseInsensitive) ? file : file + ".pdf");
    });
    auto* pathRow = new QHBoxLayout;
    pathRow->addWidget(m_path, 1);
    pathRow->addWidget(browse);
    m_page = new QComboBox(this);
    m_page->addItem(tr("A4"), int(report::PageSize::A4));
    m_page->addItem(tr("Letter"), int(report::PageSize::Letter));
    m_language = new QComboBox(this);
    m_language->setObjectName("reportLanguage");
    for (const QString& code : QStringList{"en"} + translatedLanguages())
        m_language->addItem(nativeLanguageName(code), code);
    m_language->setCurrentIndex(std::max(0, m_language->findData(installedLanguage())));
    m_language->setToolTip(tr("The language of the report's texts and numbers; the workstation's by default"));
    m_anonymize = new QCheckBox(tr("Anonymize (no patient name, ID, birth date or institution)"), this);
    m_dicom = new QCheckBox(tr("Also as DICOM Encapsulated PDF (a new series of the study)"), this);
    m_metrics = new QCheckBox(tr("Also the metrics as CSV and JSON"), this);
    m_validate = new QCheckBox(tr("Run the solvers' validation cases into the report (seconds to a minute)"), this);
    m_validate->setChecked(true);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    buttons->button(QDialogButtonBox::Ok)->setText(tr("Export"));
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    auto* form = new QFormLayout(this);
    form->addRow(tr("PDF file:"), pathRow);
    form->addRow(tr("Paper:"), m_page);
    form->addRow(tr("Language:"), m_language);
    form->addRow(m_anonymize);
    form->addRow(m_validate);
    form->addRow(m_dicom);
    form->addRow(m_metrics);
    form->addRow(buttons);
}

QStringList ReportExportRequest::outputFiles() const
{
    const QFileInfo info(pdf);
    const QString stem = info.absolutePath() + "/" + info.completeBaseName();
    QStringList files{pdf};
    if (dicom)
        files << stem + ".dcm";
    if (metrics)
        files << stem + "-metrics.csv" << stem + "-metrics.json";
    return files;
}

ReportExportRequest ReportExportDialog::request() const
{
    ReportExportRequest request{m_path->text(), report::PageSize(m_page->currentData().toInt()),
                                m_anonymize->isChecked(), m_dicom->isChecked(), m_metrics->isChecked()};
    request.language = m_language->currentData().toString();
    request.validate = m_validate->isChecked();
    return request;
}

} // namespace vsim::gui
