// The 3D view's colour legends write their numbers in the reader's decimal mark (issue 20, item 7): VTK prints
// tick labels with printf, which keeps the '.', so the view labels its legends itself (FieldScene's labelLegend).
// A long title (a run's status and averaging window, in any language) stays within the view, broken into lines
// (TitleLines.h): VTK centres it over the bar and clips it at the view's edge, and "TAWSS (Pa), averaged over
// 2.0-4.0 ms; grey: no value" lost its start in the blood-flow player's 570-pixel view.

#include "vsim/core/TriangleMesh.h"
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

    void longTitlesStayWithinTheView_data()
    {
        QTest::addColumn<QString>("title");
        QTest::addColumn<int>("width");
        QTest::newRow("en") << "TAWSS (Pa), averaged over 2.0-4.0 ms; grey: no value" << 570;
        QTest::newRow("en, narrow") << "speed (m/s), frame 3 / 5, time 0.002011 s, STOPPED EARLY" << 300;
        QTest::newRow("de") << QString::fromUtf8("mittlerer Wanddruck (Pa), gemittelt über 2,0-4,0 ms; grau: kein Wert")
                            << 570;
        QTest::newRow("zh_CN") << QString::fromUtf8("TAWSS（Pa），在 2.0-4.0 ms 上平均；灰色：无值") << 400;
    }

    // On both legends (the surface's on the left, the particles' on the right), every line of the title lies
    // within the view, and the lines hold the whole title (only the spaces at the breaks dropped).
    void longTitlesStayWithinTheView()
    {
        QFETCH(QString, title);
        QFETCH(int, width);
        viz::VolumeView3D view;
        view.resize(width, 260);
        view.show();
        QVERIFY(QTest::qWaitForWindowExposed(&view));
        VolumeGeometry geometry;
        geometry.dims = {8, 8, 8};
        RealVolume field(geometry);
        for (std::size_t n = 0; n < field.size(); ++n)
            field.data()[n] = 1.0f;
        view.showFieldVolume(field, 0.0, 1.5, title);
        TriangleMesh surface;
        surface.points = {{0, 0, 0}, {10, 0, 0}, {0, 10, 0}};
        surface.triangles = {{0, 1, 2}};
        surface.pointFields["tawss_pa"] = {0.0, 1.0, 2.0};
        view.showFieldSurface(surface, "tawss_pa", 0.0, 2.0, title);
        const auto withoutSpaces = [](QString text) { return text.remove(' ').remove('\n'); };
        for (bool onSurface : {false, true})
        {
            const QStringList lines = view.legendTitleLines(onSurface);
            QVERIFY2(lines.size() >= 2, qPrintable(lines.join(" | ")));
            QVERIFY2(view.legendTitleWithinView(onSurface), qPrintable(lines.join(" | ")));
            QCOMPARE(withoutSpaces(lines.join('\n')), withoutSpaces(title));
        }
        const QString output = qEnvironmentVariable("VSIM_TEST_OUTPUT");
        if (!output.isEmpty() && QDir().mkpath(output + "/viz-legend"))
            QVERIFY(view.grabFramebuffer().save(output + "/viz-legend/title-" + QTest::currentDataTag() + ".png"));
    }
};

QTEST_MAIN(TestLegend)
#include "tst_legend.moc"
