// Core value types against closed-form geometry: unit cube volumes, a known LPS mapping, skeleton topology.
#include "vsim/core/Error.h"
#include "vsim/core/ImageVolume.h"
#include "vsim/core/ParticleSet.h"
#include "vsim/core/SkeletonGraph.h"
#include "vsim/core/TetMesh.h"
#include "vsim/core/TriangleMesh.h"
#include "vsim/core/Units.h"

#include <Eigen/Geometry>
#include <QtTest>

namespace {

/// Unit cube [0,1]^3 split into 6 positively oriented tetrahedra (Kuhn triangulation), mm.
vsim::TetMesh unitCubeTets()
{
    vsim::TetMesh mesh;
    for (int corner = 0; corner < 8; ++corner)
        mesh.points.emplace_back(corner & 1, (corner >> 1) & 1, (corner >> 2) & 1);
    mesh.tets = {{0, 1, 3, 7}, {0, 1, 7, 5}, {0, 5, 7, 4}, {0, 3, 2, 7}, {0, 6, 4, 7}, {0, 2, 6, 7}};
    return mesh;
}

/// Closed unit cube surface, 12 outward triangles, mm.
vsim::TriangleMesh unitCubeSurface()
{
    vsim::TriangleMesh mesh;
    for (int corner = 0; corner < 8; ++corner)
        mesh.points.emplace_back(corner & 1, (corner >> 1) & 1, (corner >> 2) & 1);
    mesh.triangles = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 4}, {1, 5, 4},
                      {2, 6, 3}, {3, 6, 7}, {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};
    return mesh;
}

} // namespace

class TestTypes : public QObject
{
    Q_OBJECT
private slots:
    void unitConversionsMatchDefinitions()
    {
        QCOMPARE(vsim::units::mmHgToPa(120.0), 120.0 * 133.322387415);
        QVERIFY(std::abs(vsim::units::mlPerMinToM3PerS(60.0) - 1e-6) < 1e-18);
        QCOMPARE(vsim::units::mToMm(vsim::units::mmToM(12.5)), 12.5);
    }

    void geometryMapsIndexToLpsAndBack()
    {
        vsim::VolumeGeometry geometry;
        geometry.dims = {10, 20, 30};
        geometry.spacing = {0.5, 0.7, 2.0};
        geometry.origin = {-100.0, 50.0, 10.0};
        geometry.direction = Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitZ()).toRotationMatrix();
        // index (2,0,0) moves 1 mm along the i axis, which the 90-degree rotation turns into +y (posterior).
        const Eigen::Vector3d patient = geometry.indexToPatient({2.0, 0.0, 0.0});
        QVERIFY((patient - Eigen::Vector3d(-100.0, 51.0, 10.0)).norm() < 1e-12);
        QVERIFY((geometry.patientToIndex(patient) - Eigen::Vector3d(2, 0, 0)).norm() < 1e-12);
        QCOMPARE(geometry.voxelCount(), std::size_t(6000));
        QCOMPARE(geometry.linearIndex(1, 2, 3), std::size_t(1 + 10 * (2 + 20 * 3)));
    }

    void invalidGeometryIsRefused()
    {
        vsim::VolumeGeometry geometry;
        geometry.dims = {4, 4, 0};
        QVERIFY_THROWS_EXCEPTION(vsim::Error, vsim::CtVolume{geometry});
        geometry.dims = {4, 4, 4};
        geometry.direction(0, 0) = 2.0;
        QVERIFY_THROWS_EXCEPTION(vsim::Error, geometry.validate());
    }

    void imageVolumeCopiesShareVoxelsAndCloneDoesNot()
    {
        vsim::VolumeGeometry geometry;
        geometry.dims = {3, 3, 3};
        vsim::CtVolume volume(geometry);
        vsim::CtVolume alias = volume;
        alias.at(1, 1, 1) = 400;
        QCOMPARE(volume.at(1, 1, 1), std::int16_t(400));
        vsim::CtVolume copy = volume.clone();
        copy.at(1, 1, 1) = -1000;
        QCOMPARE(volume.at(1, 1, 1), std::int16_t(400));
    }

    void tetMeshVolumeOfUnitCubeIsOne()
    {
        vsim::TetMesh mesh = unitCubeTets();
        mesh.validate();
        QVERIFY(std::abs(mesh.totalVolume() - 1.0) < 1e-14);
        std::swap(mesh.tets[2][1], mesh.tets[2][2]); // invert one element
        try
        {
            mesh.validate();
            QFAIL("an inverted element must be refused");
        }
        catch (const vsim::Error& error)
        {
            QCOMPARE(error.contextValue("element"), std::string("2"));
        }
    }

    void closedSurfaceAreaAndVolumeOfUnitCube()
    {
        const vsim::TriangleMesh mesh = unitCubeSurface();
        mesh.validate();
        QVERIFY(std::abs(mesh.area() - 6.0) < 1e-14);
        QVERIFY(std::abs(mesh.signedVolume() - 1.0) < 1e-14);
    }

    void vertexNormalsOfAnOctahedronPointOutward()
    {
        // The regular octahedron: each vertex's four faces have equal areas, so its normal is its own direction.
        vsim::TriangleMesh mesh;
        mesh.points = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
        for (int x : {0, 1})
            for (int y : {2, 3})
                for (int z : {4, 5})
                {
                    // counter-clockwise seen from outside: (x, y, z) when the octant's sign product is positive
                    const bool positive = ((x == 0) == (y == 2)) == (z == 4);
                    mesh.triangles.push_back(positive ? std::array<int, 3>{x, y, z} : std::array<int, 3>{x, z, y});
                }
        QVERIFY(mesh.signedVolume() > 0.0);
        const std::vector<Eigen::Vector3d> normals = mesh.vertexNormals();
        for (std::size_t v = 0; v < mesh.points.size(); ++v)
            QVERIFY((normals[v] - mesh.points[v]).norm() < 1e-12);
        mesh.points.push_back({5, 5, 5}); // in no triangle
        QVERIFY(mesh.vertexNormals().back().isZero());
    }

    void skeletonDegreesOfAY()
    {
        vsim::SkeletonGraph graph;
        for (int n = 0; n < 4; ++n)
            graph.nodes.push_back({Eigen::Vector3d(n, 0, 0), {n, 0, 0}});
        for (int leaf : {0, 2, 3})
        {
            vsim::SkeletonGraph::Edge edge;
            edge.from = 1;
            edge.to = leaf;
            edge.points = {graph.nodes[1].position, graph.nodes[leaf].position};
            edge.voxels = {graph.nodes[1].voxel, graph.nodes[leaf].voxel};
            edge.radii = {2.0, 1.5};
            graph.edges.push_back(edge);
        }
        graph.validate();
        QCOMPARE(graph.junctions(), std::vector<int>{1});
        QCOMPARE(graph.endpoints(), (std::vector<int>{0, 2, 3}));
        QCOMPARE(graph.edges[2].length(), 2.0);
        graph.edges[0].radii[0] = 0.0;
        QVERIFY_THROWS_EXCEPTION(vsim::Error, graph.validate());
    }

    void particleSetKeepsFieldsConsistent()
    {
        vsim::ParticleSet particles;
        particles.positionsMm.assign(5, Eigen::Vector3d(1.0, 2.0, 3.0));
        particles.fields["speed_m_s"].assign(5, 0.25);
        particles.validate();
        QCOMPARE(particles.size(), std::size_t(5));
        particles.fields["pressure_pa"].assign(4, 0.0);
        QVERIFY_THROWS_EXCEPTION(vsim::Error, particles.validate());
    }
};

QTEST_APPLESS_MAIN(TestTypes)
#include "tst_types.moc"
