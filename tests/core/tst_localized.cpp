// core Localized.h without Qt's catalogues: a thread's own text language (a report in a language other than the
// workstation's, built on its own thread) overrides the installed one on that thread only, nests, and ends with
// its scope; numbers take the decimal mark of the language in force; texts kept English where they are stored
// keep the '.'.

#include "vsim/core/Localized.h"
#include "vsim/core/RunStatus.h"

#include <QtTest>

#include <cctype>
#include <string>
#include <thread>

using namespace vsim;

namespace {

std::string upper(const char*, const char* english)
{
    std::string text = english;
    for (char& c : text)
        c = char(std::toupper(static_cast<unsigned char>(c)));
    return text;
}

std::string german(const char*, const char* english)
{
    return std::string(english) == "converged" ? "konvergiert" : english;
}

} // namespace

class TestLocalized : public QObject
{
    Q_OBJECT
private slots:
    void cleanup()
    {
        setLocalizer(nullptr);
        setDecimalMark('.');
    }

    void numbersTakeTheInstalledMark()
    {
        QCOMPARE(localizedNumber("3.5"), std::string("3.5"));
        setDecimalMark(',');
        QCOMPARE(localizedNumber("3.5"), std::string("3,5"));
        QCOMPARE(localizedNumber("1.2e-05"), std::string("1,2e-05"));
        QCOMPARE(localizedNumber("n/a"), std::string("n/a"));
        QCOMPARE(LocalizedWhen{false}.number("3.5"), std::string("3.5")); // stored: the '.' stays
        QCOMPARE(LocalizedWhen{true}.number("3.5"), std::string("3,5"));
    }

    void aThreadLanguageOverridesOnItsThreadOnly()
    {
        setLocalizer(&upper);
        QCOMPARE(localized("Test", "wall"), std::string("WALL"));
        std::string inScope, nested, afterNested, otherThread, afterScope;
        {
            const ThreadTextLanguage report(&german, ',');
            inScope = localized("vsim::RunStatus", "converged") + " " + localizedNumber("0.25");
            {
                const ThreadTextLanguage english([](const char*, const char* text) { return std::string(text); }, '.');
                nested = localized("vsim::RunStatus", "converged") + " " + localizedNumber("0.25");
            }
            afterNested = localized("vsim::RunStatus", "converged");
            std::thread([&] { otherThread = localized("Test", "wall") + " " + localizedNumber("0.25"); }).join();
        }
        afterScope = localized("Test", "wall");
        QCOMPARE(inScope, std::string("konvergiert 0,25"));
        QCOMPARE(nested, std::string("converged 0.25"));
        QCOMPARE(afterNested, std::string("konvergiert"));
        QCOMPARE(otherThread, std::string("WALL 0.25")); // the installed language, not the report's
        QCOMPARE(afterScope, std::string("WALL"));
        QVERIFY(ThreadTextLanguage::current() == nullptr);
    }

    void runStatusNumbersForPeopleOnly()
    {
        RunStatus status;
        status.recordSolve(100, 2.5e-3, 1e-6, 100);
        const ThreadTextLanguage report(&german, ',');
        const std::string shown = status.convergenceText(true), stored = status.convergenceText(false);
        QVERIFY2(shown.find("2,5e-03") != std::string::npos && shown.find("1,0e-06") != std::string::npos, shown.c_str());
        QVERIFY2(stored.find("2.5e-03") != std::string::npos && stored.find("2,5") == std::string::npos, stored.c_str());
    }
};

QTEST_GUILESS_MAIN(TestLocalized)
#include "tst_localized.moc"
