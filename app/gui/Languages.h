#pragma once

// The workstation's languages (issue 20, item 7): English (the source texts), German and Simplified Chinese,
// chosen under View > Language and kept in the settings; the choice applies from the next start, as in 3D
// Slicer.
#include <QString>
#include <QStringList>

namespace vsim::gui {

/// The language codes VascuSim is translated into besides its English source: "de", "zh_CN".
QStringList translatedLanguages();
/// A language's name in that language ("Deutsch", "简体中文", "English").
QString nativeLanguageName(const QString& code);
/// The chosen language from the settings: "en", "de", "zh_CN", or "" for the system's.
QString chosenLanguage();
void setChosenLanguage(const QString& code);
/// Installs VascuSim's translation of `code` ("" = the system locale) and Qt's own (standard buttons, file
/// dialogs) where the system has it, replacing any installed earlier; false when VascuSim has no translation
/// for it (English then shows).
bool installLanguage(const QString& code);
/// The language installLanguage() put in place: "de", "zh_CN", or "en" when none of VascuSim's was found.
QString installedLanguage();

} // namespace vsim::gui
