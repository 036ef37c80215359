// Contacts of the wall model. 128 springs on a tube wall pull their nodes 0.1 mm outward: each node moves towards
// its anchor and, once settled, the wall's elastic forces balance the spring forces (within 2 %). A rigid probe
// pressed 0.5 mm into a block pushes the nodes under it down and none penetrates deeper than it was pressed; drawn
// sideways, Coulomb friction (mu = 0.5) drags the surface along where a frictionless probe does not.

#include "vsim/core/TetMesh.h"
#include "vsim/sim/fem/BackwardEuler.h"
#include "vsim/sim/fem/StructuredMeshes.h"

#include <QtTest>

#include <random>

using namespace vsim;
using namespace vsim::sim::fem;

class FemContacts : public QObject
{
    Q_OBJECT

private slots:
    void springsHoldAndBalance()
    {
        const StructuredTetMesh mesh = tubeWallTetMesh(0.01, 0.0115, 0.1, {1, 64, 20});
        CorotationalFem model(mesh.points, mesh.tets, ElasticMaterial{});
        std::vector<std::uint8_t> fixed(3 * model.nodeCount(), 0);
        std::vector<int> candidates;
        for (std::size_t n = 0; n < model.nodeCount(); ++n)
        {
            if (mesh.points[n].z() < 1e-9 || mesh.points[n].z() > 0.1 - 1e-9)
                fixed[3 * n] = fixed[3 * n + 1] = fixed[3 * n + 2] = 1;
            else if (mesh.points[n].head<2>().norm() > 0.011)
                candidates.push_back(int(n));
        }
        std::mt19937 random(9);
        std::shuffle(candidates.begin(), candidates.end(), random);
        Contacts contacts;
        for (int k = 0; k < 128; ++k)
        {
            const int node = candidates[std::size_t(k)];
            const Eigen::Vector3d radial(mesh.points[std::size_t(node)].x(), mesh.points[std::size_t(node)].y(), 0.0);
            contacts.springs.push_back({node, mesh.points[std::size_t(node)] + 1e-4 * radial.normalized(), 50.0});
        }
        BackwardEulerSettings settings;
        settings.timeStep = 0.02;
        settings.cgMaxIterations = 300;
        BackwardEuler integrator(model, settings);
        for (int step = 0; step < 120; ++step)
            integrator.step(model, {}, fixed, contacts);
        model.updateElements();
        const Eigen::VectorXd elastic = model.elasticForces();
        Eigen::VectorXd springForces = Eigen::VectorXd::Zero(elastic.size());
        addContactForces(contacts, model.positions(), model.velocities(), springForces);
        double imbalance = 0.0, total = 0.0;
        int towards = 0;
        for (const SpringConstraint& spring : contacts.springs)
        {
            const Eigen::Vector3d moved = model.positions().segment<3>(3 * spring.node) - mesh.points[std::size_t(spring.node)];
            towards += moved.dot(spring.anchor - mesh.points[std::size_t(spring.node)]) > 0.0;
            imbalance += (elastic.segment<3>(3 * spring.node) + springForces.segment<3>(3 * spring.node)).norm();
            total += springForces.segment<3>(3 * spring.node).norm();
        }
        qInfo("128 springs: %d nodes moved towards their anchors; force imbalance %.3g of the spring forces", towards,
              imbalance / total);
        QVERIFY(towards >= 115); // 90 %
        QVERIFY(imbalance < 0.02 * total);
    }

    void probePushesAndDragsWithFriction()
    {
        const double size = 0.02, height = 0.01, radius = 0.005, press = 5e-4;
        double dragged[2] = {0.0, 0.0};
        for (int withFriction = 0; withFriction < 2; ++withFriction)
        {
            const StructuredTetMesh mesh = boxTetMesh(Eigen::Vector3d(size, size, height), {8, 8, 4});
            CorotationalFem model(mesh.points, mesh.tets, ElasticMaterial{});
            std::vector<std::uint8_t> fixed(3 * model.nodeCount(), 0);
            for (std::size_t n = 0; n < model.nodeCount(); ++n)
                if (mesh.points[n].z() < 1e-9)
                    fixed[3 * n] = fixed[3 * n + 1] = fixed[3 * n + 2] = 1;
            RigidProbe probe;
            probe.centre = Eigen::Vector3d(0.5 * size, 0.5 * size, height + radius - press);
            probe.radius = radius;
            probe.stiffness = 2e4;
            probe.friction = withFriction ? 0.5 : 0.0;
            Contacts contacts;
            contacts.probes.push_back(probe);
            BackwardEulerSettings settings;
            settings.timeStep = 0.01;
            settings.cgMaxIterations = 300;
            BackwardEuler integrator(model, settings);
            for (int step = 0; step < 80; ++step)
                integrator.step(model, {}, fixed, contacts);
            double deepest = 0.0, sink = 0.0;
            for (std::size_t n = 0; n < model.nodeCount(); ++n)
            {
                deepest = std::max(deepest, radius - (model.positions().segment<3>(Eigen::Index(3 * n)) - probe.centre).norm());
                sink = std::min(sink, model.positions()[Eigen::Index(3 * n + 2)] - mesh.points[n].z());
            }
            QVERIFY(sink < -1e-5);        // the surface under the probe gives way
            QVERIFY(deepest < press);     // and nothing goes deeper than the probe was pressed
            // Draw the probe 1 mm along x at 10 mm/s (ten 10 ms steps).
            contacts.probes[0].velocity = Eigen::Vector3d(0.01, 0.0, 0.0);
            for (int step = 0; step < 10; ++step)
            {
                contacts.probes[0].centre += settings.timeStep * contacts.probes[0].velocity;
                integrator.step(model, {}, fixed, contacts);
            }
            const int top = mesh.node(4, 4, 4);
            dragged[withFriction] = model.positions()[3 * top] - mesh.points[std::size_t(top)].x();
            qInfo("probe mu = %.1f: deepest penetration %.3f mm (pressed %.1f mm), surface sank %.3f mm, centre node "
                  "dragged %.4f mm along x", probe.friction, 1e3 * deepest, 1e3 * press, -1e3 * sink, 1e3 * dragged[withFriction]);
        }
        QVERIFY(dragged[1] > dragged[0] + 1e-6);
    }
};

QTEST_GUILESS_MAIN(FemContacts)
#include "tst_fem_contacts.moc"
