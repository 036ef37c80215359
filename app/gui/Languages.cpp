// Languages.h: the translators from :/i18n (built from translations/*.ts) and Qt's own catalogue.
#include "Languages.h"

#include "vsim/app/TextLanguage.h"

#include <QApplication>
#include <QLibraryInfo>
#include <QLocale>
#include <QSettings>
#include <QTranslator>

#include <memory>

namespace vsim::gui {
namespace {

const char* const kLanguageKey = "language";

/// The translators installed now (ours and Qt's), owned here for the application's life.
std::unique_ptr<QTranslator>& installed(int which)
{
    static std::unique_ptr<QTranslator> translators[2];
    return translators[which];
}

void replaceTranslator(int which, std::unique_ptr<QTranslator> translator)
{
    if (installed(which))
        QApplication::removeTranslator(installed(which).get());
    installed(which) = std::move(translator);
    if (installed(which))
        QApplication::installTranslator(installed(which).get());
}

} // namespace

QStringList translatedLanguages()
{
    return {"de", "zh_CN"};
}

QString nativeLanguageName(const QString& code)
{
    if (code == "de")
        return QStringLiteral("Deutsch");
    if (code == "zh_CN")
        return QStringLiteral("简体中文");
    return QStringLiteral("English");
}

QString installedLanguage()
{
    for (const QString& code : translatedLanguages())
        if (QLocale().language() == QLocale(code).language())
            return code;
    return QStringLiteral("en");
}

QString chosenLanguage()
{
    return QSettings().value(kLanguageKey, QString()).toString();
}

void setChosenLanguage(const QString& code)
{
    QSettings().setValue(kLanguageKey, code);
}

bool installLanguage(const QString& code)
{
    const QLocale locale = code.isEmpty() ? QLocale() : QLocale(code);
    auto ours = std::make_unique<QTranslator>();
    const bool found = locale.language() != QLocale::English && ours->load(locale, "vascusim", "_", ":/i18n");
    replaceTranslator(0, found ? std::move(ours) : nullptr);
    auto qt = std::make_unique<QTranslator>();
    const bool qtFound =
        found && qt->load(locale, "qtbase", "_", QLibraryInfo::path(QLibraryInfo::TranslationsPath));
    replaceTranslator(1, qtFound ? std::move(qt) : nullptr);
    QLocale::setDefault(found ? locale : QLocale(QLocale::English)); // numbers and dates follow the texts
    // The libraries' texts (the report, definitions) through the same catalogues, with the language's decimal mark.
    app::useQtTranslations(installedLanguage().toStdString());
    return found;
}

} // namespace vsim::gui
