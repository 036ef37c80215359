// GPU smoke test: device query, then a*x+y on the GPU equals the same loop on the CPU. fma on both sides, so
// the results agree bit for bit; the tolerance 1e-15 relative is only a guard. Skips without a device.
#include "vsim/cuda_common/DeviceInfo.h"
#include "vsim/cuda_common/VectorKernels.h"

#include <QtTest>

#include <cmath>
#include <random>

class TestGpuSmoke : public QObject
{
    Q_OBJECT
private slots:
    void deviceQueryAndScaledSumMatchTheCpu()
    {
        qInfo("CUDA runtime %s; devices: %s", vsim::cuda::runtimeVersion().c_str(),
              vsim::cuda::deviceSummary().c_str());
        if (vsim::cuda::devices().empty())
            QSKIP("no CUDA device on this machine; run on the accelerator with the device tool");
        std::mt19937_64 random(7);
        std::uniform_real_distribution<double> value(-1.0, 1.0);
        std::vector<double> x(1 << 20), y(1 << 20);
        for (std::size_t i = 0; i < x.size(); ++i)
            x[i] = value(random), y[i] = value(random);
        const double a = 2.5;
        const std::vector<double> gpu = vsim::cuda::scaledSum(a, x, y);
        double worst = 0.0;
        for (std::size_t i = 0; i < x.size(); ++i)
            worst = std::max(worst, std::abs(gpu[i] - std::fma(a, x[i], y[i])) / std::max(1e-300, std::abs(gpu[i])));
        qInfo("max relative difference GPU vs CPU over %zu values: %.3g", x.size(), worst);
        QVERIFY(worst <= 1e-15);
    }
};

QTEST_APPLESS_MAIN(TestGpuSmoke)
#include "tst_gpu_smoke.moc"
