// TextLanguage.h: Qt's translation lookup behind core's localizer, and the catalogues compiled in (:/i18n).
#include "vsim/app/TextLanguage.h"

#include "vsim/core/Error.h"
#include "vsim/core/Localized.h"

#include <QCoreApplication>
#include <QLocale>
#include <QTranslator>

#include <algorithm>

namespace vsim::app {
namespace {

std::string qtLookup(const char* context, const char* english)
{
    return QCoreApplication::translate(context, english).toStdString();
}

bool isCatalogueFile(const std::string& code)
{
    return code.size() > 3 && code.compare(code.size() - 3, 3, ".qm") == 0;
}

char decimalMarkOf(const std::string& code)
{
    if (isCatalogueFile(code))
        return '.';
    const QString mark = QLocale(QString::fromStdString(code)).decimalPoint();
    return mark.size() == 1 && mark[0].unicode() < 128 ? char(mark[0].unicode()) : '.';
}

/// The catalogue of `code`, or nullptr for English.
std::unique_ptr<QTranslator> loadCatalogue(const std::string& code)
{
    const std::vector<std::string> known = textLanguages();
    const bool file = isCatalogueFile(code);
    if (!file && std::find(known.begin(), known.end(), code) == known.end())
        throw Error(Pattern{"unknown language '%1'; use en, de, zh_CN or a catalogue file (.qm)", {code}});
    if (code == "en")
        return nullptr;
    auto catalogue = std::make_unique<QTranslator>();
    if (file && !catalogue->load(QString::fromStdString(code)))
        throw Error("not a translation catalogue (.qm)", {{"file", code}});
    if (!file && !catalogue->load(QLocale(QString::fromStdString(code)), "vascusim", "_", ":/i18n"))
        throw Error(Pattern{"the %1 catalogue is missing from this build (:/i18n/vascusim_%2.qm)", {code, code}});
    return catalogue;
}

} // namespace

void useQtTranslations(const std::string& code)
{
    setLocalizer(&qtLookup);
    setDecimalMark(decimalMarkOf(code));
}

std::vector<std::string> textLanguages()
{
    return {"en", "de", "zh_CN"};
}

TextLanguage::TextLanguage(const std::string& code)
    : m_catalogue(loadCatalogue(code)), m_decimalMark(decimalMarkOf(code))
{
}

ScopedTextLanguage::ScopedTextLanguage(const TextLanguage& language) : m_catalogue(language.m_catalogue)
{
    const QTranslator* catalogue = m_catalogue.get();
    m_scope = std::make_unique<ThreadTextLanguage>(
        [catalogue](const char* context, const char* english) {
            const QString found = catalogue ? catalogue->translate(context, english) : QString();
            return found.isEmpty() ? std::string(english) : found.toStdString();
        },
        language.m_decimalMark);
}

ScopedTextLanguage::~ScopedTextLanguage() = default;

} // namespace vsim::app
