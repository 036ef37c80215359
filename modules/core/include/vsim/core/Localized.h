#pragma once

// Texts people read, in their language (issue 20, item 7), from libraries that do not link Qt: a text is written
// in English as localized("Context", "English text") and the application installs a localizer that looks it up
// in its catalogues (app/common TextLanguage.h: Qt's translators, translations/*.ts). Without one, the English
// comes back. lupdate finds the calls (-tr-function-alias translate+=localized), so the context and the text must
// be string literals at the call.

#include <functional>
#include <string>
#include <vector>

namespace vsim {

/// Looks up `english` under `context`; returns the translation or the English.
using Localizer = std::string (*)(const char* context, const char* english);

/// Installs the localizer (nullptr: English). Call before threads that report texts start.
void setLocalizer(Localizer localizer);

/// `english` in the reader's language.
std::string localized(const char* context, const char* english);

/// For texts kept English where they are stored (attributes, metrics.json) and shown to people in their language:
/// localized() when `forPeople`, else the English. Name the instance `localized` so that lupdate reads its calls:
///     const LocalizedWhen localized{forPeople};  ...  localized("vsim::RunStatus", "converged")
struct LocalizedWhen
{
    bool forPeople = false;
    std::string operator()(const char* context, const char* english) const;
    /// localizedNumber() when `forPeople`, else the number as printed.
    std::string number(std::string printed) const;
};

/// A text whose literal lupdate reads elsewhere (a parameter table's label, from translations/ParameterTexts.cpp),
/// looked up under `context` like localized().
std::string localizedText(const char* context, const std::string& english);

/// Sets the decimal mark of the installed language for localizedNumber(): '.' (English, Chinese) or ',' (German).
void setDecimalMark(char mark);

/// A number printed with a '.' (printf) in the reader's decimal mark: "3.5" stays in English, "3,5" in German.
std::string localizedNumber(std::string printed);

/// While alive, the texts localized() looks up on this thread and the decimal mark of localizedNumber() come from
/// `lookup` and `decimalMark` instead of the installed language: a report written in a language other than the
/// workstation's, on its own thread (app/common TextLanguage.h: ScopedTextLanguage). Scopes nest.
class ThreadTextLanguage
{
public:
    using Lookup = std::function<std::string(const char* context, const char* english)>;
    ThreadTextLanguage(Lookup lookup, char decimalMark);
    ~ThreadTextLanguage();
    ThreadTextLanguage(const ThreadTextLanguage&) = delete;
    ThreadTextLanguage& operator=(const ThreadTextLanguage&) = delete;

    /// The innermost scope alive on this thread, or nullptr.
    static const ThreadTextLanguage* current();
    std::string lookup(const char* context, const char* english) const { return m_lookup(context, english); }
    char decimalMark() const { return m_decimalMark; }

private:
    Lookup m_lookup;
    char m_decimalMark;
    const ThreadTextLanguage* m_outer;
};

/// `pattern` with %1 ... %9 replaced by `arguments` in order, in one pass (an argument holding "%2" stays as it
/// is); a translation may move the placeholders.
std::string withArguments(const std::string& pattern, const std::vector<std::string>& arguments);

} // namespace vsim
