// core StoredText.h: texts stored in English (warnings, stop reasons) read back in the reader's language by
// matching them against the patterns that wrote them (translations/ErrorTexts.cpp, compiled into vsim_core).
// Without Qt's catalogues: a test localizer translates the catalogue's own texts by a mark or a small dictionary.

#include "vsim/core/Localized.h"
#include "vsim/core/RunStatus.h"
#include "vsim/core/StoredText.h"

#include <QtTest>

#include <cstddef>
#include <map>
#include <set>
#include <string>

namespace vsim::detail {
extern const char* const kLibraryTexts[];
extern const std::size_t kLibraryTextCount;
} // namespace vsim::detail

using namespace vsim;

namespace {

const std::set<std::string>& catalogue()
{
    static const std::set<std::string> texts(detail::kLibraryTexts, detail::kLibraryTexts + detail::kLibraryTextCount);
    return texts;
}

/// Marks every catalogue text (as a translator that knows them all would translate them): "<<text>>".
std::string marked(const char* context, const char* english)
{
    return std::string(context) == "vsim::Error" && catalogue().count(english) ? "<<" + std::string(english) + ">>"
                                                                              : std::string(english);
}

std::string german(const char*, const char* english)
{
    static const std::map<std::string, std::string> words = {
        {"stopped early: %1", "vorzeitig beendet: %1"},
        {"the fracture entropy reached %1 (end condition %2)", "die Bruchentropie erreichte %1 (Endbedingung %2)"},
        {"the series has a single slice", "die Serie hat nur eine Schicht"},
        {"the catheter fills %1 % of the lumen at the tip", "der Katheter füllt %1 % des Lumens an der Spitze"},
        {"the injection (%1 ml/min) is at least the vessel's own flow at the tip (%2 ml/min)",
         "die Injektion (%1 ml/min) ist mindestens der eigene Fluss des Gefäßes an der Spitze (%2 ml/min)"},
        {"wedged catheter: %1; the injection refluxes or stops the blood flow at the tip",
         "verkeilter Katheter: %1; die Injektion fließt zurück oder stoppt den Blutfluss an der Spitze"},
        {"stopped by a guard", "von einem Wächter gestoppt"},
    };
    const auto found = words.find(english);
    return found == words.end() ? english : found->second;
}

/// The catalogue's patterns storedTextForPeople() recognises: placeholders apart, at least 8 literal characters.
bool recognisable(const std::string& text, int& placeholders)
{
    std::size_t literal = 0;
    placeholders = 0;
    bool lastWasPlaceholder = false;
    for (std::size_t i = 0; i < text.size(); ++i)
        if (text[i] == '%' && i + 1 < text.size() && text[i + 1] >= '1' && text[i + 1] <= '9')
        {
            if (lastWasPlaceholder && i > 0)
                return false;
            placeholders = std::max(placeholders, text[i + 1] - '0');
            lastWasPlaceholder = true;
            ++i;
        }
        else
        {
            ++literal;
            lastWasPlaceholder = false;
        }
    return placeholders > 0 && literal >= 8;
}

} // namespace

class TestStoredText : public QObject
{
    Q_OBJECT
private slots:
    void cleanup() { setLocalizer(nullptr); }

    void nestedPatternsAreReadInTheReadersLanguage()
    {
        // WallPipeline's warning around WallPathSolver's stop reason, as a study keeps it.
        const std::string stored = storedText(Pattern{
            "stopped early: %1",
            {storedText(Pattern{"the fracture entropy reached %1 (end condition %2)", {"8.14", "3.9"}})}});
        QCOMPARE(stored, std::string("stopped early: the fracture entropy reached 8.14 (end condition 3.9)"));
        const ThreadTextLanguage report(&german, ',');
        QCOMPARE(storedTextForPeople(stored),
                 std::string("vorzeitig beendet: die Bruchentropie erreichte 8,14 (Endbedingung 3,9)"));
        QCOMPARE(storedTextForPeople("the series has a single slice"), std::string("die Serie hat nur eine Schicht"));
    }

    void partsJoinedBySemicolonsAreReadOneByOne()
    {
        // BloodFlow's reasons for a wedged catheter: two texts joined by "; ", inside NetworkRun's warning.
        const std::string because =
            storedText(Pattern{"the injection (%1 ml/min) is at least the vessel's own flow at the tip (%2 ml/min)",
                               {"12.5", "10.25"}}) +
            "; " + storedText(Pattern{"the catheter fills %1 % of the lumen at the tip", {"85"}});
        const std::string stored = storedText(Pattern{
            "wedged catheter: %1; the injection refluxes or stops the blood flow at the tip", {because}});
        const ThreadTextLanguage report(&german, ',');
        QCOMPARE(storedTextForPeople(stored),
                 std::string("verkeilter Katheter: die Injektion (12,5 ml/min) ist mindestens der eigene Fluss des "
                             "Gefäßes an der Spitze (10,25 ml/min); der Katheter füllt 85 % des Lumens an der Spitze; "
                             "die Injektion fließt zurück oder stoppt den Blutfluss an der Spitze"));
    }

    void unknownTextsComeBackAsTheyAre()
    {
        const ThreadTextLanguage report(&german, ',');
        for (const std::string text : {"", "a file name 1.5.nrrd", "see: stopped early: the fracture entropy reached 1.5 (end condition 2.5)",
                                       "stopped early"})
            QCOMPARE(storedTextForPeople(text), text);
    }

    void runStatusStopMessageForPeople()
    {
        RunStatus status;
        status.stoppedBy = RunStatus::StoppedBy::Guard;
        status.stopMessage = storedText(Pattern{"the fracture entropy reached %1 (end condition %2)", {"8.14", "3.9"}});
        const ThreadTextLanguage report(&german, ',');
        QCOMPARE(status.stopText(true), std::string("von einem Wächter gestoppt: die Bruchentropie erreichte 8,14 "
                                                    "(Endbedingung 3,9)"));
        QCOMPARE(status.stopText(false),
                 std::string("stopped by a guard: the fracture entropy reached 8.14 (end condition 3.9)"));
    }

    /// Every pattern of the catalogue, filled, is recognised as itself: none is taken for a more general one.
    void everyPatternIsRecognisedAsItself()
    {
        setLocalizer(&marked);
        int checked = 0;
        QStringList wrong;
        for (const std::string& text : catalogue())
        {
            int placeholders = 0;
            if (!recognisable(text, placeholders))
                continue;
            std::vector<std::string> values;
            for (int k = 1; k <= placeholders; ++k)
                values.push_back("v" + std::to_string(k));
            const std::string stored = withArguments(text, values);
            const std::string read = storedTextForPeople(stored), expected = withArguments("<<" + text + ">>", values);
            if (read != expected)
                wrong << QString::fromStdString(text + "  ->  " + read);
            ++checked;
        }
        qInfo("%d patterns of %d catalogue texts read back as themselves", checked - int(wrong.size()),
              int(catalogue().size()));
        QVERIFY2(wrong.isEmpty(), qPrintable(wrong.join('\n')));
        QVERIFY(checked > 150);
    }
};

QTEST_GUILESS_MAIN(TestStoredText)
#include "tst_stored_text.moc"
