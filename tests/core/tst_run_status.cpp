// RunStatus's convergence text (core RunStatus.h): converged runs say so; unconverged ones count the solves above
// their tolerance and name the iteration cap only for the solves that reached it (a solve that stalled or broke
// down below the cap did not end "at the cap"); the count at the cap survives the study's records.

#include "vsim/core/RunStatus.h"

#include <QtTest>

using namespace vsim;

class TestRunStatus : public QObject
{
    Q_OBJECT
private slots:
    void convergedRunsSaySo()
    {
        RunStatus status;
        status.recordSolve(12, 1e-9, 1e-8, 100);
        QVERIFY(status.converged());
        QCOMPARE(QString::fromStdString(status.convergenceText()), QString("converged"));
    }

    void theCapOnlyForTheSolvesThatReachedIt()
    {
        RunStatus allAtCap;
        allAtCap.recordSolve(100, 3e-3, 1e-6, 100);
        allAtCap.recordSolve(100, 2e-3, 1e-6, 100);
        QCOMPARE(allAtCap.solvesAtCap, 2L);
        QVERIFY2(allAtCap.convergenceText().find("2 of 2 solves ended above their tolerance at the 100-iteration cap") !=
                     std::string::npos,
                 allAtCap.convergenceText().c_str());

        RunStatus stalled; // stopped at 40 iterations by a stall: not at the cap
        stalled.recordSolve(40, 3e-3, 1e-6, 100);
        stalled.recordSolve(5, 1e-7, 1e-6, 100);
        QCOMPARE(stalled.solvesAtCap, 0L);
        const std::string text = stalled.convergenceText();
        QVERIFY2(text.find("1 of 2 solves ended above their tolerance, worst") != std::string::npos &&
                     text.find("cap") == std::string::npos,
                 text.c_str());

        RunStatus mixed;
        mixed.recordSolve(100, 3e-3, 1e-6, 100);
        mixed.recordSolve(60, 2e-3, 1e-6, 100);
        QVERIFY2(mixed.convergenceText().find("2 of 2 solves ended above their tolerance, 1 of them at the 100-iteration cap") !=
                     std::string::npos,
                 mixed.convergenceText().c_str());

        const RunStatus read = RunStatus::fromRecords(mixed.metrics(), mixed.attributes());
        QCOMPARE(read.solvesAtCap, 1L);
        QCOMPARE(read.convergenceText(), mixed.convergenceText());
    }
};

QTEST_GUILESS_MAIN(TestRunStatus)
#include "tst_run_status.moc"
