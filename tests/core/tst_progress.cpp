// Progress: fractions map through sub-ranges; cancellation is seen at the next report.
#include "vsim/core/Error.h"
#include "vsim/core/Progress.h"

#include <QtTest>

#include <vector>

class TestProgress : public QObject
{
    Q_OBJECT
private slots:
    void subRangesMapOntoTheParentRange()
    {
        std::vector<double> seen;
        vsim::CancellationToken token;
        const vsim::Progress progress([&](double fraction, const std::string&) { seen.push_back(fraction); }, token);
        const vsim::Progress second = progress.subRange(0.5, 1.0);
        second.report(0.5);
        second.subRange(0.0, 0.5).report(1.0);
        progress.report(2.0); // clamped to 1
        QCOMPARE(seen.size(), std::size_t(3));
        QCOMPARE(seen[0], 0.75);
        QCOMPARE(seen[1], 0.75);
        QCOMPARE(seen[2], 1.0);
    }

    void cancellationThrowsAtTheNextReport()
    {
        vsim::CancellationToken token;
        const vsim::Progress progress({}, token);
        progress.report(0.1);
        token.cancel();
        QVERIFY_THROWS_EXCEPTION(vsim::Cancelled, progress.report(0.2));
        QVERIFY_THROWS_EXCEPTION(vsim::Cancelled, progress.subRange(0, 0.5).throwIfCancelled());
    }
};

QTEST_APPLESS_MAIN(TestProgress)
#include "tst_progress.moc"
