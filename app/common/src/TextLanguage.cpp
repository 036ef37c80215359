// TextLanguage.h: Qt's translation lookup behind core's localizer, and the catalogues compiled in (:/i18n).
#include "vsim/app/TextLanguage.h"

#include "vsim/core/Error.h"
#include "vsim/core/Localized.h"

#include <QCoreApplication>
#include <QLocale>
#include <QTranslator>

#include <algorithm>
#include <memory>

namespace vsim::app {
namespace {

std::string qtLookup(const char* context, const char* english)
{
    return QCoreApplication::translate(context, english).toStdString();
}

} // namespace

void useQtTranslations()
{
    setLocalizer(&qtLookup);
}

std::vector<std::string> textLanguages()
{
    return {"en", "de", "zh_CN"};
}

void installTextLanguage(const std::string& code)
{
    const std::vector<std::string> known = textLanguages();
    const bool file = code.size() > 3 && code.compare(code.size() - 3, 3, ".qm") == 0;
    if (!file && std::find(known.begin(), known.end(), code) == known.end())
        throw Error("unknown language '" + code + "'; use en, de, zh_CN or a catalogue file (.qm)");
    if (!QCoreApplication::instance())
        throw Error("a language needs a Qt application");
    static std::unique_ptr<QTranslator> installed;
    if (installed)
        QCoreApplication::removeTranslator(installed.get());
    installed.reset();
    useQtTranslations();
    if (code == "en")
        return;
    auto translator = std::make_unique<QTranslator>();
    if (file && !translator->load(QString::fromStdString(code)))
        throw Error("not a translation catalogue (.qm)", {{"file", code}});
    if (!file && !translator->load(QLocale(QString::fromStdString(code)), "vascusim", "_", ":/i18n"))
        throw Error("the " + code + " catalogue is missing from this build (:/i18n/vascusim_" + code + ".qm)");
    QCoreApplication::installTranslator(translator.get());
    installed = std::move(translator);
}

} // namespace vsim::app
