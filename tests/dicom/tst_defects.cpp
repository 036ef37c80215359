// Hospital series are incomplete, tilted, unevenly spaced, mixed and damaged. Each defect is injected into a
// phantom series here; the import must name it and still give the phantom's volume and geometry.

#include "DicomFixtures.h"
#include "vsim/dicom/DicomImport.h"
#include "vsim/dicom/DicomScan.h"
#include "vsim/dicom/SeriesGeometry.h"

#include <dcmtk/config/osconfig.h>
#include <dcmtk/dcmdata/dcddirif.h>

#include <QtTest>

#include <cmath>
#include <fstream>
#include <random>

using namespace vsim;
using namespace vsim::dicom;
namespace fs = std::filesystem;

namespace {

bool hasWarning(const std::vector<std::string>& warnings, const std::string& part)
{
    for (const std::string& warning : warnings)
        if (warning.find(part) != std::string::npos)
            return true;
    return false;
}

std::string joined(const std::vector<std::string>& warnings)
{
    std::string text;
    for (const std::string& warning : warnings)
        text += warning + "; ";
    return text;
}

const DicomSeries& onlySeries(const DicomScanResult& scan)
{
    if (scan.series.size() != 1)
        throw Error("expected one series, found " + std::to_string(scan.series.size()));
    return scan.series.front();
}

/// Mean |a - b| over one slice.
double sliceMeanError(const CtVolume& a, const CtVolume& b, int k)
{
    const std::size_t perSlice = std::size_t(a.geometry().dims[0]) * a.geometry().dims[1];
    double sum = 0.0;
    for (std::size_t i = 0; i < perSlice; ++i)
        sum += std::abs(a.data()[k * perSlice + i] - b.data()[k * perSlice + i]);
    return sum / double(perSlice);
}

/// Contrast centroid (mm): voxels weighted by their HU above `background`, counting only voxels where
/// `covered` is not padding (partial-volume aware, so it does not jump with voxel-sized thresholding noise).
Eigen::Vector3d contrastCentroid(const CtVolume& volume, double background, const CtVolume& covered)
{
    const VolumeGeometry& g = volume.geometry();
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    double weight = 0;
    for (int k = 0; k < g.dims[2]; ++k)
        for (int j = 0; j < g.dims[1]; ++j)
            for (int i = 0; i < g.dims[0]; ++i)
                if (covered.at(i, j, k) != -1024 && volume.at(i, j, k) > background)
                {
                    const double w = volume.at(i, j, k) - background;
                    sum += w * g.indexToPatient(Eigen::Vector3d(i, j, k));
                    weight += w;
                }
    return weight > 0 ? Eigen::Vector3d(sum / weight) : Eigen::Vector3d::Constant(1e9);
}

void writeBytes(const fs::path& file, const std::string& bytes)
{
    std::ofstream(file, std::ios::binary) << bytes;
}

} // namespace

class Defects : public QObject
{
    Q_OBJECT

private slots:
    void missingSlicesAreInterpolated()
    {
        const auto folder = test::freshFolder("dicom-defects", "missing");
        const auto phantom = test::writePhantomSeries(PhantomKind::Aaa, test::smallPhantomOptions(0.0), folder);
        fs::remove(phantom.written.files[10]);
        fs::remove(phantom.written.files[30]);
        fs::remove(phantom.written.files[31]);
        const DicomVolume imported = importDicomSeries(onlySeries(scanDicom(folder)));
        QVERIFY2(hasWarning(imported.warnings, "3 missing slices"), joined(imported.warnings).c_str());
        QVERIFY(imported.image.geometry().isClose(phantom.geometry, 1e-3));
        for (int k : {0, 9, 11, 29, 32, 47})
            QCOMPARE(sliceMeanError(imported.image, phantom.truth, k), 0.0);
        for (int k : {10, 30, 31}) // filled from neighbours 8 mm away: close, not exact
            QVERIFY2(sliceMeanError(imported.image, phantom.truth, k) < 10.0, qPrintable(QString::number(k)));
    }

    void unevenSpacingIsResampled()
    {
        const auto folder = test::freshFolder("dicom-defects", "uneven");
        const PhantomOptions options = test::smallPhantomOptions(0.0);
        SliceStack stack = stackOf(phantomGeometry(options));
        for (std::size_t k = 20; k < stack.positions.size(); ++k)
            stack.positions[k].z() += 3.0; // one gap of 11 mm in a stack of 8 mm
        const auto phantom = test::writePhantomSeries(PhantomKind::Aaa, options, folder, {}, stack);
        const DicomVolume imported = importDicomSeries(onlySeries(scanDicom(folder)));
        QVERIFY2(hasWarning(imported.warnings, "uneven slice spacing"), joined(imported.warnings).c_str());
        const VolumeGeometry& grid = imported.image.geometry();
        QCOMPARE(grid.dims[2], 48);
        QVERIFY(std::abs(grid.spacing.z() - (47 * 8.0 + 3.0) / 47.0) < 1e-3);
        QVERIFY((grid.origin - phantom.geometry.origin).norm() < 1e-3);
        // Against the phantom rendered on the output grid: interpolation error only.
        const CtVolume reference = renderPhantomCt(phantom.model, stackOf(grid), options);
        double sum = 0;
        for (std::size_t i = 0; i < reference.size(); ++i)
            sum += std::abs(reference.data()[i] - imported.image.data()[i]);
        QVERIFY2(sum / double(reference.size()) < 10.0, "uneven stack resampled within 10 HU mean");
    }

    void gantryTiltIsCorrected()
    {
        const auto folder = test::freshFolder("dicom-defects", "tilt");
        PhantomOptions options = test::smallPhantomOptions(0.0);
        options.size = {128, 128, 64};
        options.spacing = {1.5, 1.5, 3.0};
        const VolumeGeometry axial = phantomGeometry(options);
        const auto phantom =
            test::writePhantomSeries(PhantomKind::Bifurcation, options, folder, {}, tiltedStack(axial, 15.0));
        const DicomVolume imported = importDicomSeries(onlySeries(scanDicom(folder)));
        QVERIFY2(hasWarning(imported.warnings, "gantry tilt of 15.00 degrees"), joined(imported.warnings).c_str());
        const VolumeGeometry& grid = imported.image.geometry();
        QVERIFY2((grid.direction - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff() < 1e-6, "axial grid");
        QVERIFY((grid.spacing - axial.spacing).cwiseAbs().maxCoeff() < 1e-6);
        // The vessels must sit where the phantom has them, within one voxel: compare the contrast centroid of
        // the corrected volume with that of the phantom rendered directly on the corrected grid, over the voxels
        // the tilted slices cover (the others are padding, -1024 HU; the noise-free phantom has no -1024).
        const CtVolume reference = renderPhantomCt(phantom.model, stackOf(grid), options);
        const Eigen::Vector3d shift =
            contrastCentroid(imported.image, 60, imported.image) - contrastCentroid(reference, 60, imported.image);
        qInfo("tilt-corrected contrast centroid off by (%.2f, %.2f, %.2f) mm", shift.x(), shift.y(), shift.z());
        QVERIFY((shift.cwiseAbs().array() < grid.spacing.array()).all());
        // Read as if untilted, the slices would put the vessels tan(15 deg) * z off: many voxels at the ends.
        const VolumeGeometry naive = phantom.truth.geometry();
        const CtVolume naiveReference = renderPhantomCt(phantom.model, stackOf(naive), options);
        CtVolume naiveVolume(naive, phantom.truth.buffer());
        const Eigen::Vector3d uncorrected =
            contrastCentroid(naiveVolume, 60, naiveVolume) - contrastCentroid(naiveReference, 60, naiveVolume);
        qInfo("without the correction: off by (%.2f, %.2f, %.2f) mm", uncorrected.x(), uncorrected.y(), uncorrected.z());
        QVERIFY(uncorrected.norm() > 2.0 * shift.norm());
    }

    void duplicatePositionsAreDropped()
    {
        const auto folder = test::freshFolder("dicom-defects", "duplicates");
        const auto phantom = test::writePhantomSeries(PhantomKind::Aaa, test::smallPhantomOptions(), folder);
        for (int k : {3, 4, 40})
            fs::copy_file(phantom.written.files[k], folder / ("DUP" + std::to_string(k)));
        const DicomVolume imported = importDicomSeries(onlySeries(scanDicom(folder)));
        QVERIFY2(hasWarning(imported.warnings, "3 slices at duplicate positions dropped"), joined(imported.warnings).c_str());
        QCOMPARE(test::differingVoxels(imported.image, phantom.truth), std::size_t(0));
    }

    void mixedSeriesInOneFolder()
    {
        const auto folder = test::freshFolder("dicom-defects", "mixed");
        PhantomOptions larger = test::smallPhantomOptions();
        larger.size[2] = 56;
        CtSeriesDescription second;
        second.fileNamePrefix = "SB";
        second.seriesNumber = 2;
        const auto aaa = test::writePhantomSeries(PhantomKind::Aaa, test::smallPhantomOptions(), folder);
        const auto stenosis = test::writePhantomSeries(PhantomKind::Stenosis, larger, folder, second);
        const DicomScanResult scan = scanDicom(folder);
        QCOMPARE(scan.series.size(), std::size_t(2));
        QCOMPARE(scan.defaultSeries()->seriesInstanceUid, stenosis.written.seriesInstanceUid); // more slices
        const DicomVolume picked = importDicomSeries(*scan.find(aaa.written.seriesInstanceUid));
        QCOMPARE(test::differingVoxels(picked.image, aaa.truth), std::size_t(0));
    }

    void localizerIsSkipped()
    {
        const auto folder = test::freshFolder("dicom-defects", "localizer");
        const auto phantom = test::writePhantomSeries(PhantomKind::Aaa, test::smallPhantomOptions(), folder);
        // A coronal scout in the same series, as scanners store it.
        CtSeriesDescription scout;
        scout.seriesInstanceUid = phantom.written.seriesInstanceUid;
        scout.studyInstanceUid = phantom.written.studyInstanceUid;
        scout.imageType = "ORIGINAL\\PRIMARY\\LOCALIZER";
        scout.fileNamePrefix = "LO";
        SliceStack coronal;
        coronal.columns = 96;
        coronal.rows = 48;
        coronal.columnSpacing = 3.5;
        coronal.rowSpacing = 8.0;
        coronal.xDirection = Eigen::Vector3d::UnitX();
        coronal.yDirection = -Eigen::Vector3d::UnitZ();
        coronal.positions = {Eigen::Vector3d(-166, 0, -100)};
        const CtVolume scoutPixels = renderPhantomCt(phantom.model, coronal, phantom.options);
        writeCtSeries(scoutPixels, coronal, scout, folder);
        const DicomScanResult scan = scanDicom(folder);
        QVERIFY2(hasWarning(scan.warnings, "1 localizer image skipped"), joined(scan.warnings).c_str());
        const DicomVolume imported = importDicomSeries(onlySeries(scan));
        QCOMPARE(test::differingVoxels(imported.image, phantom.truth), std::size_t(0));
    }

    void acquisitionsAreSplit()
    {
        const auto folder = test::freshFolder("dicom-defects", "acquisitions");
        PhantomOptions first = test::smallPhantomOptions();
        PhantomOptions second = first;
        second.seed = 99;
        const auto one = test::writePhantomSeries(PhantomKind::Aaa, first, folder);
        CtSeriesDescription again;
        again.seriesInstanceUid = one.written.seriesInstanceUid;
        again.studyInstanceUid = one.written.studyInstanceUid;
        again.acquisitionNumber = 2;
        again.fileNamePrefix = "AQ";
        const auto two = test::writePhantomSeries(PhantomKind::Aaa, second, folder, again);
        const DicomScanResult scan = scanDicom(folder);
        QCOMPARE(scan.series.size(), std::size_t(2));
        QCOMPARE(scan.series[1].key, one.written.seriesInstanceUid + "#2");
        QVERIFY(hasWarning(scan.series[0].warnings, "split into 2 sub-series"));
        const CtVolume a = importDicomSeries(scan.series[0]).image, b = importDicomSeries(scan.series[1]).image;
        QVERIFY(test::differingVoxels(a, one.truth) == 0 || test::differingVoxels(a, two.truth) == 0);
        QVERIFY(test::differingVoxels(b, one.truth) == 0 || test::differingVoxels(b, two.truth) == 0);
        QVERIFY(test::differingVoxels(a, b) > 0);
    }

    void junkAndTruncatedFilesAreCountedAndSkipped()
    {
        const auto folder = test::freshFolder("dicom-defects", "junk");
        const auto phantom = test::writePhantomSeries(PhantomKind::Aaa, test::smallPhantomOptions(0.0), folder);
        writeBytes(folder / "notes.txt", "not an image\n");
        std::mt19937 random(5);
        std::string noise(5000, '\0');
        for (char& c : noise)
            c = char(random());
        writeBytes(folder / "random.bin", noise);
        fs::create_directories(folder / "nested");
        writeBytes(folder / "nested" / "empty", "");
        // Cut slice 20 in half: its data is lost, the slice is missing.
        const auto size = fs::file_size(phantom.written.files[20]);
        fs::resize_file(phantom.written.files[20], size / 2);

        const DicomScanResult scan = scanDicom(folder);
        QCOMPARE(scan.nonDicomFiles, std::size_t(3));
        QCOMPARE(scan.damagedFiles, std::size_t(1));
        QVERIFY2(hasWarning(scan.warnings, "3 files are not DICOM"), joined(scan.warnings).c_str());
        QVERIFY(hasWarning(scan.warnings, "1 DICOM file is damaged or truncated"));
        const DicomVolume imported = importDicomSeries(onlySeries(scan));
        QVERIFY(hasWarning(imported.warnings, "1 missing slices"));
        QCOMPARE(sliceMeanError(imported.image, phantom.truth, 19), 0.0);
        QVERIFY(sliceMeanError(imported.image, phantom.truth, 20) < 10.0);
    }

    void folderWithoutImagesIsAnError()
    {
        const auto folder = test::freshFolder("dicom-defects", "only-junk");
        writeBytes(folder / "a.txt", "hello");
        writeBytes(folder / "b.dat", std::string(300, 'x'));
        const DicomScanResult scan = scanDicom(folder);
        QVERIFY(scan.series.empty());
        QCOMPARE(scan.defaultSeries(), nullptr);
        QCOMPARE(scan.nonDicomFiles, std::size_t(2));
        QVERIFY_THROWS_EXCEPTION(Error, scanDicom(folder / "no-such-folder"));
    }

    void tooLargeIsRefusedBeforeAllocating()
    {
        const auto folder = test::freshFolder("dicom-defects", "large");
        test::writePhantomSeries(PhantomKind::Aaa, test::smallPhantomOptions(), folder);
        const DicomSeries series = onlySeries(scanDicom(folder));
        QCOMPARE(importMemoryNeeded(series), std::uint64_t(96 * 96 * 48 * 2));
        DicomImportOptions options;
        options.memoryLimitBytes = 512 * 1024;
        try
        {
            importDicomSeries(series, options);
            QFAIL("a series larger than the memory limit must be refused");
        }
        catch (const Error& error)
        {
            const std::string message = error.message();
            QVERIFY2(message.find("needs 0.00 GiB") != std::string::npos && message.find("96 x 96 x 48") != std::string::npos,
                     message.c_str());
            QCOMPARE(error.contextValue("needed_bytes"), std::to_string(96 * 96 * 48 * 2));
        }
    }

    void dicomDirReferencesTheFiles()
    {
        const auto root = test::freshFolder("dicom-defects", "dicomdir");
        const auto phantom = test::writePhantomSeries(PhantomKind::Aaa, test::smallPhantomOptions(), root / "SERIES1");
        DicomDirInterface dicomDir;
        QVERIFY(dicomDir.createNewDicomDir(DicomDirInterface::AP_GeneralPurpose, (root / "DICOMDIR").c_str()).good());
        for (const auto& file : phantom.written.files)
            QVERIFY(dicomDir.addDicomFile(("SERIES1/" + file.filename().string()).c_str(), root.c_str()).good());
        QVERIFY(dicomDir.writeDicomDir().good());
        // Another series beside it that the DICOMDIR does not reference must not be read.
        test::writePhantomSeries(PhantomKind::Stenosis, test::smallPhantomOptions(), root / "OTHER");

        const DicomScanResult scan = scanDicom(root / "DICOMDIR");
        QCOMPARE(scan.series.size(), std::size_t(1));
        const DicomVolume imported = importDicomSeries(scan.series.front());
        QCOMPARE(test::differingVoxels(imported.image, phantom.truth), std::size_t(0));
    }
};

QTEST_GUILESS_MAIN(Defects)
#include "tst_defects.moc"
