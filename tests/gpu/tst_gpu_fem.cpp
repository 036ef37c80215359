// The CUDA wall solver against the CPU one (same algorithm): 100 implicit steps of a pressurised tube wall with
// both ends fixed; the positions must agree within 1e-5 of the largest displacement (relative), and every step's
// PCG iteration count within one. Skips without a device.

#include "vsim/cuda_common/DeviceInfo.h"
#include "vsim/cuda_fem/CudaBackwardEuler.h"
#include "vsim/sim/fem/StructuredMeshes.h"
#include "vsim/core/TetMesh.h"
#include "vsim/sim/fem/SurfaceLoads.h"

#include <QtTest>

using namespace vsim;
using namespace vsim::sim::fem;

class TestGpuFem : public QObject
{
    Q_OBJECT
private slots:
    void parityWithTheCpuAfter100Steps_data()
    {
        QTest::addColumn<int>("around");
        QTest::addColumn<int>("along");
        QTest::addColumn<double>("pressure");
        QTest::newRow("tube 880 nodes, 16 kPa") << 40 << 10 << 16e3;
        QTest::newRow("tube 2250 nodes, 16 kPa") << 75 << 14 << 16e3;
        QTest::newRow("tube 2250 nodes, 1 MPa (large rotation)") << 75 << 14 << 1e6;
    }

    void parityWithTheCpuAfter100Steps()
    {
        if (vsim::cuda::devices().empty())
            QSKIP("no CUDA device on this machine; run on the accelerator with the device tool");
        QFETCH(int, around);
        QFETCH(int, along);
        QFETCH(double, pressure);
        const StructuredTetMesh mesh = tubeWallTetMesh(0.01, 0.0115, 0.1, {1, around, along});
        ElasticMaterial material;
        CorotationalFem cpu(mesh.points, mesh.tets, material);
        std::vector<std::uint8_t> fixed(3 * cpu.nodeCount(), 0);
        for (std::size_t n = 0; n < cpu.nodeCount(); ++n)
            if (mesh.points[n].z() < 1e-9 || mesh.points[n].z() > 0.1 - 1e-9)
                fixed[3 * n] = fixed[3 * n + 1] = fixed[3 * n + 2] = 1;
        std::vector<std::array<int, 3>> inner;
        for (const auto& face : boundaryFaces(mesh.tets))
            if (mesh.points[std::size_t(face[0])].head<2>().norm() < 0.01 + 1e-9 &&
                mesh.points[std::size_t(face[1])].head<2>().norm() < 0.01 + 1e-9 &&
                mesh.points[std::size_t(face[2])].head<2>().norm() < 0.01 + 1e-9)
                inner.push_back(face);
        BackwardEulerSettings settings;
        cuda::CudaBackwardEuler gpu(cpu, settings, fixed, inner);
        BackwardEuler integrator(cpu, settings);
        Eigen::VectorXd forces(cpu.positions().size());
        int worstIterationGap = 0, cpuIterations = 0, gpuIterations = 0;
        for (int step = 0; step < 100; ++step)
        {
            forces.setZero();
            addPressureForces(inner, cpu.positions(), pressure, forces);
            const StepReport a = integrator.step(cpu, forces, fixed);
            const StepReport b = gpu.step(pressure);
            worstIterationGap = std::max(worstIterationGap, std::abs(a.cgIterations - b.cgIterations));
            cpuIterations += a.cgIterations, gpuIterations += b.cgIterations;
        }
        Eigen::VectorXd positions, velocities;
        gpu.download(positions, velocities);
        double largest = 0.0, difference = 0.0;
        for (std::size_t n = 0; n < cpu.nodeCount(); ++n)
        {
            largest = std::max(largest, (cpu.positions().segment<3>(Eigen::Index(3 * n)) - mesh.points[n]).norm());
            difference = std::max(difference, (positions.segment<3>(Eigen::Index(3 * n)) -
                                               cpu.positions().segment<3>(Eigen::Index(3 * n))).norm());
        }
        qInfo("%zu nodes, %zu tets: largest displacement %.4g mm, GPU - CPU %.3g mm (%.3g relative); PCG iterations "
              "CPU %d, GPU %d, largest gap in a step %d",
              cpu.nodeCount(), cpu.elementCount(), 1e3 * largest, 1e3 * difference, difference / largest, cpuIterations,
              gpuIterations, worstIterationGap);
        QVERIFY(difference <= 1e-5 * largest);
        QVERIFY(worstIterationGap <= 1);
    }
};

QTEST_APPLESS_MAIN(TestGpuFem)
#include "tst_gpu_fem.moc"
