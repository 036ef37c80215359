// Masks onto a study's image grid (study::maskOnImageGrid). Truth: masks built on known grids: the same grid, a
// larger grid of the same scan offset by whole voxels (the voxel must land where its patient position says), and
// grids that must be refused (another voxel size, a half-voxel offset, a labelled voxel outside the image).
#include "vsim/core/Error.h"
#include "vsim/study/LabelImport.h"

#include <QtTest>

#include <Eigen/Geometry>

#include <algorithm>

using vsim::study::maskOnImageGrid;

namespace {

vsim::VolumeGeometry grid(std::array<int, 3> dims, Eigen::Vector3d origin, double spacing = 1.5)
{
    vsim::VolumeGeometry g;
    g.dims = dims;
    g.origin = origin;
    g.spacing = Eigen::Vector3d::Constant(spacing);
    return g;
}

} // namespace

class TestLabelImport : public QObject
{
    Q_OBJECT
private slots:
    void sameGridAndWholeVoxelOffsetsPlaceEveryVoxel()
    {
        const vsim::VolumeGeometry image = grid({10, 12, 8}, {-7.5, 3.0, 100.0});
        vsim::CtVolume same(image);
        same.data()[image.linearIndex(2, 3, 4)] = 255;
        std::vector<std::string> warnings;
        const vsim::LabelVolume placed = maskOnImageGrid(same, image, 1, warnings);
        QCOMPARE(int(placed.data()[image.linearIndex(2, 3, 4)]), 1);
        QVERIFY(warnings.empty());

        // The uncropped scan: 5, 4 and 3 voxels more before the crop's first voxel.
        const vsim::VolumeGeometry larger = grid({30, 30, 20}, image.origin - Eigen::Vector3d(5, 4, 3) * 1.5);
        vsim::CtVolume mask(larger);
        mask.data()[larger.linearIndex(9, 10, 7)] = 1; // = image voxel (4, 6, 4): the same patient position
        const vsim::LabelVolume cut = maskOnImageGrid(mask, image, 3, warnings);
        QCOMPARE(int(cut.data()[image.linearIndex(4, 6, 4)]), 3);
        QVERIFY((larger.indexToPatient({9, 10, 7}) - image.indexToPatient({4, 6, 4})).norm() < 1e-9);
        QCOMPARE(warnings.size(), std::size_t(1));
    }

    /// The same lattice stored the other way round (k reversed, as a DICOM SEG's stack along the row x column normal
    /// can be) and with i and j swapped: every voxel lands at its own patient position; a turned grid is refused.
    void reorderedAxesPlaceEveryVoxel()
    {
        const vsim::VolumeGeometry image = grid({10, 12, 8}, {-7.5, 3.0, 100.0});
        vsim::VolumeGeometry flipped = image;
        flipped.dims = {12, 10, 8};
        flipped.direction << 0, 1, 0, 1, 0, 0, 0, 0, -1; // columns: j, i, -k
        flipped.origin = image.indexToPatient({0, 0, 7});
        vsim::CtVolume mask(flipped);
        std::fill(mask.data(), mask.data() + flipped.voxelCount(), std::int16_t(0));
        const Eigen::Vector3d inImage(4, 9, 2);
        const Eigen::Vector3d inMask = flipped.patientToIndex(image.indexToPatient(inImage));
        mask.data()[flipped.linearIndex(int(std::lround(inMask.x())), int(std::lround(inMask.y())),
                                        int(std::lround(inMask.z())))] = 7;
        std::vector<std::string> warnings;
        const vsim::LabelVolume placed = maskOnImageGrid(mask, image, std::nullopt, warnings);
        QCOMPARE(int(placed.data()[image.linearIndex(4, 9, 2)]), 1); // one value: label 1 (binaryMaskIsLabelOne)
        QCOMPARE(std::count(placed.data(), placed.data() + placed.size(), std::uint8_t(1)), std::ptrdiff_t(1));
        QVERIFY(std::any_of(warnings.begin(), warnings.end(),
                            [](const std::string& w) { return w.find("axis order") != std::string::npos; }));
        vsim::VolumeGeometry turned = image;
        turned.direction = Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitZ()).toRotationMatrix();
        vsim::CtVolume turnedMask(turned);
        turnedMask.data()[0] = 1;
        QVERIFY_THROWS_EXCEPTION(vsim::Error, maskOnImageGrid(turnedMask, image, 1, warnings));
    }

    /// A binary mask from elsewhere (0 / 255) is one structure: label 1, the lumen's value, with a warning naming
    /// the value; a mask of several values keeps them; a 0 / 1 mask needs no warning; a given value wins.
    void binaryMaskIsLabelOne()
    {
        const vsim::VolumeGeometry image = grid({6, 6, 6}, {0.0, 0.0, 0.0});
        vsim::CtVolume binary(image), several(image);
        std::fill(binary.data(), binary.data() + image.voxelCount(), std::int16_t(0));
        std::fill(several.data(), several.data() + image.voxelCount(), std::int16_t(0));
        binary.data()[image.linearIndex(1, 2, 3)] = binary.data()[image.linearIndex(4, 4, 4)] = 255;
        several.data()[image.linearIndex(1, 2, 3)] = 1, several.data()[image.linearIndex(4, 4, 4)] = 4;
        std::vector<std::string> warnings;
        const vsim::LabelVolume one = maskOnImageGrid(binary, image, std::nullopt, warnings);
        QCOMPARE(int(one.data()[image.linearIndex(1, 2, 3)]), 1);
        QCOMPARE(int(one.data()[image.linearIndex(4, 4, 4)]), 1);
        QCOMPARE(warnings.size(), std::size_t(1));
        QVERIFY(warnings.front().find("one value (255)") != std::string::npos);
        warnings.clear();
        const vsim::LabelVolume kept = maskOnImageGrid(several, image, std::nullopt, warnings);
        QCOMPARE(int(kept.data()[image.linearIndex(1, 2, 3)]), 1);
        QCOMPARE(int(kept.data()[image.linearIndex(4, 4, 4)]), 4);
        QVERIFY(warnings.empty());
        binary.data()[image.linearIndex(1, 2, 3)] = binary.data()[image.linearIndex(4, 4, 4)] = 1;
        QCOMPARE(int(maskOnImageGrid(binary, image, std::nullopt, warnings).data()[image.linearIndex(4, 4, 4)]), 1);
        QVERIFY(warnings.empty());
        QCOMPARE(int(maskOnImageGrid(binary, image, 9, warnings).data()[image.linearIndex(4, 4, 4)]), 9);
        QVERIFY(warnings.empty());
    }

    void mismatchedGridsAreRefused()
    {
        const vsim::VolumeGeometry image = grid({10, 12, 8}, {0, 0, 0});
        std::vector<std::string> warnings;
        vsim::CtVolume finer(grid({10, 12, 8}, {0, 0, 0}, 0.75));
        finer.data()[0] = 1;
        QVERIFY_THROWS_EXCEPTION(vsim::Error, maskOnImageGrid(finer, image, 1, warnings));
        vsim::CtVolume half(grid({10, 12, 8}, {0.75, 0, 0}));
        half.data()[0] = 1;
        QVERIFY_THROWS_EXCEPTION(vsim::Error, maskOnImageGrid(half, image, 1, warnings));
        const vsim::VolumeGeometry larger = grid({20, 20, 20}, {-15, 0, 0});
        vsim::CtVolume outside(larger);
        outside.data()[larger.linearIndex(0, 0, 0)] = 1; // 10 voxels before the image's first
        QVERIFY_THROWS_EXCEPTION(vsim::Error, maskOnImageGrid(outside, image, 1, warnings));
        QVERIFY_THROWS_EXCEPTION(vsim::Error, maskOnImageGrid(vsim::CtVolume(image), image, 1, warnings)); // empty
        vsim::CtVolume negative(image);
        negative.data()[3] = -5; // not a label value: the user must say which to use
        QVERIFY_THROWS_EXCEPTION(vsim::Error, maskOnImageGrid(negative, image, std::nullopt, warnings));
        QCOMPARE(int(maskOnImageGrid(negative, image, 4, warnings).data()[3]), 4);
    }
};

QTEST_APPLESS_MAIN(TestLabelImport)
#include "tst_label_import.moc"
