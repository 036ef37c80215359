// The vessel wall mesh: on a capped cylinder (radius 5 mm, 1.5 mm wall) the open wall's volume equals
// pi ((r + t)^2 - r^2) L within 1 % and both open ends are planar fixed sets; on the aaa phantom (lumen surface
// of the truth label decimated to about 3,000 vertices, centerlines from its skeleton) the wall opens at the five
// vessel ends, every element is positive and the dihedral angles are reported. With a sac's outer wall the thrombus
// is its own layer: on the cylinder with an outer contour 6 mm out over z 20..40 mm (thrombus 4.5 mm) the thrombus
// elements fill that stretch and their volume is the annulus's, the wall keeps its thickness everywhere, and the
// pressure still acts on the lumen alone. Bad input is refused.

#include "PhantomGrids.h"
#include "WallFixtures.h"
#include "vsim/core/Error.h"
#include "vsim/dicom/PhantomRender.h"
#include "vsim/imaging/Centerlines.h"
#include "vsim/imaging/Skeletonization.h"
#include "vsim/mesh/SurfaceRemeshing.h"
#include "vsim/mesh/VesselSurface.h"
#include "vsim/mesh/WallMesh.h"
#include "WallFlips.h"

#include <QtTest>

#include <cmath>

using namespace vsim;


class WallMeshTest : public QObject
{
    Q_OBJECT

private slots:
    void cylinderWallVolumeAndEnds()
    {
        const double radius = 5.0, length = 60.0, thickness = 1.5;
        const TriangleMesh lumen = test::cappedCylinder(radius, length, 96);
        QVERIFY(lumen.signedVolume() > 0.0);
        const std::vector<mesh::VesselEnd> ends{{Eigen::Vector3d(0, 0, 0), -Eigen::Vector3d::UnitZ(), radius},
                                                {Eigen::Vector3d(0, 0, length), Eigen::Vector3d::UnitZ(), radius}};
        const mesh::WallMesh wall = mesh::buildWallMesh(lumen, ends, thickness);
        wall.mesh.validate(); // every element positive
        QCOMPARE(wall.inverted, std::size_t(0));
        QCOMPARE(wall.endNodes.size(), std::size_t(2));
        // Cut one radius inside each end: 50 mm of tube left.
        double zLow = 1e9, zHigh = -1e9;
        for (int node : wall.endNodes[0])
            zLow = std::min(zLow, wall.mesh.points[std::size_t(node)].z()), zHigh = std::max(zHigh, wall.mesh.points[std::size_t(node)].z());
        QVERIFY(std::abs(zLow - 5.0) < 1e-9 && std::abs(zHigh - 5.0) < 1e-9); // the rings are 1 mm apart: planar
        const double open = 50.0;
        // The polygon of 96 sides: area factor sin(2 pi / n) n / (2 pi).
        const double polygon = std::sin(2.0 * M_PI / 96) * 96 / (2.0 * M_PI);
        const double expected = polygon * M_PI * ((radius + thickness) * (radius + thickness) - radius * radius) * open;
        qInfo("cylinder wall: %zu tets, volume %.1f mm3 (expected %.1f), min dihedral %.1f deg (mean %.1f)",
              wall.mesh.tets.size(), wall.mesh.totalVolume(), expected, wall.minDihedralDeg, wall.meanMinDihedralDeg);
        QVERIFY(std::abs(wall.mesh.totalVolume() / expected - 1.0) < 0.01);
        // The lumen faces carry the pressure: their area is the open lumen's, 2 pi r L (polygonal).
        double area = 0.0;
        for (const auto& face : mesh::lumenFaces(wall.mesh))
        {
            const auto& p = wall.mesh.points;
            const Eigen::Vector3d n = (p[std::size_t(face[1])] - p[std::size_t(face[0])]).cross(p[std::size_t(face[2])] - p[std::size_t(face[0])]);
            area += 0.5 * n.norm();
            const Eigen::Vector3d centre = (p[std::size_t(face[0])] + p[std::size_t(face[1])] + p[std::size_t(face[2])]) / 3.0;
            QVERIFY(n.dot(Eigen::Vector3d(centre.x(), centre.y(), 0.0)) < 0.0); // points into the lumen
        }
        const double lumenArea = 2.0 * 96 * radius * std::sin(M_PI / 96) * open;
        QVERIFY(std::abs(area / lumenArea - 1.0) < 1e-9);
    }

    void thrombusLayerInsideTheSac()
    {
        const double radius = 5.0, length = 60.0, thickness = 1.5, outer = 6.0; // outer wall 6 mm from the lumen
        const TriangleMesh lumen = test::cappedCylinder(radius, length, 96);
        const std::vector<mesh::VesselEnd> ends{{Eigen::Vector3d(0, 0, 0), -Eigen::Vector3d::UnitZ(), radius},
                                                {Eigen::Vector3d(0, 0, length), Eigen::Vector3d::UnitZ(), radius}};
        // The "sac": z 20..40 mm; elsewhere no sac (negative).
        const mesh::OuterWallDistance sac = [&](const Eigen::Vector3d& p, const Eigen::Vector3d&) {
            return p.z() >= 20.0 && p.z() <= 40.0 ? outer : -1.0;
        };
        const mesh::WallMesh wall = mesh::buildWallMesh(lumen, ends, thickness, sac);
        wall.mesh.validate();
        QCOMPARE(wall.inverted, std::size_t(0));
        const auto& material = wall.mesh.cellFields.at("material");
        double thrombusVolume = 0.0, wallVolume = 0.0, zMin = 1e9, zMax = -1e9;
        for (std::size_t t = 0; t < wall.mesh.tets.size(); ++t)
        {
            const auto& tet = wall.mesh.tets[t];
            const auto& p = wall.mesh.points;
            const double volume = (p[std::size_t(tet[1])] - p[std::size_t(tet[0])])
                                      .cross(p[std::size_t(tet[2])] - p[std::size_t(tet[0])])
                                      .dot(p[std::size_t(tet[3])] - p[std::size_t(tet[0])]) / 6.0;
            if (material[t] > 0.5)
            {
                thrombusVolume += volume;
                for (int node : tet)
                    zMin = std::min(zMin, p[std::size_t(node)].z()), zMax = std::max(zMax, p[std::size_t(node)].z());
            }
            else
                wallVolume += volume;
        }
        // The outer distances are smoothed over two 1-rings (rings 1 mm apart along z), so the sac's ends ramp over
        // a few mm; in its middle the thrombus is 4.5 mm and the annulus r 5..9.5 mm.
        const double polygon = std::sin(2.0 * M_PI / 96) * 96 / (2.0 * M_PI);
        const double annulus = polygon * M_PI * ((radius + outer - thickness) * (radius + outer - thickness) - radius * radius);
        qInfo("thrombus layer: %zu of %zu elements over z %.1f..%.1f mm, volume %.0f mm3 (the 20 mm annulus %.0f), "
              "thickest %.2f mm; wall volume %.0f mm3; min dihedral %.1f deg", wall.thrombusElements,
              wall.mesh.tets.size(), zMin, zMax, thrombusVolume, annulus * 20.0, wall.maxThrombusMm, wallVolume,
              wall.minDihedralDeg);
        QVERIFY(wall.thrombusElements > 0 && zMin > 15.0 && zMax < 45.0);
        QVERIFY(std::abs(wall.maxThrombusMm - (outer - thickness)) < 1e-6);
        QVERIFY(std::abs(thrombusVolume / (annulus * 20.0) - 1.0) < 0.15);
        // The wall: 1.5 mm outside the thrombus, and two layers of 0.75 mm + 0.75 mm elsewhere (wall material).
        const double wallOnly = polygon * M_PI * ((radius + thickness) * (radius + thickness) - radius * radius);
        const double wallInSac =
            polygon * M_PI * ((radius + outer) * (radius + outer) - (radius + outer - thickness) * (radius + outer - thickness));
        QVERIFY(std::abs(wallVolume / (wallOnly * 30.0 + wallInSac * 20.0) - 1.0) < 0.15);
        // The 4.5 mm thrombus over 0.33 mm lumen edges (14 times as tall): the inner layer in three sub-layers (each
        // 4.5 times as tall as wide), everywhere; the interfaces at l / 4, each with as many nodes as the lumen. The
        // single thrombus layer had 4.1 deg (RESULTS.md 2026-11-30).
        QCOMPARE(wall.innerSubLayers, 3);
        QVERIFY2(wall.minDihedralDeg >= 10.0, qPrintable(QString::number(wall.minDihedralDeg)));
        const auto& layer = wall.mesh.pointFields.at("wall_layer");
        for (double level : {0.25, 0.5, 0.75, 1.0})
            QCOMPARE(std::count(layer.begin(), layer.end(), level), std::count(layer.begin(), layer.end(), 0.0));
        // The pressure on the lumen only (its area as without the thrombus).
        QCOMPARE(mesh::lumenFaces(wall.mesh).size(), mesh::lumenFaces(mesh::buildWallMesh(lumen, ends, thickness).mesh).size());
    }

    void aaaPhantomWall()
    {
        dicom::PhantomModel model = dicom::buildPhantomModel(dicom::PhantomKind::Aaa, {});
        model.tissues.clear();
        // A margin beyond the aneurysm's 27.5 mm radius: the lumen must not be cut by the grid's border.
        const LabelVolume label = dicom::renderPhantomLabels(model, test::gridAroundVessels(model, 1.0, 32.0));
        ParameterSet surfaceParameters(mesh::surfaceParameters());
        surfaceParameters.set("target_vertices", 3000);
        const TriangleMesh decimated = mesh::extractVesselSurface(label, 1, surfaceParameters).surface;
        const TriangleMesh lumen = mesh::remeshIsotropic(decimated, [](const Eigen::Vector3d&) { return 2.5; });
        qInfo("lumen: %zu vertices decimated (smallest angle %.2f deg), %zu remeshed at 2.5 mm (%.2f deg); volume "
              "%.0f -> %.0f mm3", decimated.points.size(), mesh::minTriangleAngle(decimated), lumen.points.size(),
              mesh::minTriangleAngle(lumen), decimated.signedVolume(), lumen.signedVolume());
        const auto skeleton = imaging::extractSkeleton(label, 1, ParameterSet(imaging::skeletonParameters()));
        const SkeletonGraph centerlines =
            imaging::extractCenterlines(label, 1, skeleton.graph, ParameterSet(imaging::centerlineParameters()));
        const std::vector<mesh::VesselEnd> ends = mesh::vesselEnds(centerlines);
        QCOMPARE(ends.size(), std::size_t(5)); // aorta above, two renal arteries, two iliac arteries
        const mesh::WallMesh wall = mesh::buildWallMesh(lumen, ends, 1.5);
        qInfo("aaa wall: %zu nodes, %zu tets, %zu inverted, min dihedral %.2f deg (mean of element minima %.1f, %zu "
              "under 5 deg), end sets %zu %zu %zu %zu %zu nodes",
              wall.mesh.points.size(), wall.mesh.tets.size(), wall.inverted, wall.minDihedralDeg, wall.meanMinDihedralDeg,
              wall.slivers,
              wall.endNodes[0].size(), wall.endNodes[1].size(), wall.endNodes[2].size(), wall.endNodes[3].size(),
              wall.endNodes[4].size());
        QCOMPARE(wall.inverted, std::size_t(0));
        wall.mesh.validate();
        for (const auto& end : wall.endNodes)
            QVERIFY(end.size() >= 12);
        // The remeshed surface's triangles are good (smallest angle about 28 deg); the few flat elements sit where
        // the outward offset crowds into the crotch of the iliac bifurcation.
        QVERIFY(mesh::minTriangleAngle(lumen) > 20.0);
        QVERIFY(wall.minDihedralDeg >= 10.0); // issue 16: no element under 10 degrees
        QCOMPARE(wall.slivers, std::size_t(0));
    }

    /// The 4-4 flip (src/WallFlips.h) on a ring of four elements around a long edge (a, b), whose other diagonal
    /// (p0, p2) gives better elements: the count, the volume and the boundary faces stay, the smallest dihedral angle
    /// rises; no flip across two materials, nor around an edge whose ring does not close.
    void edgeFlipOfFour()
    {
        const auto ring = [](double halfHeight, double halfLength, double halfWidth) {
            TetMesh m;
            m.points = {{0, 0, -halfHeight}, {0, 0, halfHeight}, {halfLength, 0, 0}, {0, halfWidth, 0},
                        {-halfLength, 0, 0}, {0, -halfWidth, 0}};
            for (int i = 0; i < 4; ++i)
            {
                m.tets.push_back({0, 1, 2 + i, 2 + (i + 1) % 4});
                if (m.elementVolume(m.tets.size() - 1) < 0.0)
                    std::swap(m.tets.back()[2], m.tets.back()[3]);
            }
            return m;
        };
        const auto smallest = [](const TetMesh& m) {
            double angle = 180.0;
            for (const auto& t : m.tets)
                angle = std::min(angle, mesh::minDihedralAngle(m.points[std::size_t(t[0])], m.points[std::size_t(t[1])],
                                                              m.points[std::size_t(t[2])], m.points[std::size_t(t[3])]));
            return angle;
        };
        const auto sortedFaces = [](const TetMesh& m) {
            auto faces = boundaryFaces(m.tets);
            for (auto& f : faces)
                std::sort(f.begin(), f.end());
            std::sort(faces.begin(), faces.end());
            return faces;
        };
        TetMesh tall = ring(1.0, 2.0, 0.5); // smallest angle 29.2 deg; 58.4 with the diagonal across the ring's width
        const double before = smallest(tall), volume = tall.totalVolume();
        const auto faces = sortedFaces(tall);
        QCOMPARE(mesh::detail::flipEdgesOfFour(tall, {}, 30.0), std::size_t(1));
        tall.validate();
        qInfo("4-4 flip: smallest dihedral %.2f -> %.2f deg", before, smallest(tall));
        QCOMPARE(tall.tets.size(), std::size_t(4));
        QVERIFY(std::abs(tall.totalVolume() - volume) < 1e-12);
        QVERIFY(sortedFaces(tall) == faces);
        QVERIFY(smallest(tall) > before + 25.0);
        TetMesh flat = ring(0.3, 1.0, 1.0); // the edge (a, b) is already the best diagonal (46.0 against 23.0 deg)
        QCOMPARE(mesh::detail::flipEdgesOfFour(flat, {}, 30.0), std::size_t(0));
        TetMesh twoMaterials = ring(1.0, 2.0, 0.5);
        QCOMPARE(mesh::detail::flipEdgesOfFour(twoMaterials, {0.0, 0.0, 1.0, 1.0}, 30.0), std::size_t(0));
        TetMesh open = ring(1.0, 2.0, 0.5);
        open.tets.pop_back(); // three elements: the ring does not close
        QCOMPARE(mesh::detail::flipEdgesOfFour(open, {}, 30.0), std::size_t(0));
    }

    void badInputIsRefused()
    {
        const TriangleMesh lumen = test::cappedCylinder(5.0, 60.0, 32);
        const std::vector<mesh::VesselEnd> ends{{Eigen::Vector3d(0, 0, 0), -Eigen::Vector3d::UnitZ(), 5.0}};
        QVERIFY_THROWS_EXCEPTION(Error, mesh::buildWallMesh(TriangleMesh{}, ends, 1.5));
        QVERIFY_THROWS_EXCEPTION(Error, mesh::buildWallMesh(lumen, ends, 0.0));
        const std::vector<mesh::VesselEnd> farAway{{Eigen::Vector3d(0, 0, 500), Eigen::Vector3d::UnitZ(), 5.0}};
        QVERIFY_THROWS_EXCEPTION(Error, mesh::buildWallMesh(lumen, farAway, 1.5));
        QVERIFY_THROWS_EXCEPTION(Error, mesh::lumenFaces(TetMesh{}));
    }
};

QTEST_GUILESS_MAIN(WallMeshTest)
#include "tst_wall_mesh.moc"
