#pragma once

// The language of the texts VascuSim writes for people (issue 20, item 7): the workstation's choice (gui
// Languages.h), and a report's own language (`vascusim-cli report --language`, the workstation's Export Report
// dialog). The catalogues (translations/*.ts) are compiled into this library as :/i18n/vascusim_<code>.qm; the
// libraries' localized() texts and localizedNumber() marks (core Localized.h) come from them.

#include <memory>
#include <string>
#include <vector>

class QTranslator;

namespace vsim {
class ThreadTextLanguage;
}

namespace vsim::app {

/// Routes core's localized() through Qt's installed translators (QCoreApplication::translate) and sets the decimal
/// mark of `code` (a textLanguages() code or a Qt locale name: "de" writes 3,5).
void useQtTranslations(const std::string& code = "en");

/// The languages of the catalogues and the English source: "en", "de", "zh_CN".
std::vector<std::string> textLanguages();

/// While alive, this thread's localized() texts and numbers are in `code`'s language, whatever the application's:
/// `code` is a textLanguages() code or a compiled catalogue file (*.qm: a translation in progress, the tests'
/// pseudo-locale; numbers keep the '.'). The report is built and rendered inside one. Throws vsim::Error for
/// another code, a file that is not a catalogue, or when this build lacks the catalogue.
class ScopedTextLanguage
{
public:
    explicit ScopedTextLanguage(const std::string& code);
    ~ScopedTextLanguage();
    ScopedTextLanguage(const ScopedTextLanguage&) = delete;
    ScopedTextLanguage& operator=(const ScopedTextLanguage&) = delete;

private:
    std::unique_ptr<QTranslator> m_catalogue; // none for English
    std::unique_ptr<ThreadTextLanguage> m_scope;
};

} // namespace vsim::app
