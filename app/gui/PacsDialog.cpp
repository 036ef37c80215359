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
#include <QSpinBox>
#include <QTableWidget>
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

} // namespace

PacsDialog::PacsDialog(QWidget* parent) : QDialog(parent)
{
    setWindowTitle(tr("Query/Retrieve (PACS)"));
    auto* layout = new QVBoxLayout(this);
    auto* top = new QHBoxLayout;
    top->addWidget(createNodeBox(), 1);
    top->addWidget(createFilterBox(), 1);
    layout->addLayout(top);

    m_results = new QTableWidget(0, 7, this);
    m_results->setHorizontalHeaderLabels({tr("Patient"), tr("Patient ID"), tr("Study date"), tr("Description"),
                                          tr("Accession"), tr("Modalities"), tr("Series")});
    m_results->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_results->setSelectionMode(QAbstractItemView::SingleSelection);
    m_results->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_results->horizontalHeader()->setStretchLastSection(true);
    m_results->verticalHeader()->hide();
    layout->addWidget(m_results, 1);
    m_status = new QLabel(tr("Choose or enter a PACS node, then Echo or Search."), this);
    m_status->setWordWrap(true);
    layout->addWidget(m_status);

    auto* buttons = new QDialogButtonBox(this);
    m_retrieve = buttons->addButton(tr("Retrieve and Import"), QDialogButtonBox::AcceptRole);
    m_retrieve->setToolTip(tr("Fetch the selected study (C-GET) and import its CT into the open study"));
    buttons->addButton(QDialogButtonBox::Close);
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    layout->addWidget(buttons);
    connect(m_results, &QTableWidget::itemSelectionChanged, this, &PacsDialog::updateButtons);
    connect(m_results, &QTableWidget::cellDoubleClicked, this, [this] {
        if (m_retrieve->isEnabled())
            accept();
    });
    connect(&m_watcher, &QFutureWatcher<void>::finished, this, [this] {
        std::function<void()> done = std::move(m_done);
        done();
        updateButtons();
    });
    fillSavedNodes({});
    resize(1000, 560);
    updateButtons();
}

PacsDialog::~PacsDialog()
{
    m_watcher.waitForFinished(); // a node's timeout bounds it
}

QWidget* PacsDialog::createNodeBox()
{
    auto* box = new QGroupBox(tr("PACS node"), this);
    auto* form = new QFormLayout(box);
    m_saved = new QComboBox(box);
    connect(m_saved, &QComboBox::activated, this, &PacsDialog::chooseSaved);
    form->addRow(tr("Saved:"), m_saved);
    m_name = new QLineEdit(box);
    m_name->setPlaceholderText(tr("e.g. Radiology PACS"));
    form->addRow(tr("Name:"), m_name);
    const auto aeTitle = new QRegularExpressionValidator(QRegularExpression("[\\x20-\\x5b\\x5d-\\x7e]{1,16}"), box);
    m_aeTitle = new QLineEdit(box);
    m_aeTitle->setValidator(aeTitle);
    form->addRow(tr("AE title:"), m_aeTitle);
    m_host = new QLineEdit(box);
    form->addRow(tr("Host:"), m_host);
    m_port = new QSpinBox(box);
    m_port->setRange(1, 65535);
    m_port->setValue(104);
    form->addRow(tr("Port:"), m_port);
    m_callingAeTitle = new QLineEdit("VASCUSIM", box);
    m_callingAeTitle->setValidator(aeTitle);
    m_callingAeTitle->setToolTip(tr("Our AE title, as the PACS has it registered"));
    form->addRow(tr("Our AE title:"), m_callingAeTitle);
    m_timeout = new QSpinBox(box);
    m_timeout->setRange(1, 600);
    m_timeout->setValue(30);
    m_timeout->setSuffix(tr(" s"));
    form->addRow(tr("Timeout:"), m_timeout);
    m_uidRoot = new QLineEdit(savedUidRoot(), box);
    m_uidRoot->setPlaceholderText(tr("empty: UUID-based UIDs (2.25...)"));
    m_uidRoot->setToolTip(tr("The organisation's DICOM UID root for the reports and segmentations VascuSim makes"));
    form->addRow(tr("UID root:"), m_uidRoot);
    auto* row = new QHBoxLayout;
    auto* save = new QPushButton(tr("Save"), box);
    auto* remove = new QPushButton(tr("Remove"), box);
    m_echo = new QPushButton(tr("Echo"), box);
    m_echo->setToolTip(tr("Test the connection (C-ECHO)"));
    row->addWidget(save);
    row->addWidget(remove);
    row->addStretch();
    row->addWidget(m_echo);
    form->addRow(row);
    connect(save, &QPushButton::clicked, this, &PacsDialog::saveNode);
    connect(remove, &QPushButton::clicked, this, &PacsDialog::removeNode);
    connect(m_echo, &QPushButton::clicked, this, &PacsDialog::echo);
    return box;
}

QWidget* PacsDialog::createFilterBox()
{
    auto* box = new QGroupBox(tr("Find studies"), this);
    auto* form = new QFormLayout(box);
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

dicom::PacsNode PacsDialog::node() const
{
    dicom::PacsNode node;
    node.calledAeTitle = m_aeTitle->text().trimmed().toStdString();
    node.host = m_host->text().trimmed().toStdString();
    node.port = m_port->value();
    node.callingAeTitle = m_callingAeTitle->text().trimmed().toStdString();
    node.timeoutS = m_timeout->value();
    return node;
}

void PacsDialog::setNode(const QString& name, const dicom::PacsNode& node)
{
    m_name->setText(name);
    m_aeTitle->setText(text(node.calledAeTitle));
    m_host->setText(text(node.host));
    m_port->setValue(node.port);
    m_callingAeTitle->setText(text(node.callingAeTitle));
    m_timeout->setValue(node.timeoutS);
}

void PacsDialog::fillSavedNodes(const QString& current)
{
    m_saved->clear();
    const QList<PacsNodeEntry> nodes = loadPacsNodes();
    for (const PacsNodeEntry& entry : nodes)
        m_saved->addItem(tr("%1 (%2)").arg(entry.name, text(dicom::describe(entry.node))), entry.name);
    const int index = std::max(0, m_saved->findData(current));
    if (!nodes.isEmpty())
    {
        m_saved->setCurrentIndex(index);
        chooseSaved(index);
    }
}

void PacsDialog::chooseSaved(int index)
{
    const QList<PacsNodeEntry> nodes = loadPacsNodes();
    if (index >= 0 && index < nodes.size())
        setNode(nodes[index].name, nodes[index].node);
}

bool PacsDialog::saveNode()
{
    const QString name = m_name->text().trimmed();
    if (name.isEmpty())
    {
        m_status->setText(tr("Give the node a name to save it."));
        return false;
    }
    try
    {
        saveUidRoot(m_uidRoot->text());
    }
    catch (const Error& error)
    {
        m_status->setText(tr("Not saved: %1").arg(text(error.message())));
        return false;
    }
    QList<PacsNodeEntry> nodes = loadPacsNodes();
    const auto same = std::find_if(nodes.begin(), nodes.end(), [&](const PacsNodeEntry& entry) { return entry.name == name; });
    if (same != nodes.end())
        same->node = node();
    else
        nodes << PacsNodeEntry{name, node()};
    savePacsNodes(nodes);
    fillSavedNodes(name);
    m_status->setText(tr("Saved %1.").arg(name));
    return true;
}

void PacsDialog::removeNode()
{
    QList<PacsNodeEntry> nodes = loadPacsNodes();
    const QString name = m_saved->currentData().toString();
    nodes.erase(std::remove_if(nodes.begin(), nodes.end(), [&](const PacsNodeEntry& entry) { return entry.name == name; }),
                nodes.end());
    savePacsNodes(nodes);
    fillSavedNodes({});
}

void PacsDialog::runInBackground(std::function<void()> work, std::function<void()> done)
{
    m_error->clear();
    m_done = std::move(done);
    m_watcher.setFuture(QtConcurrent::run([work = std::move(work), error = m_error] {
        try
        {
            work();
        }
        catch (const std::exception& failure)
        {
            *error = failure.what();
        }
    }));
    updateButtons();
}

void PacsDialog::echo()
{
    if (isBusy())
        return;
    const dicom::PacsNode target = node();
    m_status->setText(tr("Echo to %1...").arg(text(dicom::describe(target))));
    runInBackground([target] { dicom::pacsEcho(target); },
                    [this, target] {
                        m_status->setText(m_error->empty() ? tr("%1 answers the echo.").arg(text(dicom::describe(target)))
                                                           : tr("Echo failed: %1").arg(text(*m_error)));
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

void PacsDialog::search()
{
    if (isBusy())
        return;
    const dicom::PacsNode target = node();
    dicom::StudyQuery query;
    query.patientName = m_patientName->text().trimmed().toStdString();
    query.patientId = m_patientId->text().trimmed().toStdString();
    query.dateFrom = m_dateFrom->text().toStdString();
    query.dateTo = m_dateTo->text().toStdString();
    query.modality = m_modality->currentText().trimmed().toStdString();
    for (const std::string& date : {query.dateFrom, query.dateTo})
        if (!date.empty() && date.size() != 8)
        {
            m_status->setText(tr("A study date is YYYYMMDD (8 digits)."));
            emit searchFinished();
            return;
        }
    m_status->setText(tr("Searching %1...").arg(text(dicom::describe(target))));
    runInBackground([target, query, matches = m_matches] { *matches = dicom::findStudies(target, query); },
                    [this] {
                        if (!m_error->empty())
                        {
                            m_matches->clear();
                            m_status->setText(tr("Search failed: %1").arg(text(*m_error)));
                        }
                        else
                            m_status->setText(tr("Studies found: %1.").arg(m_matches->size()));
                        showMatches();
                        emit searchFinished();
                    });
}

void PacsDialog::showMatches()
{
    m_results->setRowCount(0);
    for (const dicom::StudyMatch& match : *m_matches)
    {
        const int row = m_results->rowCount();
        m_results->insertRow(row);
        const QStringList cells{text(match.patientName), text(match.patientId), isoDate(match.studyDate),
                                text(match.studyDescription), text(match.accessionNumber), text(match.modalities),
                                match.seriesCount < 0 ? QString() : QString::number(match.seriesCount)};
        for (int column = 0; column < cells.size(); ++column)
            m_results->setItem(row, column, new QTableWidgetItem(cells[column]));
        m_results->item(row, 0)->setData(Qt::UserRole, text(match.studyInstanceUid));
    }
    m_results->resizeColumnsToContents();
    if (m_results->rowCount() > 0)
        m_results->selectRow(0);
}

bool PacsDialog::isBusy() const
{
    return m_watcher.isRunning();
}

QString PacsDialog::statusText() const
{
    return m_status->text();
}

QString PacsDialog::selectedStudyUid() const
{
    const QList<QTableWidgetItem*> selected = m_results->selectedItems();
    return selected.isEmpty() ? QString() : m_results->item(selected.first()->row(), 0)->data(Qt::UserRole).toString();
}

QString PacsDialog::selectedStudyLabel() const
{
    const QList<QTableWidgetItem*> selected = m_results->selectedItems();
    if (selected.isEmpty())
        return {};
    const int row = selected.first()->row();
    return tr("%1, %2").arg(m_results->item(row, 3)->text(), m_results->item(row, 2)->text());
}

void PacsDialog::updateButtons()
{
    const bool busy = isBusy();
    m_echo->setEnabled(!busy);
    m_search->setEnabled(!busy);
    m_retrieve->setEnabled(!busy && !selectedStudyUid().isEmpty());
}

} // namespace vsim::gui
