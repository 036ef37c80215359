// The label brush: a disc of the requested radius in the view's plane (area within 3 % of pi r^2, one slice
// thick), exact undo / redo of single and merged strokes on a seeded random label, and refusals.

#include "vsim/imaging/LabelEditing.h"

#include <QtTest>

#include <cmath>
#include <random>
#include <set>

using namespace vsim;

namespace {

LabelVolume randomLabel(std::uint32_t seed)
{
    VolumeGeometry geometry;
    geometry.dims = {60, 50, 40};
    geometry.spacing = {0.5, 0.5, 1.25};
    geometry.origin = {-10.0, 20.0, -300.0};
    LabelVolume label(geometry);
    std::mt19937 random(seed);
    for (std::size_t i = 0; i < label.size(); ++i)
        label.data()[i] = std::uint8_t(random() % 3 == 0);
    return label;
}

} // namespace

class LabelEditing : public QObject
{
    Q_OBJECT

private slots:
    void discAreaAndThickness()
    {
        VolumeGeometry geometry;
        geometry.dims = {80, 80, 20};
        geometry.spacing = {0.5, 0.5, 2.0};
        LabelVolume label(geometry);
        const Eigen::Vector3d centre = geometry.indexToPatient(Eigen::Vector3d(40.2, 39.7, 10.0));
        const double radius = 12.0;
        const imaging::LabelEdit axial = imaging::paintDisc(label, centre, Eigen::Vector3d::UnitZ(), radius, 1);
        const double area = double(axial.voxels.size()) * 0.25;
        qInfo("axial disc r = 12 mm: %zu voxels, %.1f mm2 (pi r2 = %.1f)", axial.voxels.size(), area, M_PI * radius * radius);
        QVERIFY(std::abs(area / (M_PI * radius * radius) - 1.0) < 0.03);
        for (std::size_t voxel : axial.voxels)
            QCOMPARE(int(voxel / (80 * 80)), 10); // one slice
        // A sagittal stroke (normal x) spans one column of 0.5 mm voxels: 2 mm slices give about pi r^2 / 1 mm2.
        LabelVolume other(geometry);
        const imaging::LabelEdit sagittal = imaging::paintDisc(other, centre, Eigen::Vector3d::UnitX(), radius, 1);
        const double sagittalArea = double(sagittal.voxels.size()) * 0.5 * 2.0;
        QVERIFY(std::abs(sagittalArea / (M_PI * radius * radius) - 1.0) < 0.08);
        for (std::size_t voxel : sagittal.voxels)
            QCOMPARE(int(voxel % 80), 40);
    }

    /// The 3D sphere brush: the voxel volume of a ball of radius 6 mm on anisotropic voxels within 3 % of 4/3 pi r^3,
    /// across the 6 slices of 2 mm it reaches; the values it writes (thrombus 4) are kept as written.
    void sphereBrushFillsABall()
    {
        VolumeGeometry geometry;
        geometry.dims = {60, 60, 30};
        geometry.spacing = {0.5, 0.5, 2.0};
        LabelVolume label(geometry);
        const Eigen::Vector3d centre = geometry.indexToPatient(Eigen::Vector3d(30.3, 29.6, 15.2));
        const double radius = 6.0;
        const imaging::LabelEdit ball = imaging::paintBall(label, centre, radius, 4);
        const double volume = double(ball.voxels.size()) * 0.5 * 0.5 * 2.0;
        qInfo("ball r = 6 mm: %zu voxels, %.0f mm3 (4/3 pi r3 = %.0f)", ball.voxels.size(), volume,
              4.0 / 3.0 * M_PI * radius * radius * radius);
        QVERIFY(std::abs(volume / (4.0 / 3.0 * M_PI * radius * radius * radius) - 1.0) < 0.03);
        std::set<int> slices;
        for (std::size_t voxel : ball.voxels)
            slices.insert(int(voxel / (60 * 60)));
        QCOMPARE(int(slices.size()), 6);
        QCOMPARE(int(label.at(30, 30, 15)), 4);
        QVERIFY_THROWS_EXCEPTION(Error, imaging::paintBall(label, centre, 0.0, 1));
    }

    void undoRedoIsExact()
    {
        LabelVolume label = randomLabel(7);
        const LabelVolume original = label.clone();
        const Eigen::Vector3d centre = label.geometry().indexToPatient(Eigen::Vector3d(30, 25, 20));
        imaging::LabelEdit stroke = imaging::paintDisc(label, centre, Eigen::Vector3d::UnitZ(), 6.0, 1);
        // A second, overlapping dab of the same stroke: merged, the first "before" values win.
        const imaging::LabelEdit dab =
            imaging::paintDisc(label, centre + Eigen::Vector3d(3.0, 1.0, 0.0), Eigen::Vector3d::UnitZ(), 6.0, 1);
        stroke.merge(dab);
        const LabelVolume painted = label.clone();
        QVERIFY(stroke.voxels.size() > 100);
        imaging::revert(label, stroke);
        QVERIFY(std::equal(label.data(), label.data() + label.size(), original.data()));
        imaging::reapply(label, stroke);
        QVERIFY(std::equal(label.data(), label.data() + label.size(), painted.data()));
        // Erasing records only voxels that change.
        const imaging::LabelEdit erase = imaging::paintDisc(label, centre, Eigen::Vector3d::UnitZ(), 6.0, 0);
        for (std::size_t i = 0; i < erase.voxels.size(); ++i)
            QCOMPARE(int(erase.before[i]), 1);
        imaging::revert(label, erase);
        QVERIFY(std::equal(label.data(), label.data() + label.size(), painted.data()));
    }

    /// Remove island: the piece at the point goes, the other stays; undo restores it exactly; a point far from any
    /// labelled voxel changes nothing.
    void removeIsland()
    {
        VolumeGeometry g;
        g.dims = {40, 40, 20};
        g.spacing = {0.8, 0.8, 1.5};
        LabelVolume label(g);
        std::fill(label.data(), label.data() + label.size(), std::uint8_t(0));
        for (int k = 2; k < 18; ++k)
            for (int j = 5; j < 12; ++j)
                for (int i = 5; i < 12; ++i)
                    label.at(i, j, k) = 1, label.at(i + 20, j + 20, k) = 1; // two blocks, apart
        const LabelVolume original = label.clone();
        const Eigen::Vector3d inSecond = g.indexToPatient(Eigen::Vector3d(25, 25, 10));
        const imaging::LabelEdit island = imaging::removeIsland(label, inSecond + Eigen::Vector3d(2.0, 0, 0));
        QCOMPARE(island.voxels.size(), std::size_t(7 * 7 * 16));
        QCOMPARE(int(label.at(25, 25, 10)), 0);
        QCOMPARE(int(label.at(8, 8, 10)), 1);
        imaging::revert(label, island);
        QVERIFY(std::equal(label.data(), label.data() + label.size(), original.data()));
        QVERIFY(imaging::removeIsland(label, g.indexToPatient(Eigen::Vector3d(35, 5, 10))).empty());
    }

    void refusals()
    {
        LabelVolume label = randomLabel(3);
        const Eigen::Vector3d centre = label.geometry().indexToPatient(Eigen::Vector3d(30, 25, 20));
        QVERIFY_THROWS_EXCEPTION(Error, imaging::paintDisc(label, centre, Eigen::Vector3d::UnitZ(), 0.0, 1));
        QVERIFY_THROWS_EXCEPTION(Error, imaging::paintDisc(label, centre, Eigen::Vector3d::Zero(), 2.0, 1));
        LabelVolume empty;
        QVERIFY_THROWS_EXCEPTION(Error, imaging::paintDisc(empty, centre, Eigen::Vector3d::UnitZ(), 2.0, 1));
        imaging::LabelEdit paint = imaging::paintDisc(label, centre, Eigen::Vector3d::UnitZ(), 3.0, 1);
        imaging::LabelEdit erase = imaging::paintDisc(label, centre, Eigen::Vector3d::UnitZ(), 3.0, 0);
        QVERIFY_THROWS_EXCEPTION(Error, paint.merge(erase));
        // A brush outside the volume changes nothing.
        QVERIFY(imaging::paintDisc(label, centre + Eigen::Vector3d(500, 0, 0), Eigen::Vector3d::UnitZ(), 3.0, 1).empty());
    }
};

QTEST_GUILESS_MAIN(LabelEditing)
#include "tst_label_editing.moc"
