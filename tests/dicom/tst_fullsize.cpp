// Full size (label bench): the 512 x 512 x 400 aaa phantom as the CLI writes it (`vascusim-cli phantom aaa`)
// comes back from DICOM voxel for voxel (mean error 0 HU) on the phantom's exact grid, for the uncompressed and
// a compressed transfer syntax. Prints the timings as JSON.

#include "TestOutput.h"
#include "vsim/dicom/DicomImport.h"
#include "vsim/dicom/DicomScan.h"
#include "vsim/dicom/PhantomRender.h"
#include "vsim/dicom/PhantomWriter.h"

#include <QElapsedTimer>
#include <QtTest>

using namespace vsim;
using namespace vsim::dicom;

class FullSize : public QObject
{
    Q_OBJECT

private slots:
    void aaaRoundTrip_data()
    {
        QTest::addColumn<QString>("syntax");
        QTest::newRow("explicit-le") << "explicit-le";
        QTest::newRow("jpeg-ls") << "jpeg-ls";
    }

    void aaaRoundTrip()
    {
        QFETCH(QString, syntax);
        const auto out = std::filesystem::path(test::outputFolder("dicom-fullsize").toStdString()) / syntax.toStdString();
        std::filesystem::remove_all(out);
        const PhantomOptions options; // the CLI defaults: 512 x 512 x 400, 0.7 x 0.7 x 1.0 mm, 20 HU, seed 1
        CtSeriesDescription description = phantomSeriesDescription(PhantomKind::Aaa);
        description.transferSyntax = transferSyntaxFromName(syntax.toStdString());
        QElapsedTimer timer;
        timer.start();
        const PhantomFiles files = writePhantom(PhantomKind::Aaa, options, description, out);
        const qint64 writeMs = timer.restart();
        const DicomScanResult scan = scanDicom(files.dicomFolder);
        const DicomVolume imported = importDicomSeries(*scan.defaultSeries());
        const qint64 importMs = timer.elapsed();

        const CtVolume truth = renderPhantomCt(buildPhantomModel(PhantomKind::Aaa, options), stackOf(files.geometry), options);
        QVERIFY(imported.image.geometry().isClose(files.geometry, 1e-6));
        double sumError = 0;
        std::size_t differing = 0;
        for (std::size_t i = 0; i < truth.size(); ++i)
        {
            const int error = imported.image.data()[i] - truth.data()[i];
            sumError += std::abs(error);
            differing += error != 0;
        }
        std::printf("{\"case\": \"aaa_512x512x400_%s\", \"write_s\": %.2f, \"scan_import_s\": %.2f, "
                    "\"mean_abs_error_hu\": %.3f, \"differing_voxels\": %zu}\n",
                    qPrintable(syntax), writeMs / 1000.0, importMs / 1000.0, sumError / double(truth.size()), differing);
        QCOMPARE(differing, std::size_t(0));
        QCOMPARE(imported.image.geometry().dims, (std::array<int, 3>{512, 512, 400}));
    }
};

QTEST_GUILESS_MAIN(FullSize)
#include "tst_fullsize.moc"
