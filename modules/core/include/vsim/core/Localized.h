#pragma once

// Texts people read, in their language (issue 20, item 7), from libraries that do not link Qt: a text is written
// in English as localized("Context", "English text") and the application installs a localizer that looks it up
// in its catalogues (app/common TextLanguage.h: Qt's translators, translations/*.ts). Without one, the English
// comes back. lupdate finds the calls (-tr-function-alias translate+=localized), so the context and the text must
// be string literals at the call.

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
};

/// A text whose literal lupdate reads elsewhere (a parameter table's label, from translations/ParameterTexts.cpp),
/// looked up under `context` like localized().
std::string localizedText(const char* context, const std::string& english);

/// `pattern` with %1 ... %9 replaced by `arguments` in order, in one pass (an argument holding "%2" stays as it
/// is); a translation may move the placeholders.
std::string withArguments(const std::string& pattern, const std::vector<std::string>& arguments);

} // namespace vsim
