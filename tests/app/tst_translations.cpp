// Three languages (issue 20, item 7). A pseudo-locale run: a translator that brackets every text it is asked
// for is installed, the main window opens on a study, and every menu, action, dock, button, label, group,
// tab, header, tooltip and parameter form is read: a user-visible text without the brackets never went
// through tr(). Then the shipped German and Simplified Chinese catalogues: every parameter table's text is
// translated, the window built under each shows its menus in that language, and the Chinese glyphs come from
// a CJK font (no missing-glyph boxes), and the libraries' error messages come in the window's language. Marker
// phantom (MarkerPhantom.h); screenshots in test-output/gui-translations.
#include "DicomImportDialog.h"
#include "EndoscopePanel.h"
#include "GuiTestMain.h"
#include "HelpWindow.h"
#include "Languages.h"
#include "MainWindow.h"
#include "MarkerPhantom.h"
#include "ParameterForm.h"
#include "ReportExportDialog.h"
#include "TestOutput.h"
#include "ViewCapture.h"
#include "ViewLayout.h"
#include "vsim/app/ParameterCatalogue.h"
#include "vsim/core/Error.h"
#include "vsim/study/Study.h"
#include "vsim/viz/SliceView.h"

#include <QAbstractButton>
#include <QComboBox>
#include <QDockWidget>
#include <QFile>
#include <QGroupBox>
#include <QHeaderView>
#include <QLabel>
#include <QListWidget>
#include <QMenuBar>
#include <QRegularExpression>
#include <QTabBar>
#include <QTextBrowser>
#include <QTextLayout>
#include <QTranslator>
#include <QTreeWidget>

#include <filesystem>

using namespace vsim;

namespace {

const QString kOpen = QStringLiteral("\u27e6"), kClose = QStringLiteral("\u27e7");

/// The pseudo-locale: every text asked for comes back in brackets.
class PseudoTranslator : public QTranslator
{
public:
    QString translate(const char*, const char* source, const char*, int) const override
    {
        return kOpen + QString::fromUtf8(source) + kClose;
    }
    bool isEmpty() const override { return false; }
};

/// Texts a person reads that need no translation: empty, no letters (numbers, units after numbers,
/// punctuation), unit symbols, or rich text whose words all came from tr().
bool needsTranslation(QString text)
{
    text.remove(QRegularExpression("<[^>]*>")); // markup
    text.remove('&');
    if (text.contains(kOpen))
        return false;
    static const QRegularExpression wordy("[A-Za-z]{3,}");
    static const QRegularExpression unitOnly(
        "^\\s*[-+0-9.,:x×/ ]*\\s*(mm|ml|HU|s|ms|%|mm²|mmHg|MPa|kPa|°)?\\s*$");
    return text.contains(wordy) && !unitOnly.match(text).hasMatch();
}

/// The user-visible texts of a widget tree outside tr(), each with where it was found.
QStringList untranslatedTexts(QWidget* root, const QStringList& dataTexts)
{
    QStringList found;
    auto check = [&](const QString& where, const QString& text)
    {
        if (needsTranslation(text) && !dataTexts.contains(text))
            found << where + ": \"" + text + "\"";
    };
    QList<QWidget*> widgets = root->findChildren<QWidget*>();
    widgets.prepend(root);
    for (QWidget* widget : widgets)
    {
        const QString where =
            QString::fromLatin1(widget->metaObject()->className()) + " " + widget->objectName();
        check(where + " tooltip", widget->toolTip());
        check(where + " whatsThis", widget->whatsThis());
        if (widget->isWindow())
            check(where + " title", widget->windowTitle());
        if (auto* label = qobject_cast<QLabel*>(widget))
            check(where, label->text());
        if (auto* button = qobject_cast<QAbstractButton*>(widget))
            check(where, button->text());
        if (auto* group = qobject_cast<QGroupBox*>(widget))
            check(where, group->title());
        if (auto* dock = qobject_cast<QDockWidget*>(widget))
            check(where, dock->windowTitle());
        if (auto* tabs = qobject_cast<QTabBar*>(widget))
            for (int i = 0; i < tabs->count(); ++i)
                check(where + " tab", tabs->tabText(i));
        if (auto* header = qobject_cast<QHeaderView*>(widget); header && header->model())
            for (int i = 0; i < header->count(); ++i)
            {
                check(where + " header", header->model()->headerData(i, header->orientation()).toString());
                check(where + " header tooltip",
                      header->model()->headerData(i, header->orientation(), Qt::ToolTipRole).toString());
            }
        if (auto* list = qobject_cast<QListWidget*>(widget))
            for (int i = 0; i < list->count(); ++i)
            {
                check(where + " item", list->item(i)->text());
                check(where + " item tooltip", list->item(i)->toolTip());
            }
        if (auto* tree = qobject_cast<QTreeWidget*>(widget))
            for (int i = 0; i < tree->topLevelItemCount();
                 ++i) // the groups; the artifacts under them are data
                for (int column = 0; column < tree->columnCount(); ++column)
                    check(where + " item", tree->topLevelItem(i)->text(column));
        // A language is named in its own language (as every workstation's language list does): the report's
        // language choice too.
        if (auto* combo = qobject_cast<QComboBox*>(widget); combo && combo->objectName() != "reportLanguage")
            for (int i = 0; i < combo->count(); ++i)
                check(where + " choice", combo->itemText(i));
        for (QAction* action : widget->actions())
        {
            // The languages (above); recent studies are paths.
            if (action->isSeparator() || action->objectName().startsWith("language_") ||
                action->text().contains('/'))
                continue;
            const QString actionWhere = where + " action " + action->objectName();
            check(actionWhere, action->text());
            check(actionWhere + " tooltip", action->toolTip());
            check(actionWhere + " statusTip", action->statusTip());
            if (action->menu())
                check(actionWhere + " menu", action->menu()->title());
        }
    }
    found.removeDuplicates();
    return found;
}

/// The study every window here opens: the marker CT.
QString markerStudy()
{
    const std::filesystem::path bundle =
        std::filesystem::path(test::outputFolder("gui-translations").toStdString()) / "marker.vsim";
    std::filesystem::remove_all(bundle);
    study::Study study = study::Study::create(bundle, "marker");
    study.addImage(test::markerPhantom().image, "marker CT", {});
    study.save();
    return QString::fromStdString(bundle.string());
}

/// Shows `window` at 1400 x 900 on the marker study; false when it does not open.
bool showOnMarkerStudy(gui::MainWindow& window)
{
    window.resize(1400, 900);
    window.show();
    return QTest::qWaitForWindowExposed(&window) && window.openStudy(markerStudy()) && test::waitForTask(window, 30000);
}

/// Whether every character of `text` drawn in `font` has a glyph (none is the missing-glyph box).
bool allGlyphsFound(const QString& text, const QFont& font)
{
    QTextLayout layout(text, font);
    layout.beginLayout();
    layout.createLine();
    layout.endLayout();
    for (const QGlyphRun& run : layout.glyphRuns())
        for (quint32 glyph : run.glyphIndexes())
            if (glyph == 0)
                return false;
    return !layout.glyphRuns().isEmpty();
}

/// The width (pixels) of the overlay text in a view's top-right corner (window / level), from a capture: the
/// overlay's yellow pixels in the top-right third of the top band.
int topRightTextWidth(QWidget* view)
{
    const QImage shot = gui::captureView(view);
    int left = shot.width(), right = -1;
    for (int y = 0; y < std::min(40, shot.height()); ++y)
        for (int x = shot.width() * 2 / 3; x < shot.width(); ++x)
        {
            const QColor c = shot.pixelColor(x, y);
            if (c.red() > 150 && c.green() > 110 && c.blue() < 100)
                left = std::min(left, x), right = std::max(right, x);
        }
    return right - left + 1;
}

} // namespace

class TestTranslations : public QObject
{
    Q_OBJECT

    int m_germanOverlayWidth = 0;

private slots:
    void pseudoLocaleFindsNoTextOutsideTr()
    {
        PseudoTranslator pseudo;
        QApplication::installTranslator(&pseudo);
        gui::MainWindow window;
        QVERIFY(showOnMarkerStudy(window));
        // The study's own words (its name, the series description) are data, not interface.
        const QStringList data{"marker", "marker CT"};
        QStringList found = untranslatedTexts(&window, data);
        for (const app::ParameterTable& table : app::parameterCatalogue())
        {
            gui::ParameterForm form{ParameterSet(table.specs)};
            for (const QString& text : untranslatedTexts(&form, data))
                found << QString::fromStdString(table.name) + " form: " + text;
        }
        gui::ReportExportDialog report("report.pdf", &window);
        found << untranslatedTexts(&report, data);
        gui::DicomImportDialog dicom(&window);
        found << untranslatedTexts(&dicom, data);
        gui::EndoscopePanel endoscope; // made when first opened
        found << untranslatedTexts(&endoscope, data);
        QApplication::removeTranslator(&pseudo);
        for (const QString& text : found)
            qWarning("outside tr(): %s", qPrintable(text));
        QVERIFY2(found.isEmpty(), qPrintable(QString::number(found.size()) + " texts outside tr()"));
    }

    void catalogueComplete_data()
    {
        QTest::addColumn<QString>("language");
        for (const QString& code : gui::translatedLanguages())
            QTest::newRow(qPrintable(code)) << code;
    }

    // Every label, group and description of every parameter table has a translation (the catalogue is built
    // from the same tables the forms show, so a new parameter without one fails here).
    void catalogueComplete()
    {
        QFETCH(QString, language);
        QTranslator translator;
        QVERIFY(translator.load(QLocale(language), "vascusim", "_", ":/i18n"));
        QStringList missing;
        for (const app::ParameterTable& table : app::parameterCatalogue())
            for (const ParameterSpec& spec : table.specs)
                for (const std::string* text : {&spec.label, &spec.group, &spec.description})
                    if (!text->empty() && translator.translate("vsim::Parameters", text->c_str()).isEmpty())
                        missing << QString::fromStdString(table.name + " " + spec.key + ": " + *text);
        for (const QString& text : missing)
            qWarning("no %s translation: %s", qPrintable(language), qPrintable(text));
        QVERIFY2(missing.isEmpty(), qPrintable(QString::number(missing.size()) + " untranslated"));
    }

    // Item 6: every parameter field's tooltip names its unit, range, default and --param key.
    void everyParameterTooltipHasItsUnitAndRange()
    {
        int fields = 0;
        for (const app::ParameterTable& table : app::parameterCatalogue())
        {
            gui::ParameterForm form{ParameterSet(table.specs)};
            for (const ParameterSpec& spec : table.specs)
            {
                const auto* field = form.findChild<QWidget*>(QString::fromStdString(spec.key));
                QVERIFY2(field, spec.key.c_str());
                const QString tip = field->toolTip();
                const QString where = QString::fromStdString(table.name + " " + spec.key) + ": " + tip;
                QVERIFY2(tip.contains(QString::fromStdString(spec.key)) && tip.contains("default"), qPrintable(where));
                QVERIFY2(tip.contains(QString::fromStdString(numberText(spec.maximum))), qPrintable(where));
                if (!spec.unit.empty())
                    QVERIFY2(tip.contains(QString::fromStdString(spec.unit).toHtmlEscaped()), qPrintable(where));
                ++fields;
            }
        }
        qInfo("%d parameter fields, each tooltip with its unit, range, default and key", fields);
    }

    // The guide in each language has the English guide's sections and pictures (a section added to one and not
    // the others fails here; a language's own picture where it has one, and every picture there), and the English
    // guide opens where there is no translation.
    void guideInEachLanguageMatchesTheEnglish()
    {
        const auto structure = [](const QString& page) {
            QFile file(page);
            if (!file.open(QIODevice::ReadOnly))
                return QStringList{"missing " + page};
            const QString html = QString::fromUtf8(file.readAll());
            QStringList parts;
            static const QRegularExpression marks("(id|href|src)=\"([^\"]+)\"");
            // A language's own picture (pictures/de/x.png) stands where the English page has pictures/x.png.
            static const QRegularExpression ownPicture("^pictures/[a-zA-Z_]+/");
            for (auto match = marks.globalMatch(html); match.hasNext();)
            {
                const auto found = match.next();
                QString value = found.captured(2);
                if (found.captured(1) == "src")
                {
                    if (!QFile::exists(":/help/" + value))
                        return QStringList{"missing picture " + value + " of " + page};
                    value.replace(ownPicture, "pictures/");
                }
                parts << found.captured(1) + "=" + value;
            }
            return parts;
        };
        const QStringList english = structure(":/help/guide.html");
        QVERIFY(english.size() > 20);
        for (const QString& code : gui::translatedLanguages())
        {
            const QString page = gui::guidePage(QLocale(code));
            QCOMPARE(page, "qrc:/help/guide_" + code + ".html");
            QCOMPARE(structure(page.mid(3)), english);
        }
        QCOMPARE(gui::guidePage(QLocale(QLocale::French)), QString("qrc:/help/guide.html"));
    }

    void windowInEachLanguage_data()
    {
        QTest::addColumn<QString>("language");
        QTest::addColumn<QString>("file");
        QTest::addColumn<QString>("view");
        QTest::addColumn<QString>("guideTitle");
        QTest::addColumn<QString>("fileKey");
        QTest::newRow("de") << "de"
                            << "&Datei"
                            << "&Ansicht"
                            << "VascuSim-Benutzerhandbuch"
                            << "Datei";
        QTest::newRow("zh_CN") << "zh_CN" << QString::fromUtf8("文件(&F)") << QString::fromUtf8("视图(&V)")
                               << QString::fromUtf8("VascuSim 用户指南") << QString::fromUtf8("文件");
    }

    // View > Language keeps the choice; the next window (as at the next start) speaks it, and its text
    // renders.
    void windowInEachLanguage()
    {
        QFETCH(QString, language);
        QFETCH(QString, file);
        QFETCH(QString, view);
        QFETCH(QString, guideTitle);
        QFETCH(QString, fileKey);
        {
            gui::MainWindow chooser;
            QAction* choice = chooser.findChild<QAction*>("language_" + language);
            QVERIFY(choice);
            choice->trigger();
        }
        QCOMPARE(gui::chosenLanguage(), language);
        QVERIFY(gui::installLanguage(gui::chosenLanguage()));
        gui::MainWindow window;
        QVERIFY(showOnMarkerStudy(window));
        const QList<QAction*> menus = window.menuBar()->actions();
        QCOMPARE(menus.first()->text(), file);
        QVERIFY(std::any_of(menus.begin(), menus.end(), [&](QAction* menu) { return menu->text() == view; }));
        for (QAction* menu : menus)
            QVERIFY2(allGlyphsFound(menu->text(), window.menuBar()->font()), qPrintable(menu->text()));
        // The views' overlays drawn by VTK: "F 700  L 200" and "窗宽 700  窗位 200" (a font without the
        // Chinese glyphs would leave only "700  200", narrower than the German).
        const int overlayWidth = topRightTextWidth(window.views()->sliceView(viz::SliceOrientation::Axial));
        qInfo("%s: window/level overlay %d px wide", qPrintable(language), overlayWidth);
        if (language == "de")
            m_germanOverlayWidth = overlayWidth;
        else
            QVERIFY2(overlayWidth > m_germanOverlayWidth + 20, "the Chinese overlay lost its glyphs");
        const QImage shot = gui::captureWindow(&window);
        QVERIFY(shot.save(test::outputFolder("gui-translations") + "/window-" + language + ".png"));
        // Help > User Guide opens the guide in that language.
        gui::HelpWindow help(&window);
        QCOMPARE(help.browser()->documentTitle(), guideTitle);
        // The libraries' error messages as the window shows them: a literal message, its context key, and a
        // pattern's words around its value, in that language; what() stays English (logs, the CLI).
        const Error plain("the skeleton is empty: run the skeleton step first", {{"file", "walk.vsim"}});
        const Error pattern(Pattern{"the study has no artifact '%1'", {"run-3"}});
        const QString shown = QString::fromStdString(plain.textForPeople());
        QVERIFY2(!shown.contains("skeleton is empty") && shown.contains(fileKey + ": walk.vsim"), qPrintable(shown));
        QVERIFY(std::string(plain.what()).find("the skeleton is empty") == 0);
        const QString filled = QString::fromStdString(pattern.messageForPeople());
        QVERIFY2(filled.contains("'run-3'") && !filled.contains("has no artifact"), qPrintable(filled));
        QCOMPARE(pattern.message(), std::string("the study has no artifact 'run-3'"));
        window.close();
        QVERIFY(gui::installLanguage("en") ==
                false); // English is the source: no catalogue, the texts as written
        gui::setChosenLanguage({});
    }
};

VSIM_GUI_TEST_MAIN(TestTranslations)
#include "tst_translations.moc"
