#pragma once

// The language of the texts VascuSim writes for people (issue 20, item 7): the workstation's choice (gui
// Languages.h) or `vascusim-cli report --language`. The catalogues (translations/*.ts) are compiled into this
// library as :/i18n/vascusim_<code>.qm; the libraries' localized() texts (core Localized.h) are looked up in them.

#include <string>
#include <vector>

namespace vsim::app {

/// Routes core's localized() through Qt's installed translators (QCoreApplication::translate).
void useQtTranslations();

/// The languages of the catalogues and the English source: "en", "de", "zh_CN".
std::vector<std::string> textLanguages();

/// Installs the catalogue of `code` (textLanguages()) into the running Qt application, replacing one installed
/// here before ("en": none), and useQtTranslations(). `code` may also name a compiled catalogue file (*.qm, e.g.
/// a translation in progress, or the tests' pseudo-locale). Throws vsim::Error for another code, a file that is
/// not a catalogue, without a Qt application, or when this build lacks the catalogue.
void installTextLanguage(const std::string& code);

} // namespace vsim::app
