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

/// A language's catalogue, loaded once and shared by the threads that write in it (the report's background thread
/// and its 3D snapshots on the GUI thread). `code` is a textLanguages() code or a compiled catalogue file (*.qm: a
/// translation in progress, the tests' pseudo-locale; numbers keep the '.'). Throws vsim::Error for another code,
/// a file that is not a catalogue, or when this build lacks the catalogue.
class TextLanguage
{
public:
    explicit TextLanguage(const std::string& code);

private:
    friend class ScopedTextLanguage;
    std::shared_ptr<const QTranslator> m_catalogue; // none for English
    char m_decimalMark = '.';
};

/// While alive, this thread's localized() texts and numbers are in `language`, whatever the application's. The
/// report is built and rendered inside one.
class ScopedTextLanguage
{
public:
    explicit ScopedTextLanguage(const TextLanguage& language);
    ~ScopedTextLanguage();
    ScopedTextLanguage(const ScopedTextLanguage&) = delete;
    ScopedTextLanguage& operator=(const ScopedTextLanguage&) = delete;

private:
    std::shared_ptr<const QTranslator> m_catalogue; // kept alive while the scope looks texts up in it
    std::unique_ptr<ThreadTextLanguage> m_scope;
};

} // namespace vsim::app
