// The report module on a report with every kind of block: the PDF (A4 and Letter, fonts embedded, the metrics'
// text with units found by pdftotext, pages rendered), the DICOM Encapsulated PDF read back with DCMTK (the given
// Study Instance UID, a new series, the PDF bytes intact, no patient name when anonymized), the metrics as CSV and
// JSON, the printed number format, and bad input refused with a message.

#include "vsim/core/Error.h"
#include "vsim/report/EncapsulatedPdf.h"
#include "vsim/report/MetricsExport.h"
#include "vsim/report/PdfReport.h"

#include <QGuiApplication>
#include <QProcess>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QtTest>

#include <dcmtk/dcmdata/dcdeftag.h>
#include <dcmtk/dcmdata/dcfilefo.h>
#include <dcmtk/dcmdata/dcuid.h>
#include <nlohmann/json.hpp>

#include <cmath>

using namespace vsim;

namespace {

report::Report sampleReport()
{
    report::Report r;
    r.header.patientName = "DOE JANE";
    r.header.patientId = "PID-4711";
    r.header.studyDate = "2026-11-22";
    r.header.softwareVersion = "VascuSim test";
    r.header.reportDate = "2026-11-22T12:00:00Z";
    report::Section aaa{"aaa", "AAA rupture-risk review", {}};
    aaa.blocks.push_back(report::MetricTable{"Geometry",
                                             {report::metric("max_diameter_mm", "Maximum diameter", 55.0123, "mm"),
                                              report::metric("peak_rupture_index", "Peak rupture index", 0.43712, ""),
                                              report::metric("tumour_fraction", "Drug reaching the tumour, a label "
                                                                                "long enough to wrap in its cell",
                                                             6.3811, "%")}});
    aaa.blocks.push_back(report::Paragraph{"A paragraph of text that says what the figures mean, long enough to wrap "
                                           "over more than one line of the page so that wrapping is exercised."});
    report::Plot plot;
    plot.caption = "Diameter along the centerline";
    plot.xLabel = "Distance [mm]";
    plot.yLabel = "Diameter [mm]";
    report::PlotSeries series{"diameter", {}};
    for (int i = 0; i <= 100; ++i)
        series.points.emplace_back(i, 20.0 + 35.0 * std::exp(-0.002 * (i - 50) * (i - 50)));
    plot.series.push_back(series);
    plot.references = {{"55 mm", 55.0}, {"50 mm", 50.0}};
    aaa.blocks.push_back(plot);
    QImage picture(400, 300, QImage::Format_RGB888);
    picture.fill(QColor(30, 120, 200));
    aaa.blocks.push_back(report::Figure{"A picture", picture});
    report::Table table{"Branches", {"Segment", "Flow [ml/min]"}, {}};
    for (int i = 0; i < 90; ++i) // longer than a page: the header repeats
        table.rows.push_back({std::to_string(i), report::formatMetric(0.01 * i)});
    aaa.blocks.push_back(table);
    r.sections.push_back(aaa);
    r.notRun = {"Surgical smoke: no smoke run."};
    return r;
}

QString run(const QString& program, const QStringList& arguments)
{
    QProcess process;
    process.start(program, arguments);
    process.waitForFinished(60000);
    return QString::fromUtf8(process.readAllStandardOutput());
}

} // namespace

class ReportTest : public QObject
{
    Q_OBJECT

private slots:
    void numbersPrintWithFourDigits()
    {
        QCOMPARE(report::formatMetric(55.0123), std::string("55.01"));
        QCOMPARE(report::formatMetric(0.43712), std::string("0.4371"));
        QCOMPARE(report::formatMetric(1401.3), std::string("1401"));
        QCOMPARE(report::formatMetric(2.5e-5), std::string("2.500e-05"));
        QCOMPARE(report::formatMetric(std::nan("")), std::string("n/a"));
    }

    void figuresAreRoundedToTheirUnitsPrecision()
    {
        // Issue 14: diameters 0.1 mm (1 mm in the clinical summary), stresses 1 kPa, times 0.1 s, shares 0.1 %.
        QCOMPARE(report::formatMetric(55.009, "mm"), std::string("55.0"));
        QCOMPARE(report::formatMetric(55.009, "mm", 0), std::string("55"));
        QCOMPARE(report::formatMetric(312.64, "kPa"), std::string("313"));
        QCOMPARE(report::formatMetric(0.000243527, "s"), std::string("0.0"));
        QCOMPARE(report::formatMetric(6.3811, "%"), std::string("6.4"));
        QCOMPARE(report::formatMetric(120.0, "mmHg"), std::string("120"));
        QCOMPARE(report::formatMetric(10.4349, "MPa"), std::string("10.43"));
        QCOMPARE(report::formatMetric(0.43712, ""), std::string("0.437"));
        QCOMPARE(report::formatMetric(16.0, ""), std::string("16"));      // a count
        QCOMPARE(report::formatMetric(1.2345, "ml/min"), std::string("1.23"));
        QCOMPARE(report::formatMetric(1234.5, "kg/m3"), std::string("1234")); // %.0f rounds half to even
        QCOMPARE(report::formatMetric(-0.04, "mm"), std::string("0.0"));
    }

    void pdfHasEveryMetricWithItsUnit()
    {
        if (QStandardPaths::findExecutable("pdftotext").isEmpty())
            QSKIP("poppler-utils (pdftotext) is not installed: scripts/install-deps.sh installs it");
        QTemporaryDir folder;
        const report::Report r = sampleReport();
        for (auto [size, points] : {std::pair{report::PageSize::A4, "595 x 842"}, std::pair{report::PageSize::Letter, "612 x 792"}})
        {
            const QString file = folder.filePath(size == report::PageSize::A4 ? "a4.pdf" : "letter.pdf");
            report::writePdf(r, file.toStdString(), size);
            const QString info = run("pdfinfo", {file});
            QVERIFY2(info.contains(points), qPrintable(info));
            const int pages = info.section("Pages:", 1).trimmed().section('\n', 0, 0).toInt();
            QVERIFY2(pages >= 2, qPrintable(info)); // the long table goes over a page
            const QString text = run("pdftotext", {"-raw", file, "-"}).simplified();
            for (const auto& [section, m] : r.metrics())
            {
                const QString printed = QString::fromStdString(m.text + (m.unit.empty() ? "" : " " + m.unit));
                QVERIFY2(text.contains(printed), qPrintable(printed));
            }
            QVERIFY(text.contains("planning support only"));
            QVERIFY(text.contains("Analyses not run"));
            QVERIFY(text.contains("Surgical smoke: no smoke run."));
            QCOMPARE(text.count("Flow [ml/min]"), pages - 1); // the table's header on each page it spans
            // Every font embedded.
            const QString fonts = run("pdffonts", {file});
            const QStringList rows = fonts.split('\n', Qt::SkipEmptyParts).mid(2);
            QVERIFY(!rows.isEmpty());
            for (const QString& row : rows)
                QVERIFY2(row.contains(" yes "), qPrintable(fonts));
        }
    }

    // Chinese in a report (a patient's name, a segment named by the user, a translated heading): drawn with a CJK
    // font (Debian's fonts-noto-cjk through Qt's font fallback), the font embedded, the text extractable.
    void chineseTextIsEmbedded()
    {
        if (QStandardPaths::findExecutable("pdftotext").isEmpty())
            QSKIP("poppler-utils (pdftotext) is not installed: scripts/install-deps.sh installs it");
        QTemporaryDir folder;
        report::Report r = sampleReport();
        r.header.patientName = "张伟";
        r.sections.front().title = "腹主动脉瘤破裂风险评估";
        r.sections.front().blocks.push_back(report::Table{"肝动脉", {"段", "名称"}, {{"3", "肝右动脉"}}});
        const QString file = folder.filePath("chinese.pdf");
        report::writePdf(r, file.toStdString(), report::PageSize::A4);
        const QString text = run("pdftotext", {"-raw", file, "-"});
        // Known limit: Qt's ToUnicode map gives a glyph that two code points share the first of them, so the
        // drawn 风 extracts as the radical ⻛ (U+2EDB); the page shows the right character.
        for (const char* expected : {"张伟", "腹主动脉瘤破裂", "险评估", "肝右动脉"})
            QVERIFY2(text.contains(QString::fromUtf8(expected)), expected);
        const QString fonts = run("pdffonts", {file});
        QVERIFY2(fonts.contains("NotoSansCJK"), qPrintable(fonts));
        QVERIFY2(QFileInfo(file).size() < 400000, "the CJK fonts embedded as subsets, not whole");
        for (const QString& row : fonts.split('\n', Qt::SkipEmptyParts).mid(2))
            QVERIFY2(row.contains(" yes "), qPrintable(fonts));
    }

    void encapsulatedPdfReadsBack()
    {
        QTemporaryDir folder;
        const QByteArray pdf = report::renderPdf(sampleReport());
        QVERIFY(pdf.startsWith("%PDF"));
        report::DocumentIdentity identity;
        identity.studyInstanceUid = "1.2.826.0.1.3680043.8.498.1";
        identity.patientName = "DOE^JANE";
        identity.patientId = "PID-4711";
        const std::string file = folder.filePath("report.dcm").toStdString();
        const std::string series = report::writeEncapsulatedPdf(pdf, identity, file);
        DcmFileFormat format;
        QVERIFY(format.loadFile(file.c_str()).good());
        DcmDataset& data = *format.getDataset();
        OFString value;
        QVERIFY(data.findAndGetOFString(DCM_SOPClassUID, value).good());
        QCOMPARE(std::string(value.c_str()), std::string(UID_EncapsulatedPDFStorage));
        QVERIFY(data.findAndGetOFString(DCM_StudyInstanceUID, value).good());
        QCOMPARE(std::string(value.c_str()), identity.studyInstanceUid);
        QVERIFY(data.findAndGetOFString(DCM_SeriesInstanceUID, value).good());
        QCOMPARE(std::string(value.c_str()), series);
        QVERIFY(series != identity.studyInstanceUid);
        QVERIFY(data.findAndGetOFString(DCM_PatientName, value).good());
        QCOMPARE(std::string(value.c_str()), identity.patientName);
        const Uint8* bytes = nullptr;
        unsigned long length = 0;
        QVERIFY(data.findAndGetUint8Array(DCM_EncapsulatedDocument, bytes, &length).good());
        QVERIFY(length == std::size_t(pdf.size()) || length == std::size_t(pdf.size()) + 1);
        QCOMPARE(QByteArray(reinterpret_cast<const char*>(bytes), pdf.size()), pdf);

        // Anonymized: the name and ID given are written as given (the caller anonymizes), Burned In Annotation NO.
        identity.patientName = "ANONYMIZED";
        identity.patientId = "ANONYMIZED";
        identity.identifiesPatient = false;
        const std::string anonymous = folder.filePath("anonymous.dcm").toStdString();
        report::writeEncapsulatedPdf(pdf, identity, anonymous);
        DcmFileFormat second;
        QVERIFY(second.loadFile(anonymous.c_str()).good());
        QVERIFY(second.getDataset()->findAndGetOFString(DCM_BurnedInAnnotation, value).good());
        QCOMPARE(std::string(value.c_str()), std::string("NO"));
        QVERIFY(second.getDataset()->findAndGetOFString(DCM_PatientName, value).good());
        QCOMPARE(std::string(value.c_str()), std::string("ANONYMIZED"));
        QVERIFY(second.getDataset()->findAndGetOFString(DCM_PatientIdentityRemoved, value).good());
        QCOMPARE(std::string(value.c_str()), std::string("YES"));
    }

    void metricsExportAsCsvAndJson()
    {
        const report::Report r = sampleReport();
        const std::string csv = report::metricsCsv(r);
        QVERIFY(csv.rfind("section,key,label,value,unit,text\n", 0) == 0);
        QVERIFY(csv.find("aaa,max_diameter_mm,Maximum diameter,55.012300000000003,mm,55.0\n") != std::string::npos);
        QVERIFY(csv.find("\"Drug reaching the tumour, a label long enough to wrap in its cell\"") != std::string::npos);
        const auto json = nlohmann::json::parse(report::metricsJson(r));
        QCOMPARE(json.at("format").get<std::string>(), std::string("vascusim-report-metrics"));
        QCOMPARE(json.at("metrics").size(), std::size_t(3));
        QCOMPARE(json.at("metrics")[0].at("value").get<double>(), 55.0123);
        QCOMPARE(json.at("metrics")[0].at("unit").get<std::string>(), std::string("mm"));
        QCOMPARE(json.at("not_run").size(), std::size_t(1));
    }

    void badInputIsRefused()
    {
        try
        {
            report::pageSizeFromName("a5");
            QFAIL("a5 was accepted");
        }
        catch (const Error& error)
        {
            QVERIFY(std::string(error.what()).find("a4 or letter") != std::string::npos);
        }
        QVERIFY_THROWS_EXCEPTION(Error, report::writePdf(sampleReport(), "/nonexistent-folder/report.pdf"));
        QVERIFY_THROWS_EXCEPTION(Error, report::writeEncapsulatedPdf(QByteArray(), {}, "/tmp/never.dcm"));
        QVERIFY_THROWS_EXCEPTION(Error, report::writeText("x", "/nonexistent-folder/metrics.csv"));
    }
};

int main(int argc, char** argv)
{
    qputenv("QT_QPA_PLATFORM", "offscreen"); // fonts and painting without a display
    QGuiApplication application(argc, argv);
    ReportTest test;
    return QTest::qExec(&test, argc, argv);
}

#include "tst_report.moc"
