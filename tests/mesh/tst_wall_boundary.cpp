// Pressure faces and held nodes of a wall from elsewhere (mesh::markWallBoundary). Truth: a structured tube wall
// (inner radius 10 mm, outer 11.5 mm, z 0..100 mm): its lumen faces are the boundary faces whose three nodes lie on
// the inner radius, its held nodes those on the two end cuts, and it has two open loops.
#include "vsim/core/Error.h"
#include "vsim/mesh/WallBoundary.h"
#include "vsim/sim/fem/StructuredMeshes.h"

#include <QtTest>

using vsim::mesh::markWallBoundary;
using vsim::mesh::WallBoundarySelection;

namespace {

/// The tube without wall fields, with truth arrays "truth_lumen" and "truth_held" (1 on those nodes).
vsim::TetMesh tube()
{
    const vsim::sim::fem::StructuredTetMesh structured = vsim::sim::fem::tubeWallTetMesh(0.01, 0.0115, 0.1, {2, 32, 12});
    vsim::TetMesh mesh;
    mesh.tets = structured.tets;
    std::vector<double> lumen, held;
    for (const Eigen::Vector3d& p : structured.points)
    {
        mesh.points.push_back(1e3 * p);
        lumen.push_back(p.head<2>().norm() < 0.01 + 1e-9 ? 1.0 : 0.0);
        held.push_back(p.z() < 1e-9 || p.z() > 0.1 - 1e-9 ? 1.0 : 0.0);
    }
    mesh.pointFields["truth_lumen"] = lumen;
    mesh.pointFields["truth_held"] = held;
    return mesh;
}

std::size_t truthLumenFaces(const vsim::TetMesh& mesh)
{
    std::size_t count = 0;
    for (const auto& face : vsim::boundaryFaces(mesh.tets))
        count += mesh.pointFields.at("truth_lumen")[std::size_t(face[0])] > 0 &&
                 mesh.pointFields.at("truth_lumen")[std::size_t(face[1])] > 0 &&
                 mesh.pointFields.at("truth_lumen")[std::size_t(face[2])] > 0;
    return count;
}

} // namespace

class TestWallBoundary : public QObject
{
    Q_OBJECT
private slots:
    void lumenPointAndOpenEndsFindTheTubesLumenAndEndCuts()
    {
        const vsim::TetMesh mesh = tube();
        for (const Eigen::Vector3d point : {Eigen::Vector3d(0, 0, 50), Eigen::Vector3d(4, -6, 12), Eigen::Vector3d(-8, 1, 95)})
        {
            WallBoundarySelection selection;
            selection.lumenPointMm = point;
            selection.fixOpenEnds = true;
            const auto marked = markWallBoundary(mesh, selection);
            QCOMPARE(marked.pressureFaces, truthLumenFaces(mesh));
            QCOMPARE(marked.pressureFaces, std::size_t(2 * 32 * 12));
            QCOMPARE(marked.openLoops, std::size_t(2));
            QCOMPARE(marked.wall.pointFields.at("end_set"), mesh.pointFields.at("truth_held"));
            for (std::size_t i = 0; i < mesh.points.size(); ++i)
                QCOMPARE(marked.wall.pointFields.at("wall_layer")[i] == 0.0, mesh.pointFields.at("truth_lumen")[i] > 0);
            QVERIFY(marked.warnings.empty());
        }
    }

    void namedArraysSelectTheSame()
    {
        WallBoundarySelection selection;
        selection.pressureArray = "truth_lumen";
        selection.fixedArray = "truth_held";
        const auto marked = markWallBoundary(tube(), selection);
        QCOMPARE(marked.pressureFaces, std::size_t(2 * 32 * 12));
        QCOMPARE(marked.fixedNodes, std::size_t(3 * 32 * 2)); // three node rings through the wall at each end
    }

    void incompleteSelectionsAreRefused()
    {
        WallBoundarySelection nothing;
        QVERIFY_THROWS_EXCEPTION(vsim::Error, markWallBoundary(tube(), nothing));
        WallBoundarySelection noEnds;
        noEnds.lumenPointMm = Eigen::Vector3d(0, 0, 50);
        QVERIFY_THROWS_EXCEPTION(vsim::Error, markWallBoundary(tube(), noEnds));
        WallBoundarySelection missingArray;
        missingArray.pressureArray = "lumen";
        missingArray.fixOpenEnds = true;
        try
        {
            markWallBoundary(tube(), missingArray);
            QFAIL("a missing array must be refused");
        }
        catch (const vsim::Error& error)
        {
            QVERIFY(error.message().find("truth_lumen") != std::string::npos); // the arrays it has are listed
        }
        WallBoundarySelection noLoad;
        noLoad.pressureArray = "none";
        noLoad.fixedArray = "truth_held";
        vsim::TetMesh unloaded = tube();
        unloaded.pointFields["none"] = std::vector<double>(unloaded.points.size(), 0.0);
        QVERIFY_THROWS_EXCEPTION(vsim::Error, markWallBoundary(unloaded, noLoad));
    }
};

QTEST_APPLESS_MAIN(TestWallBoundary)
#include "tst_wall_boundary.moc"
