#include "PacsDialog.h"

#include "PacsNodes.h"
#include "vsim/core/Error.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QRegularExpressionValidator>
#include <QTreeWidget>
#include <QVBoxLayout>
#include <QtConcurrent>

#include <algorithm>

namespace vsim::gui {
namespace {

QString text(const std::string& value)
{
    return QString::fromStdString(value);
}

/// YYYYMMDD shown as YYYY-MM-DD (ISO 8601), as the rest of the workstation writes dates.
QString isoDate(const std::string& dicomDate)
{
    return dicomDate.size() == 8 ? text(dicomDate.substr(0, 4) + "-" + dicomDate.substr(4, 2) + "-" + dicomDate.substr(6, 2))
                                 : text(dicomDate);
}

enum Column
{
    kName,
    kPatientId,
    kDate,
    kDescription,
    kAccession,
    kModality,
    kCount,
    kColumns
};

constexpr int kKindRole = Qt::UserRole;     ///< PacsDialog::Row
constexpr int kUidRole = Qt::UserRole + 1;  ///< the patient's ID, the study's or the series' instance UID
constexpr int kStudyRole = Qt::UserRole + 2; ///< a series row's study UID

QTreeWidgetItem* row(PacsDialog::Row kind, const QStringList& cells, const QString& uid)
{
    auto* item = new QTreeWidgetItem(cells);
    item->setData(kName, kKindRole, int(kind));
    item->setData(kName, kUidRole, uid);
    return item;
}

/// The "..." child that gives a patient or a study its expand arrow until its children are loaded.
void addPlaceholder(QTreeWidgetItem* parent)
{
    parent->addChild(row(PacsDialog::Row::Placeholder, {QStringLiteral("...")}, {}));
}

PacsDialog::Row kindOf(const QTreeWidgetItem* item)
{
    return PacsDialog::Row(item->data(kName, kKindRole).toInt());
}

QString count(int number, const QString& unit)
{
    return number < 0 ? QString() : QStringLiteral("%1 %2").arg(number).arg(unit);
}

} // namespace

struct PacsDialog::Job
{
    CancellationToken token;
    bool abandoned = false; ///< cancelled: its end is not shown (GUI thread only)
};

PacsDialog::PacsDialog(QWidget* parent) : QDialog(parent)
{
    setWindowTitle(tr("Query/Retrieve (PACS)"));
    auto* layout = new QVBoxLayout(this);
    auto* top = new QHBoxLayout;
    top->addWidget(createNodeBox(), 1);
    top->addWidget(createFilterBox(), 1);
    layout->addLayout(top);

    m_results = new QTreeWidget(this);
    m_results->setColumnCount(kColumns);
    m_results->setHeaderLabels({tr("Patient / series"), tr("Patient ID"), tr("Date"), tr("Description"), tr("Accession"),
                                tr("Modalities"), tr("Count")});
    m_results->setSelectionMode(QAbstractItemView::SingleSelection);
    m_results->setAlternatingRowColors(true);
    m_results->header()->setStretchLastSection(true);
    layout->addWidget(m_results, 1);
    auto* statusRow = new QHBoxLayout;
    m_status = new QLabel(tr("Choose or enter a PACS node, then Echo or Search."), this);
    m_status->setWordWrap(true);
    statusRow->addWidget(m_status, 1);
    m_cancel = new QPushButton(tr("Cancel"), this);
    m_cancel->setToolTip(tr("Stop the echo or the query (C-CANCEL)"));
    statusRow->addWidget(m_cancel);
    layout->addLayout(statusRow);

    auto* buttons = new QDialogButtonBox(this);
    m_retrieve = buttons->addButton(tr("Retrieve and Import"), QDialogButtonBox::AcceptRole);
    m_retrieve->setToolTip(tr("Fetch the selected study or series (C-GET) and import its CT into the open study"));
    buttons->addButton(QDialogButtonBox::Close);
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    layout->addWidget(buttons);
    connect(m_cancel, &QPushButton::clicked, this, &PacsDialog::cancel);
    connect(m_results, &QTreeWidget::itemSelectionChanged, this, &PacsDialog::updateButtons);
    connect(m_results, &QTreeWidget::itemExpanded, this, &PacsDialog::loadChildren);
    connect(m_results, &QTreeWidget::itemDoubleClicked, this, [this](QTreeWidgetItem* item) {
        if (kindOf(item) == Row::Series && m_retrieve->isEnabled())
            accept();
    });
    fillSavedNodes({});
    resize(1100, 720);
    updateButtons();
}

PacsDialog::~PacsDialog()
{
    cancel(); // a running job ends on its own (its node's timeout bounds it) and touches nothing of the dialog
}

QWidget* PacsDialog::createFilterBox()
{
    auto* box = new QGroupBox(tr("Find"), this);
    auto* form = new QFormLayout(box);
    m_level = new QComboBox(box);
    m_level->addItem(tr("Studies"), int(Level::Studies));
    m_level->addItem(tr("Patients"), int(Level::Patients));
    m_level->setToolTip(tr("List studies, or patients whose studies open below them; a study opens onto its series"));
    form->addRow(tr("List:"), m_level);
    m_patientName = new QLineEdit(box);
    m_patientName->setPlaceholderText(tr("e.g. DOE^J* (wildcards * and ?)"));
    form->addRow(tr("Patient name:"), m_patientName);
    m_patientId = new QLineEdit(box);
    form->addRow(tr("Patient ID:"), m_patientId);
    const auto date = new QRegularExpressionValidator(QRegularExpression("\\d{0,8}"), box);
    m_dateFrom = new QLineEdit(box);
    m_dateTo = new QLineEdit(box);
    for (QLineEdit* edit : {m_dateFrom, m_dateTo})
    {
        edit->setValidator(date);
        edit->setPlaceholderText(tr("YYYYMMDD"));
    }
    auto* dates = new QHBoxLayout;
    dates->addWidget(m_dateFrom);
    dates->addWidget(new QLabel(tr("to"), box));
    dates->addWidget(m_dateTo);
    form->addRow(tr("Study date:"), dates);
    m_modality = new QComboBox(box);
    m_modality->setEditable(true);
    m_modality->addItems({"", "CT", "MR", "SEG", "DOC"});
    form->addRow(tr("Modality:"), m_modality);
    m_search = new QPushButton(tr("Search"), box);
    m_search->setDefault(true);
    form->addRow(m_search);
    connect(m_search, &QPushButton::clicked, this, &PacsDialog::search);
    return box;
}

void PacsDialog::runInBackground(std::function<void(const Progress&)> work, std::function<void(const QString&)> done)
{
    auto job = std::make_shared<Job>();
    m_job = job;
    auto* watcher = new QFutureWatcher<QString>(this);
    connect(watcher, &QFutureWatcher<QString>::finished, this, [this, watcher, job, done = std::move(done)] {
        watcher->deleteLater();
        if (job->abandoned)
            return;
        m_job.reset();
        done(watcher->result());
        updateButtons();
    });
    // The work holds no pointer into the dialog: it may outlive it after Cancel.
    watcher->setFuture(QtConcurrent::run([work = std::move(work), token = job->token]() -> QString {
        try
        {
            work(Progress([](double, const std::string&) {}, token));
            return {};
        }
        catch (const Cancelled&)
        {
            return QStringLiteral("cancelled");
        }
        catch (const std::exception& failure)
        {
            return QString::fromStdString(textForPeople(failure));
        }
    }));
    updateButtons();
}

void PacsDialog::cancel()
{
    if (!m_job)
        return;
    m_job->abandoned = true;
    m_job->token.cancel(); // a query sends its C-CANCEL at the next answer
    m_job.reset();
    m_status->setText(tr("Cancelled."));
    updateButtons();
}

void PacsDialog::echo()
{
    if (isBusy())
        return;
    const dicom::PacsNode target = node();
    m_status->setText(tr("Echo to %1...").arg(nodeText(target)));
    runInBackground([target](const Progress&) { dicom::pacsEcho(target); },
                    [this, target](const QString& error) {
                        m_status->setText(error.isEmpty() ? tr("%1 answers the echo.").arg(nodeText(target))
                                                          : tr("Echo failed: %1").arg(error));
                        emit echoFinished();
                    });
}

void PacsDialog::setFilters(const QString& patientName, const QString& patientId, const QString& dateFrom,
                            const QString& dateTo, const QString& modality)
{
    m_patientName->setText(patientName);
    m_patientId->setText(patientId);
    m_dateFrom->setText(dateFrom);
    m_dateTo->setText(dateTo);
    m_modality->setCurrentText(modality);
}

void PacsDialog::setLevel(Level level)
{
    m_level->setCurrentIndex(m_level->findData(int(level)));
}

dicom::StudyQuery PacsDialog::studyQuery(const std::string& patientId) const
{
    dicom::StudyQuery query;
    query.patientName = patientId.empty() ? m_patientName->text().trimmed().toStdString() : std::string();
    query.patientId = patientId.empty() ? m_patientId->text().trimmed().toStdString() : patientId;
    query.dateFrom = m_dateFrom->text().toStdString();
    query.dateTo = m_dateTo->text().toStdString();
    query.modality = m_modality->currentText().trimmed().toStdString();
    return query;
}

namespace {

QTreeWidgetItem* studyRow(const dicom::StudyMatch& match)
{
    QTreeWidgetItem* item =
        row(PacsDialog::Row::Study,
            {text(match.patientName), text(match.patientId), isoDate(match.studyDate), text(match.studyDescription),
             text(match.accessionNumber), text(match.modalities), count(match.seriesCount, PacsDialog::tr("series"))},
            text(match.studyInstanceUid));
    addPlaceholder(item);
    return item;
}

} // namespace

void PacsDialog::search()
{
    if (isBusy())
        return;
    const dicom::PacsNode target = node();
    const dicom::StudyQuery query = studyQuery({});
    for (const std::string& date : {query.dateFrom, query.dateTo})
        if (!date.empty() && date.size() != 8)
        {
            m_status->setText(tr("A study date is YYYYMMDD (8 digits)."));
            emit searchFinished();
            return;
        }
    const bool patients = Level(m_level->currentData().toInt()) == Level::Patients;
    m_status->setText(tr("Searching %1...").arg(nodeText(target)));
    auto studies = std::make_shared<std::vector<dicom::StudyMatch>>();
    auto people = std::make_shared<std::vector<dicom::PatientMatch>>();
    runInBackground(
        [target, query, patients, studies, people](const Progress& progress) {
            if (patients)
                *people = dicom::findPatients(target, {query.patientName, query.patientId}, progress);
            else
                *studies = dicom::findStudies(target, query, progress);
        },
        [this, patients, studies, people](const QString& error) {
            m_results->clear();
            if (!error.isEmpty())
                m_status->setText(tr("Search failed: %1").arg(error));
            else if (patients)
                m_status->setText(tr("Patients found: %1.").arg(people->size()));
            else
                m_status->setText(tr("Studies found: %1.").arg(studies->size()));
            for (const dicom::PatientMatch& match : *people)
            {
                QTreeWidgetItem* item = row(Row::Patient,
                                            {text(match.patientName), text(match.patientId),
                                             match.birthDate.empty() ? QString() : tr("born %1").arg(isoDate(match.birthDate)),
                                             text(match.sex), {}, {}, count(match.studyCount, tr("studies"))},
                                            text(match.patientId));
                addPlaceholder(item);
                m_results->addTopLevelItem(item);
            }
            for (const dicom::StudyMatch& match : *studies)
                m_results->addTopLevelItem(studyRow(match));
            for (int column = 0; column < kColumns; ++column)
                m_results->resizeColumnToContents(column);
            if (m_results->topLevelItemCount() > 0)
                m_results->setCurrentItem(m_results->topLevelItem(0));
            emit searchFinished();
        });
}

void PacsDialog::loadChildren(QTreeWidgetItem* item)
{
    if (item == nullptr || item->childCount() != 1 || kindOf(item->child(0)) != Row::Placeholder)
        return; // loaded already
    if (isBusy())
    {
        item->setExpanded(false);
        m_status->setText(tr("Wait for the running query, or Cancel it, then open this row again."));
        return;
    }
    const dicom::PacsNode target = node();
    const bool patient = kindOf(item) == Row::Patient;
    const std::string key = item->data(kName, kUidRole).toString().toStdString();
    const dicom::StudyQuery query = studyQuery(key);
    const std::string modality = m_modality->currentText().trimmed().toStdString();
    m_status->setText(patient ? tr("Finding the studies of %1...").arg(item->text(kName))
                              : tr("Finding the series of %1...").arg(item->text(kDescription)));
    auto studies = std::make_shared<std::vector<dicom::StudyMatch>>();
    auto series = std::make_shared<std::vector<dicom::SeriesMatch>>();
    runInBackground(
        [target, patient, key, query, modality, studies, series](const Progress& progress) {
            if (patient)
                *studies = dicom::findStudies(target, query, progress);
            else // the study's every series: the modality filter chose the studies, a study's SEG or PDF belongs to it
                *series = dicom::findSeries(target, key, {}, progress);
        },
        [this, item, key, studies, series](const QString& error) {
            if (!error.isEmpty())
            {
                item->setExpanded(false);
                m_status->setText(tr("Search failed: %1").arg(error));
                emit childrenLoaded();
                return;
            }
            delete item->takeChild(0);
            for (const dicom::StudyMatch& match : *studies)
                item->addChild(studyRow(match));
            for (const dicom::SeriesMatch& match : *series)
            {
                QTreeWidgetItem* child =
                    row(Row::Series,
                        {match.seriesNumber.empty() ? text(match.modality)
                                                    : tr("%1 #%2").arg(text(match.modality), text(match.seriesNumber)),
                         {}, isoDate(match.seriesDate), text(match.seriesDescription), {}, text(match.modality),
                         count(match.instanceCount, tr("images"))},
                        text(match.seriesInstanceUid));
                child->setData(kName, kStudyRole, QString::fromStdString(key));
                item->addChild(child);
            }
            m_status->setText(studies->empty() && series->empty() ? tr("Nothing found below this row.")
                                                                   : tr("Found: %1.").arg(item->childCount()));
            emit childrenLoaded();
        });
}

bool PacsDialog::isBusy() const
{
    return m_job != nullptr;
}

QString PacsDialog::statusText() const
{
    return m_status->text();
}

dicom::RetrieveTarget PacsDialog::selectedTarget() const
{
    const QTreeWidgetItem* item = m_results->currentItem();
    if (item == nullptr || !item->isSelected())
        return {std::string()};
    const std::string uid = item->data(kName, kUidRole).toString().toStdString();
    switch (kindOf(item))
    {
    case Row::Study:
        return {uid};
    case Row::Series:
        return {item->data(kName, kStudyRole).toString().toStdString(), uid};
    default:
        return {std::string()};
    }
}

QString PacsDialog::selectedLabel() const
{
    const QTreeWidgetItem* item = m_results->currentItem();
    if (item == nullptr)
        return {};
    if (kindOf(item) == Row::Series && item->parent() != nullptr)
        return tr("%1 of %2, %3").arg(item->text(kName), item->parent()->text(kDescription), item->parent()->text(kDate));
    return tr("%1, %2").arg(item->text(kDescription), item->text(kDate));
}

void PacsDialog::updateButtons()
{
    const bool busy = isBusy();
    m_echo->setEnabled(!busy);
    m_search->setEnabled(!busy);
    m_cancel->setEnabled(busy);
    m_retrieve->setEnabled(!busy && !selectedTarget().studyInstanceUid.empty());
}

} // namespace vsim::gui
