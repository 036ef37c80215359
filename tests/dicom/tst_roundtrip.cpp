// Phantom -> DICOM (every transfer syntax, classic and Enhanced multi-frame, signed and unsigned storage) -> scan
// -> import must give back the rendered HU voxel for voxel, and the geometry within 1e-3 mm.

#include "DicomFixtures.h"
#include "vsim/dicom/DicomImport.h"
#include "vsim/dicom/DicomScan.h"

#include <QProcess>
#include <QStandardPaths>
#include <QtTest>

#include <cmath>

using namespace vsim;
using namespace vsim::dicom;

namespace {

constexpr double kGeometryToleranceMm = 1e-3;

void compareGeometry(const VolumeGeometry& actual, const VolumeGeometry& expected)
{
    QCOMPARE(actual.dims, expected.dims);
    QVERIFY2((actual.origin - expected.origin).cwiseAbs().maxCoeff() < kGeometryToleranceMm, "origin");
    QVERIFY2((actual.spacing - expected.spacing).cwiseAbs().maxCoeff() < kGeometryToleranceMm, "spacing");
    QVERIFY2((actual.direction - expected.direction).cwiseAbs().maxCoeff() < 1e-6, "direction");
}

DicomVolume importOnly(const std::filesystem::path& folder)
{
    const DicomScanResult scan = scanDicom(folder);
    if (scan.series.size() != 1)
        throw Error("expected one series, found " + std::to_string(scan.series.size()));
    return importDicomSeries(scan.series.front());
}

} // namespace

class RoundTrip : public QObject
{
    Q_OBJECT

private slots:
    void everyTransferSyntax_data()
    {
        QTest::addColumn<QString>("syntax");
        QTest::addColumn<bool>("enhanced");
        QTest::addColumn<bool>("signedPixels");
        for (const char* syntax : {"explicit-le", "implicit-le", "jpeg-lossless", "jpeg-ls", "rle"})
        {
            QTest::addRow("%s", syntax) << QString(syntax) << false << false;
            QTest::addRow("%s enhanced multi-frame", syntax) << QString(syntax) << true << false;
        }
        QTest::addRow("explicit-le signed") << QString("explicit-le") << false << true;
        QTest::addRow("jpeg-ls signed") << QString("jpeg-ls") << false << true;
    }

    void everyTransferSyntax()
    {
        QFETCH(QString, syntax);
        QFETCH(bool, enhanced);
        QFETCH(bool, signedPixels);
        const auto folder = test::freshFolder("dicom-roundtrip", QString(QTest::currentDataTag()).replace(' ', '_'));
        CtSeriesDescription description;
        description.transferSyntax = transferSyntaxFromName(syntax.toStdString());
        description.enhancedMultiFrame = enhanced;
        description.signedPixels = signedPixels;
        const test::PhantomSeries phantom =
            test::writePhantomSeries(PhantomKind::Aaa, test::smallPhantomOptions(), folder, description);
        QCOMPARE(phantom.written.files.size(), enhanced ? std::size_t(1) : std::size_t(48));

        const DicomVolume imported = importOnly(folder);
        compareGeometry(imported.image.geometry(), phantom.geometry);
        QCOMPARE(test::differingVoxels(imported.image, phantom.truth), std::size_t(0));
        QVERIFY2(imported.warnings.empty(), imported.warnings.empty() ? "" : imported.warnings.front().c_str());
        QCOMPARE(imported.attributes.at("series_instance_uid"), phantom.written.seriesInstanceUid);
        QCOMPARE(imported.attributes.at("patient_name"), std::string("PHANTOM^VASCUSIM"));
        QCOMPARE(imported.attributes.at("modality"), std::string("CT"));
    }

    void lossyJpegStaysClose()
    {
        const auto folder = test::freshFolder("dicom-roundtrip", "jpeg-extended");
        CtSeriesDescription description;
        description.transferSyntax = TransferSyntax::JpegExtended;
        const test::PhantomSeries phantom =
            test::writePhantomSeries(PhantomKind::Aaa, test::smallPhantomOptions(), folder, description);
        const DicomVolume imported = importOnly(folder);
        compareGeometry(imported.image.geometry(), phantom.geometry);
        double sumError = 0.0;
        for (std::size_t i = 0; i < imported.image.size(); ++i)
            sumError += std::abs(imported.image.data()[i] - phantom.truth.data()[i]);
        const double meanError = sumError / double(imported.image.size());
        qInfo("JPEG extended (quality 90): mean absolute error %.2f HU", meanError);
        QVERIFY2(meanError < 15.0, "lossy JPEG must stay within 15 HU on average"); // noise is 20 HU
    }

    void jpeg2000ThroughGdcm()
    {
        const QString gdcmconv = QStandardPaths::findExecutable("gdcmconv");
        if (gdcmconv.isEmpty())
            QSKIP("gdcmconv (libgdcm-tools) is not installed");
        const auto folder = test::freshFolder("dicom-roundtrip", "jpeg2000-source");
        const auto converted = test::freshFolder("dicom-roundtrip", "jpeg2000");
        const test::PhantomSeries phantom =
            test::writePhantomSeries(PhantomKind::Stenosis, test::smallPhantomOptions(), folder);
        for (const auto& file : phantom.written.files)
        {
            const QString out = QString::fromStdString((converted / file.filename()).string());
            QCOMPARE(QProcess::execute(gdcmconv, {"--j2k", QString::fromStdString(file.string()), out}), 0);
        }
        const DicomScanResult scan = scanDicom(converted);
        QCOMPARE(scan.series.size(), std::size_t(1));
        QCOMPARE(scan.series.front().format().transferSyntaxUid, std::string("1.2.840.10008.1.2.4.90"));
        const DicomVolume imported = importDicomSeries(scan.series.front());
        compareGeometry(imported.image.geometry(), phantom.geometry);
        QCOMPARE(test::differingVoxels(imported.image, phantom.truth), std::size_t(0));
    }

    void seriesTableAndThumbnail()
    {
        const auto folder = test::freshFolder("dicom-roundtrip", "thumbnail");
        const test::PhantomSeries phantom =
            test::writePhantomSeries(PhantomKind::Aaa, test::smallPhantomOptions(), folder);
        const DicomScanResult scan = scanDicom(folder);
        const DicomSeries& series = scan.series.front();
        QCOMPARE(series.slices.size(), std::size_t(48));
        QCOMPARE(series.description, std::string("CTA arterial phase"));
        const std::vector<std::uint8_t> thumbnail = seriesThumbnail(series, 64);
        QCOMPARE(thumbnail.size(), std::size_t(64 * 64));
        // The middle slice of the aaa phantom: bright aorta near the centre, dark air in the corner.
        QVERIFY(thumbnail[32 * 64 + 32] > 150);
        QCOMPARE(int(thumbnail[0]), 0);
    }
};

QTEST_GUILESS_MAIN(RoundTrip)
#include "tst_roundtrip.moc"
