#include "ParameterForm.h"

#include <QCoreApplication>
#include <QCheckBox>
#include <QDialog>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QPushButton>
#include <QScrollArea>
#include <QSpinBox>
#include <QTabWidget>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>

namespace vsim::gui {

QString parameterText(const std::string& english)
{
    return QCoreApplication::translate("vsim::Parameters", english.c_str());
}

QString parameterToolTip(const ParameterSpec& spec)
{
    const QString unit = spec.unit.empty() ? QString() : " " + QString::fromStdString(spec.unit);
    const QString range = QCoreApplication::translate("vsim::gui::ParameterForm", "%1 to %2%3, default %4%3")
                              .arg(numberText(spec.minimum).c_str(), numberText(spec.maximum).c_str(), unit,
                                   numberText(spec.defaultValue).c_str());
    return QStringLiteral("<p><b>%1</b> (%2)</p><p>%3</p><p><tt>%4</tt></p>")
        .arg(parameterText(spec.label).toHtmlEscaped(), range.toHtmlEscaped(),
             parameterText(spec.description).toHtmlEscaped(), QString::fromStdString(spec.key));
}

ParameterForm::ParameterForm(const ParameterSet& initial, QWidget* parent)
    : ParameterForm(initial, AutomaticParameters{}, parent)
{
}

ParameterForm::ParameterForm(const ParameterSet& initial, const AutomaticParameters& automatic, QWidget* parent)
    : QWidget(parent), m_declared(initial.specs())
{
    auto* layout = new QVBoxLayout(this);
    std::map<std::string, QFormLayout*> groups;
    for (const ParameterSpec& spec : initial.specs())
    {
        QFormLayout*& form = groups[spec.group];
        if (!form)
        {
            auto* box = new QGroupBox(parameterText(spec.group), this);
            form = new QFormLayout(box);
            layout->addWidget(box);
        }
        QAbstractSpinBox* field = nullptr;
        const QString suffix = spec.unit.empty() ? QString() : " " + QString::fromStdString(spec.unit);
        if (spec.kind == ParameterSpec::Kind::Integer)
        {
            auto* box = new QSpinBox(this);
            box->setRange(int(spec.minimum), int(spec.maximum));
            box->setSuffix(suffix);
            field = box;
        }
        else
        {
            auto* box = new QDoubleSpinBox(this);
            // Enough decimals for the default and a hundredth of the range.
            const double step = (spec.maximum - spec.minimum) / 100.0;
            const int decimals = std::clamp(int(std::ceil(-std::log10(std::max(step, 1e-6)))), 0, 4);
            box->setDecimals(std::max(decimals, 2));
            box->setRange(spec.minimum, spec.maximum);
            box->setSingleStep(std::pow(10.0, -std::max(decimals, 1)));
            box->setSuffix(suffix);
            field = box;
        }
        field->setObjectName(QString::fromStdString(spec.key));
        field->setToolTip(parameterToolTip(spec));
        m_fields[spec.key] = field;
        if (std::find(automatic.keys.begin(), automatic.keys.end(), spec.key) == automatic.keys.end())
        {
            form->addRow(parameterText(spec.label), field);
            continue;
        }
        auto* row = new QWidget(this);
        auto* rowLayout = new QHBoxLayout(row);
        rowLayout->setContentsMargins(0, 0, 0, 0);
        auto* tick = new QCheckBox(tr("Automatic"), row);
        tick->setObjectName(QString::fromStdString(spec.key + "_automatic"));
        tick->setToolTip(tr("Chosen for the vessel when the run starts (recorded in its provenance); untick to give "
                            "this value, the default included."));
        rowLayout->addWidget(field, 1);
        rowLayout->addWidget(tick);
        form->addRow(parameterText(spec.label), row);
        m_automatic[spec.key] = tick;
        connect(tick, &QCheckBox::toggled, this, [this, key = spec.key](bool ticked) { setAutomatic(key, ticked); });
    }
    layout->addStretch();
    show(initial);
    for (const auto& [key, tick] : m_automatic)
    {
        tick->setChecked(automatic.ticked.count(key) > 0);
        setAutomatic(key, tick->isChecked());
    }
}

void ParameterForm::setAutomatic(const std::string& key, bool ticked)
{
    QAbstractSpinBox* field = m_fields.at(key);
    field->setEnabled(!ticked);
    if (!ticked)
        return;
    const double declared = m_declared.get(key);
    if (auto* integer = qobject_cast<QSpinBox*>(field))
        integer->setValue(int(std::lround(declared)));
    else if (auto* real = qobject_cast<QDoubleSpinBox*>(field))
        real->setValue(declared);
}

std::set<std::string> ParameterForm::automatic() const
{
    std::set<std::string> ticked;
    for (const auto& [key, tick] : m_automatic)
        if (tick->isChecked())
            ticked.insert(key);
    return ticked;
}

void ParameterForm::show(const ParameterSet& values)
{
    for (const auto& [key, field] : m_fields)
    {
        if (auto* integer = qobject_cast<QSpinBox*>(field))
            integer->setValue(int(std::lround(values.get(key))));
        else if (auto* real = qobject_cast<QDoubleSpinBox*>(field))
            real->setValue(values.get(key));
    }
}

ParameterSet ParameterForm::values() const
{
    ParameterSet result = m_declared;
    for (const auto& [key, field] : m_fields)
    {
        if (const auto* integer = qobject_cast<const QSpinBox*>(field))
            result.set(key, integer->value());
        else if (const auto* real = qobject_cast<const QDoubleSpinBox*>(field))
            result.set(key, real->value());
    }
    return result;
}

void ParameterForm::resetToDefaults()
{
    show(m_declared);
    for (const auto& [key, tick] : m_automatic)
        tick->setChecked(true);
}

bool editParametersInDialog(QWidget* parent, const QString& title, const std::vector<ParameterPage>& pages)
{
    QDialog dialog(parent);
    dialog.setWindowTitle(title);
    auto* layout = new QVBoxLayout(&dialog);
    auto* tabs = new QTabWidget(&dialog);
    std::vector<ParameterForm*> forms;
    for (const ParameterPage& page : pages)
    {
        auto* scroll = new QScrollArea(tabs);
        auto* form = new ParameterForm(*page.values, page.automatic ? *page.automatic : AutomaticParameters{}, scroll);
        scroll->setWidget(form);
        scroll->setWidgetResizable(true);
        tabs->addTab(scroll, page.title);
        forms.push_back(form);
    }
    layout->addWidget(tabs);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel |
                                             QDialogButtonBox::RestoreDefaults, &dialog);
    QObject::connect(buttons, &QDialogButtonBox::accepted, &dialog, &QDialog::accept);
    QObject::connect(buttons, &QDialogButtonBox::rejected, &dialog, &QDialog::reject);
    QObject::connect(buttons->button(QDialogButtonBox::RestoreDefaults), &QPushButton::clicked, &dialog,
                     [&] { forms[std::size_t(tabs->currentIndex())]->resetToDefaults(); });
    layout->addWidget(buttons);
    dialog.resize(560, 640);
    if (dialog.exec() != QDialog::Accepted)
        return false;
    for (std::size_t page = 0; page < pages.size(); ++page)
    {
        *pages[page].values = forms[page]->values();
        if (pages[page].automatic)
            pages[page].automatic->ticked = forms[page]->automatic();
    }
    return true;
}

} // namespace vsim::gui
