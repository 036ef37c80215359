// DICOM SEG: a label of values 1 and 4 on a rotated, anisotropic grid written with DCMTK's dcmseg and read back by
// our own dataset parser (an independent path): the same voxels and values on the same grid, the segment names kept,
// only the slices holding labels stored; DCMTK's own SEG loader accepts what we wrote; a CT slice and a truncated SEG are refused.
// With the CT's instances given slice by slice, every frame names the CT image of its own slice (Derivation Image
// Sequence) and the Referenced Series Sequence lists the CT series with those images; with a list that does not
// match the grid, no reference is written.
#include "vsim/core/Error.h"
#include "vsim/dicom/CtSeriesWriter.h"
#include "vsim/dicom/DicomSegmentation.h"
#include "vsim/dicom/SliceStack.h"

#include <QtTest>

#include <dcmtk/config/osconfig.h>
#include <dcmtk/dcmdata/dcfilefo.h>
#include <dcmtk/dcmdata/dcdeftag.h>
#include <dcmtk/dcmdata/dcitem.h>
#include <dcmtk/dcmseg/segdoc.h>

#include <Eigen/Geometry>

#include <filesystem>
#include <fstream>
#include <set>

namespace fs = std::filesystem;
using namespace vsim;

namespace {

fs::path freshFolder(const std::string& name)
{
    const fs::path folder = fs::temp_directory_path() / ("vsim-seg-test-" + name);
    fs::remove_all(folder);
    fs::create_directories(folder);
    return folder;
}

/// Two balls (values 1 and 4, as a sac's lumen and thrombus) on a grid turned 10 degrees about z with 0.8 x 0.7 x
/// 1.5 mm voxels.
LabelVolume twoBalls()
{
    VolumeGeometry g;
    g.dims = {40, 36, 24};
    g.spacing = {0.8, 0.7, 1.5};
    g.origin = {-12.0, 30.0, -200.0};
    g.direction = Eigen::AngleAxisd(10.0 * M_PI / 180.0, Eigen::Vector3d::UnitZ()).toRotationMatrix();
    LabelVolume label(g);
    std::fill(label.data(), label.data() + g.voxelCount(), std::uint8_t(0));
    for (int k = 0; k < g.dims[2]; ++k)
        for (int j = 0; j < g.dims[1]; ++j)
            for (int i = 0; i < g.dims[0]; ++i)
            {
                const Eigen::Vector3d p = g.indexToPatient(Eigen::Vector3d(i, j, k));
                const Eigen::Vector3d a = g.indexToPatient(Eigen::Vector3d(12, 14, 8));
                const Eigen::Vector3d b = g.indexToPatient(Eigen::Vector3d(27, 20, 12));
                if ((p - a).norm() <= 6.0)
                    label.at(i, j, k) = 1;
                else if ((p - b).norm() <= 5.0)
                    label.at(i, j, k) = 4;
            }
    return label;
}

} // namespace

class SegmentationTest : public QObject
{
    Q_OBJECT

private slots:
    void referencesTheCtSlices()
    {
        const LabelVolume label = twoBalls();
        const VolumeGeometry& grid = label.geometry();
        dicom::SegmentationDescription description;
        description.sourceSeriesUid = "1.2.826.0.1.3680043.2.1125.9.1";
        description.sourceSopClassUid = "1.2.840.10008.5.1.4.1.1.2";
        for (int k = 0; k < grid.dims[2]; ++k)
            description.sourceSopInstanceUids.push_back("1.2.826.0.1.3680043.2.1125.9.1." + std::to_string(100 + k));
        const fs::path file = freshFolder("references") / "labels.dcm";
        dicom::writeDicomSegmentation(label, {"aorta"}, description, file);
        DcmFileFormat format;
        QVERIFY(format.loadFile(file.string().c_str()).good());
        DcmDataset& data = *format.getDataset();
        DcmItem* perFrame = nullptr;
        int frames = 0;
        std::set<std::string> sources;
        while (data.findAndGetSequenceItem(DCM_PerFrameFunctionalGroupsSequence, perFrame, frames).good())
        {
            ++frames;
            DcmItem *plane = nullptr, *derivation = nullptr, *source = nullptr;
            Float64 z = 0.0;
            OFString uid;
            QVERIFY(perFrame->findAndGetSequenceItem(DCM_PlanePositionSequence, plane).good());
            QVERIFY(plane->findAndGetFloat64(DCM_ImagePositionPatient, z, 2).good());
            QVERIFY(perFrame->findAndGetSequenceItem(DCM_DerivationImageSequence, derivation).good());
            QVERIFY(derivation->findAndGetSequenceItem(DCM_SourceImageSequence, source).good());
            QVERIFY(source->findAndGetOFString(DCM_ReferencedSOPInstanceUID, uid).good());
            const int k = int(std::lround((z - grid.origin.z()) / grid.spacing.z())); // the grid turns about z only
            QCOMPARE(std::string(uid.c_str()), description.sourceSopInstanceUids[std::size_t(k)]);
            sources.insert(uid.c_str());
        }
        QVERIFY(frames > 0);
        DcmItem* series = nullptr;
        OFString seriesUid;
        QVERIFY(data.findAndGetSequenceItem(DCM_ReferencedSeriesSequence, series).good());
        QVERIFY(series->findAndGetOFString(DCM_SeriesInstanceUID, seriesUid).good());
        QCOMPARE(std::string(seriesUid.c_str()), description.sourceSeriesUid);
        DcmItem* instance = nullptr;
        std::set<std::string> listed;
        for (int n = 0; series->findAndGetSequenceItem(DCM_ReferencedInstanceSequence, instance, n).good(); ++n)
        {
            OFString uid;
            QVERIFY(instance->findAndGetOFString(DCM_ReferencedSOPInstanceUID, uid).good());
            listed.insert(uid.c_str());
        }
        QCOMPARE(listed, sources);
        qInfo("%d frames, each derived from its own slice's CT image; %zu images in the Referenced Series Sequence",
              frames, listed.size());

        // A list that does not fit the grid: no references at all (never a wrong one).
        description.sourceSopInstanceUids.pop_back();
        dicom::writeDicomSegmentation(label, {"aorta"}, description, file.parent_path() / "unreferenced.dcm");
        DcmFileFormat other;
        QVERIFY(other.loadFile((file.parent_path() / "unreferenced.dcm").string().c_str()).good());
        DcmItem* none = nullptr;
        QVERIFY(other.getDataset()->findAndGetSequenceItem(DCM_ReferencedSeriesSequence, none).bad());
        QVERIFY(other.getDataset()->findAndGetSequenceItem(DCM_PerFrameFunctionalGroupsSequence, none).good());
        DcmItem* derivation = nullptr;
        QVERIFY(none->findAndGetSequenceItem(DCM_DerivationImageSequence, derivation).bad());
    }

    void roundTrip()
    {
        const LabelVolume label = twoBalls();
        const fs::path file = freshFolder("roundtrip") / "labels.dcm";
        dicom::writeDicomSegmentation(label, {"aorta", "", "", "thrombus"}, {}, file);
        QVERIFY(dicom::isDicomSegmentation(file));

        // DCMTK's own loader takes it: segments 1..4 (2 and 3 without frames), one frame per slice and segment
        // holding voxels.
        DcmSegmentation* loaded = nullptr;
        QVERIFY(DcmSegmentation::loadFile(file.string().c_str(), loaded).good() && loaded);
        QCOMPARE(loaded->getNumberOfSegments(), std::size_t(4));
        const std::size_t dcmtkFrames = loaded->getNumberOfFrames();
        delete loaded;

        const dicom::SegmentationMask read = dicom::readDicomSegmentation(file);
        QCOMPARE(read.segmentLabels, (std::vector<std::string>{"aorta", "unused label value 2", "unused label value 3",
                                                                "thrombus"}));
        QVERIFY(read.warnings.empty());
        const VolumeGeometry& g = read.mask.geometry();
        const VolumeGeometry& original = label.geometry();
        qInfo("%zu frames; read grid %d x %d x %d", dcmtkFrames, g.dims[0], g.dims[1], g.dims[2]);
        // Only the slices holding labels are stored: the read grid is the original's, cropped in k.
        QCOMPARE(g.dims[0], original.dims[0]);
        QCOMPARE(g.dims[1], original.dims[1]);
        QVERIFY(g.dims[2] < original.dims[2]);
        QVERIFY((g.spacing - original.spacing).norm() < 1e-4);
        QVERIFY((g.direction - original.direction).norm() < 1e-5);
        const Eigen::Vector3d firstIndex = original.patientToIndex(g.origin);
        QVERIFY(std::abs(firstIndex.x()) < 1e-3 && std::abs(firstIndex.y()) < 1e-3);
        const int k0 = int(std::lround(firstIndex.z()));
        std::size_t compared = 0;
        for (int k = 0; k < original.dims[2]; ++k)
            for (int j = 0; j < original.dims[1]; ++j)
                for (int i = 0; i < original.dims[0]; ++i)
                {
                    const int kk = k - k0;
                    const int value = kk >= 0 && kk < g.dims[2] ? read.mask.at(i, j, kk) : 0;
                    QCOMPARE(value, int(label.at(i, j, k)));
                    compared += value != 0;
                }
        QVERIFY(compared > 1000);
    }

    void refusals()
    {
        const fs::path folder = freshFolder("refusals");
        // A CT slice is no SEG.
        VolumeGeometry g;
        g.dims = {16, 16, 2};
        CtVolume ct(g);
        std::fill(ct.data(), ct.data() + g.voxelCount(), std::int16_t(40));
        const auto written = dicom::writeCtSeries(ct, dicom::stackOf(g), {}, folder / "ct");
        QVERIFY(!written.files.empty());
        QVERIFY(!dicom::isDicomSegmentation(written.files.front()));
        QVERIFY_THROWS_EXCEPTION(Error, dicom::readDicomSegmentation(written.files.front()));
        // A truncated SEG: refused with a message, not read as a smaller mask.
        const fs::path whole = folder / "whole.dcm";
        dicom::writeDicomSegmentation(twoBalls(), {}, {}, whole);
        const auto size = fs::file_size(whole);
        fs::copy_file(whole, folder / "cut.dcm");
        fs::resize_file(folder / "cut.dcm", size - 600);
        QVERIFY_THROWS_EXCEPTION(Error, dicom::readDicomSegmentation(folder / "cut.dcm"));
        // Nothing to write.
        LabelVolume empty(g);
        std::fill(empty.data(), empty.data() + g.voxelCount(), std::uint8_t(0));
        QVERIFY_THROWS_EXCEPTION(Error, dicom::writeDicomSegmentation(empty, {}, {}, folder / "empty.dcm"));
    }
};

QTEST_GUILESS_MAIN(SegmentationTest)
#include "tst_segmentation.moc"
