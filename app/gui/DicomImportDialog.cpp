#include "DicomImportDialog.h"

#include "FileLocations.h"

#include "vsim/dicom/DicomImport.h"
#include "vsim/dicom/SeriesGeometry.h"
#include "vsim/viz/DecimalText.h"
#include "vsim/core/StoredText.h"

#include <QDialogButtonBox>
#include <QFileDialog>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QImage>
#include <QLabel>
#include <QLineEdit>
#include <QPixmap>
#include <QProgressBar>
#include <QPushButton>
#include <QTreeWidget>
#include <QVBoxLayout>
#include <QtConcurrent>

#include <map>

namespace vsim::gui {
namespace {

constexpr int kThumbnailSize = 64;
constexpr int kKeyRole = Qt::UserRole + 1;

enum Column
{
    Description,
    Modality,
    Slices,
    Spacing,
    Warnings,
};

QString text(const std::map<std::string, std::string>& attributes, const char* key, const QString& fallback = {})
{
    const auto found = attributes.find(key);
    return found == attributes.end() || found->second.empty() ? fallback : QString::fromStdString(found->second);
}

QString spacingText(const dicom::DicomSeries& series, QStringList& warnings)
{
    try
    {
        const dicom::SeriesGeometry plan = dicom::planSeriesGeometry(series);
        for (const std::string& warning : plan.warnings)
            warnings << QString::fromStdString(storedTextForPeople(warning));
        const Eigen::Vector3d& s = plan.grid.spacing;
        return QString("%1 x %2 x %3")
            .arg(viz::decimalText(s.x(), 2))
            .arg(viz::decimalText(s.y(), 2))
            .arg(viz::decimalText(s.z(), 2));
    }
    catch (const Error& error)
    {
        warnings << QString::fromStdString(error.messageForPeople());
        return QObject::tr("cannot be placed");
    }
}

} // namespace

DicomImportDialog::DicomImportDialog(QWidget* parent) : QDialog(parent)
{
    setWindowTitle(tr("Import DICOM"));
    setObjectName("dicomImportDialog");
    resize(900, 520);

    m_path = new QLineEdit(this);
    m_path->setPlaceholderText(tr("Folder, DICOMDIR or file"));
    auto* browse = new QPushButton(tr("Browse..."), this);
    auto* scanButton = new QPushButton(tr("Scan"), this);
    auto* pathRow = new QHBoxLayout;
    pathRow->addWidget(m_path, 1);
    pathRow->addWidget(browse);
    pathRow->addWidget(scanButton);

    m_tree = new QTreeWidget(this);
    m_tree->setObjectName("dicomSeriesTree");
    m_tree->setHeaderLabels({tr("Patient / study / series"), tr("Modality"), tr("Slices"), tr("Voxel spacing (mm)"),
                             tr("Warnings")});
    m_tree->setIconSize(QSize(kThumbnailSize, kThumbnailSize));
    m_tree->header()->setSectionResizeMode(Description, QHeaderView::Stretch);

    m_summary = new QLabel(this);
    m_progress = new QProgressBar(this);
    m_progress->setRange(0, 0);
    m_progress->setVisible(false);
    m_cancelScan = new QPushButton(tr("Stop"), this);
    m_cancelScan->setVisible(false);
    auto* statusRow = new QHBoxLayout;
    statusRow->addWidget(m_summary, 1);
    statusRow->addWidget(m_progress);
    statusRow->addWidget(m_cancelScan);

    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Cancel, this);
    m_import = buttons->addButton(tr("Import"), QDialogButtonBox::AcceptRole);
    m_import->setEnabled(false);

    auto* layout = new QVBoxLayout(this);
    layout->addLayout(pathRow);
    layout->addWidget(m_tree, 1);
    layout->addLayout(statusRow);
    layout->addWidget(buttons);

    connect(browse, &QPushButton::clicked, this, [this] {
        const QString folder = QFileDialog::getExistingDirectory(this, tr("DICOM folder"),
                                                                 m_path->text().isEmpty() ? startFolder("dicom") : m_path->text());
        if (!folder.isEmpty())
            scan(folder);
    });
    connect(scanButton, &QPushButton::clicked, this, [this] { scan(m_path->text()); });
    connect(m_path, &QLineEdit::returnPressed, this, [this] { scan(m_path->text()); });
    connect(m_cancelScan, &QPushButton::clicked, this, &DicomImportDialog::cancelWork);
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    connect(m_tree, &QTreeWidget::itemSelectionChanged, this, [this] { m_import->setEnabled(!selectedSeriesKey().isEmpty()); });
    connect(m_tree, &QTreeWidget::itemDoubleClicked, this, [this](QTreeWidgetItem* item) {
        if (!item->data(Description, kKeyRole).toString().isEmpty())
            accept();
    });
    connect(&m_scanWatcher, &QFutureWatcher<std::shared_ptr<const dicom::DicomScanResult>>::finished, this,
            &DicomImportDialog::onScanFinished);
    connect(&m_thumbnailWatcher, &QFutureWatcher<void>::finished, this, [this] {
        m_summary->setText(m_summaryText);
        m_progress->setVisible(false);
        m_cancelScan->setVisible(false);
        emit thumbnailsFinished();
    });
    connect(this, &QDialog::finished, this, &DicomImportDialog::cancelWork);
}

DicomImportDialog::~DicomImportDialog()
{
    cancelWork();
    m_scanWatcher.waitForFinished();
    m_thumbnailWatcher.waitForFinished();
}

bool DicomImportDialog::isBusy() const
{
    return m_scanWatcher.isRunning() || m_thumbnailWatcher.isRunning();
}

void DicomImportDialog::cancelWork()
{
    m_token.cancel();
}

void DicomImportDialog::scan(const QString& path)
{
    if (path.isEmpty() || isBusy())
        return;
    m_path->setText(path);
    m_scannedPath = path;
    rememberFolder("dicom", path);
    m_tree->clear();
    m_scan.reset();
    m_import->setEnabled(false);
    m_summary->setText(tr("Reading DICOM headers..."));
    m_progress->setVisible(true);
    m_cancelScan->setVisible(true);
    m_token = CancellationToken();
    const Progress progress({}, m_token);
    m_scanWatcher.setFuture(QtConcurrent::run([input = path.toStdString(), progress]() {
        try
        {
            return std::make_shared<const dicom::DicomScanResult>(dicom::scanDicom(input, progress));
        }
        catch (const Error& error)
        {
            auto failed = std::make_shared<dicom::DicomScanResult>();
            failed->warnings.push_back(error.messageForPeople());
            return std::shared_ptr<const dicom::DicomScanResult>(failed);
        }
    }));
}

void DicomImportDialog::onScanFinished()
{
    m_scan = m_scanWatcher.result();
    showScan();
    emit scanFinished();
    if (m_scan->series.empty())
    {
        m_progress->setVisible(false);
        m_cancelScan->setVisible(false);
        emit thumbnailsFinished();
        return;
    }
    startThumbnails();
}

void DicomImportDialog::showScan()
{
    std::map<QString, QTreeWidgetItem*> patients, studies;
    const dicom::DicomSeries* preferred = m_scan->defaultSeries();
    for (const dicom::DicomSeries& series : m_scan->series)
    {
        const auto& attributes = series.attributes();
        const QString patientKey = text(attributes, "patient_id") + '|' + text(attributes, "patient_name");
        QTreeWidgetItem*& patient = patients[patientKey];
        if (!patient)
        {
            patient = new QTreeWidgetItem(m_tree, {text(attributes, "patient_name", tr("(no name)")) + "  [" +
                                                   text(attributes, "patient_id", tr("no ID")) + "]"});
            patient->setFlags(Qt::ItemIsEnabled);
        }
        QTreeWidgetItem*& study = studies[QString::fromStdString(series.studyInstanceUid)];
        if (!study)
        {
            study = new QTreeWidgetItem(patient, {text(attributes, "study_description", tr("(no description)")) + "  " +
                                                  text(attributes, "study_date")});
            study->setFlags(Qt::ItemIsEnabled);
        }
        QStringList warnings;
        for (const std::string& warning : series.warnings)
            warnings << QString::fromStdString(storedTextForPeople(warning));
        const QString spacing = spacingText(series, warnings);
        auto* item = new QTreeWidgetItem(
            study, {QString("%1: %2").arg(series.seriesNumber).arg(series.description.empty()
                                                                       ? tr("(no description)")
                                                                       : QString::fromStdString(series.description)),
                    QString::fromStdString(series.modality), QString::number(series.slices.size()), spacing,
                    warnings.join("; ")});
        item->setData(Description, kKeyRole, QString::fromStdString(series.key));
        item->setToolTip(Warnings, warnings.join('\n'));
        if (&series == preferred)
            m_tree->setCurrentItem(item);
    }
    m_tree->expandAll();
    QStringList summary{tr("%n file(s), %1 series", nullptr, int(m_scan->filesSeen)).arg(m_scan->series.size())};
    for (const std::string& warning : m_scan->warnings)
        summary << QString::fromStdString(storedTextForPeople(warning));
    m_summaryText = summary.join("; ");
    m_summary->setText(m_summaryText);
    for (int column : {Modality, Slices, Spacing})
        m_tree->resizeColumnToContents(column);
}

void DicomImportDialog::startThumbnails()
{
    m_summary->setText(m_summaryText + tr(" (making previews)"));
    // One preview per series, decoded off the GUI thread and handed to the tree as it comes.
    std::vector<std::string> keys;
    for (QTreeWidgetItemIterator it(m_tree); *it; ++it)
        if (const QString key = (*it)->data(Description, kKeyRole).toString(); !key.isEmpty())
            keys.push_back(key.toStdString());
    m_thumbnailWatcher.setFuture(QtConcurrent::run([this, keys, scan = m_scan, token = m_token] {
        for (const std::string& key : keys)
        {
            if (token.isCancelled())
                return;
            std::vector<std::uint8_t> grey;
            try
            {
                grey = dicom::seriesThumbnail(*scan->find(key), kThumbnailSize);
            }
            catch (const Error&)
            {
                continue; // no preview for a series that cannot be decoded; the import will say why
            }
            const QImage image =
                QImage(grey.data(), kThumbnailSize, kThumbnailSize, kThumbnailSize, QImage::Format_Grayscale8).copy();
            QMetaObject::invokeMethod(
                this, [this, key = QString::fromStdString(key), image] { setThumbnail(key, image); },
                Qt::QueuedConnection);
        }
    }));
}

void DicomImportDialog::setThumbnail(const QString& key, const QImage& image)
{
    for (QTreeWidgetItemIterator it(m_tree); *it; ++it)
        if ((*it)->data(Description, kKeyRole).toString() == key)
            (*it)->setIcon(Description, QIcon(QPixmap::fromImage(image)));
}

QString DicomImportDialog::selectedSeriesKey() const
{
    const QTreeWidgetItem* item = m_tree->currentItem();
    return item ? item->data(Description, kKeyRole).toString() : QString();
}

} // namespace vsim::gui
