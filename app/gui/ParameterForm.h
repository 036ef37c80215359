#pragma once

#include "vsim/core/Parameters.h"

#include <QWidget>

#include <map>
#include <string>
#include <utility>
#include <vector>

class QAbstractSpinBox;

namespace vsim::gui {

/// A parameter table's label, group or description (Parameters.h) in the chosen language (context
/// "vsim::Parameters"; translations/ParameterTexts.cpp lists them for lupdate).
QString parameterText(const std::string& english);
/// A parameter field's tooltip: label, range with unit, default, the description and the --param key.
QString parameterToolTip(const ParameterSpec& spec);

/// A form built from parameter declarations (ParameterSpec): one group box per group, one spin box per
/// parameter with its unit, range and description (tooltip). Values are checked by the declarations' ranges.
class ParameterForm : public QWidget
{
    Q_OBJECT
public:
    explicit ParameterForm(const ParameterSet& initial, QWidget* parent = nullptr);

    /// The values shown now.
    ParameterSet values() const;
    /// Puts every declared default back.
    void resetToDefaults();

private:
    void show(const ParameterSet& values);

    ParameterSet m_declared;
    std::map<std::string, QAbstractSpinBox*> m_fields;
};

/// A modal dialog with one tab per (title, parameters) page; OK writes the edited values back. Returns whether
/// the user accepted.
bool editParametersInDialog(QWidget* parent, const QString& title,
                            const std::vector<std::pair<QString, ParameterSet*>>& pages);

} // namespace vsim::gui
