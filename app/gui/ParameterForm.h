#pragma once

#include "vsim/core/Parameters.h"

#include <QWidget>

#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

class QAbstractSpinBox;
class QCheckBox;

namespace vsim::gui {

/// A parameter table's label, group or description (Parameters.h) in the chosen language (context
/// "vsim::Parameters"; translations/ParameterTexts.cpp lists them for lupdate).
QString parameterText(const std::string& english);
/// A parameter field's tooltip: label, range with unit, default, the description and the --param key.
QString parameterToolTip(const ParameterSpec& spec);

/// Parameters a run chooses for its case unless the user gives them (the blood flow's Courant number, sound
/// speed...): each gets an "Automatic" tick beside its field. Ticked, the field shows the default, disabled, and
/// the run chooses; unticked, the field's value is given, whatever it is (the default included).
struct AutomaticParameters
{
    std::vector<std::string> keys;        ///< those the run may choose
    std::set<std::string> ticked;         ///< those it chooses now (a subset of keys)
};

/// A form built from parameter declarations (ParameterSpec): one group box per group, one spin box per
/// parameter with its unit, range and description (tooltip). Values are checked by the declarations' ranges.
class ParameterForm : public QWidget
{
    Q_OBJECT
public:
    explicit ParameterForm(const ParameterSet& initial, QWidget* parent = nullptr);
    ParameterForm(const ParameterSet& initial, const AutomaticParameters& automatic, QWidget* parent = nullptr);

    /// The values shown now (an automatic parameter's: its default).
    ParameterSet values() const;
    /// The automatic parameters ticked now.
    std::set<std::string> automatic() const;
    /// Puts every declared default back and ticks every automatic parameter.
    void resetToDefaults();

private:
    void show(const ParameterSet& values);
    void setAutomatic(const std::string& key, bool ticked);

    ParameterSet m_declared;
    std::map<std::string, QAbstractSpinBox*> m_fields;
    std::map<std::string, QCheckBox*> m_automatic;
};

/// One tab of editParametersInDialog: its title, the values it edits and, optionally, which of them a run may
/// choose (`automatic`; its ticks are written back with the values).
struct ParameterPage
{
    QString title;
    ParameterSet* values = nullptr;
    AutomaticParameters* automatic = nullptr;
};

/// A modal dialog with one tab per page; OK writes the edited values (and ticks) back. Returns whether the user
/// accepted.
bool editParametersInDialog(QWidget* parent, const QString& title, const std::vector<ParameterPage>& pages);

} // namespace vsim::gui
