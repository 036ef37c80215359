#pragma once

// What a result field is called on screen: the solvers name their fields by keys with the unit in the name
// ("von_mises_kpa", stored so in the study); the workstation shows them as a title with the unit, in the reader's
// language ("von Mises stress (kPa)", "Von-Mises-Spannung (kPa)").

#include <QString>

namespace vsim::gui {

/// The title of field `key` with its unit, in the reader's language; a key it does not know comes back as it is.
QString fieldTitle(const QString& key);

} // namespace vsim::gui
