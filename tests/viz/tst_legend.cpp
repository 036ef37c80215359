// The 3D view's colour legends write their numbers in the reader's decimal mark (issue 20, item 7): VTK prints
// tick labels with printf, which keeps the '.', so the view labels its legends itself (FieldScene's labelLegend).

#include "vsim/viz/VolumeView3D.h"

#include <QDir>
#include <QLocale>
#include <QtTest>

using namespace vsim;

class TestLegend : public QObject
{
    Q_OBJECT
private slots:
    void numbersInTheReadersMark_data()
    {
        QTest::addColumn<QString>("locale");
        QTest::addColumn<QStringList>("labels");
        QTest::newRow("de") << "de_DE" << QStringList{"0", "0,375", "0,75", "1,13", "1,5"};
        QTest::newRow("en") << "en_US" << QStringList{"0", "0.375", "0.75", "1.13", "1.5"};
        QTest::newRow("zh_CN") << "zh_CN" << QStringList{"0", "0.375", "0.75", "1.13", "1.5"};
    }

    // A field volume over [0, 1.5] m/s: five numbers from the low end to the high, three significant digits.
    void numbersInTheReadersMark()
    {
        QFETCH(QString, locale);
        QFETCH(QStringList, labels);
        const QLocale before;
        QLocale::setDefault(QLocale(locale));
        {
            viz::VolumeView3D view;
            view.resize(400, 300);
            view.show();
            QVERIFY(QTest::qWaitForWindowExposed(&view));
            QVERIFY(view.legendLabels().isEmpty());
            VolumeGeometry geometry;
            geometry.dims = {8, 8, 8};
            RealVolume field(geometry);
            for (std::size_t n = 0; n < field.size(); ++n)
                field.data()[n] = float(1.5 * double(n) / double(field.size() - 1));
            view.showFieldVolume(field, 0.0, 1.5, "speed (m/s)");
            QCOMPARE(view.legendLabels(), labels);
            QVERIFY(view.legendLabels(true).isEmpty()); // no coloured surface
            // The picture, kept as test output for a reader to look at.
            const QString output = qEnvironmentVariable("VSIM_TEST_OUTPUT");
            if (!output.isEmpty() && QDir().mkpath(output + "/viz-legend"))
                QVERIFY(view.grabFramebuffer().save(output + "/viz-legend/legend-" + QTest::currentDataTag() + ".png"));
        }
        QLocale::setDefault(before);
    }
};

QTEST_MAIN(TestLegend)
#include "tst_legend.moc"
