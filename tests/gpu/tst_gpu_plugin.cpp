// The GPU plugin as the executables load it (issue 22; app/common/src/GpuPlugin.h, app/gpu-plugin): the file from
// the build (or $VASCUSIM_GPU_PLUGIN, as on the accelerator machine) loads, states this version and its CUDA runtime,
// and gives every factory. Where there is a device, the smoke plume stepped through the plugin's backend matches
// the CPU's to rounding level (the same bound as tst_gpu_smoke_solver): the objects cross the plugin's boundary
// intact. Without a device only the loading is checked (this runs in the default suite).

#include "GpuPlugin.h"
#include "SmokePlume.h"

#include <QtTest>

#include <cmath>
#include <cstdlib>

using namespace vsim;

class TestGpuPlugin : public QObject
{
    Q_OBJECT
private slots:
    void initTestCase()
    {
        if (qEnvironmentVariableIsEmpty("VASCUSIM_GPU_PLUGIN"))
            qputenv("VASCUSIM_GPU_PLUGIN", VSIM_GPU_PLUGIN_FILE);
    }

    void loadsAndStatesItsVersion()
    {
        const app::GpuPluginApi* plugin = app::gpuPlugin();
        QVERIFY2(plugin != nullptr, app::gpuPluginStatus().c_str());
        QVERIFY(QString::fromStdString(app::gpuPluginStatus()).startsWith("loaded from "));
        QVERIFY(!plugin->runtimeVersion().empty());
        QVERIFY(plugin->wallStepperFactory() && plugin->wallStaticModelFactory() && plugin->sphStepperFactory() &&
                plugin->smokeBackendFactory());
        const int devices = plugin->deviceCount();
        QCOMPARE(app::gpuUnavailableReason().empty(), devices > 0);
        qInfo("plugin: %s; CUDA runtime %s; %s", app::gpuPluginStatus().c_str(), plugin->runtimeVersion().c_str(),
              plugin->deviceSummary().c_str());
    }

    void smokeThroughThePluginMatchesTheCpu()
    {
        const app::GpuPluginApi* plugin = app::gpuPlugin();
        if (plugin == nullptr || plugin->deviceCount() == 0)
            QSKIP("no CUDA device on this machine; run on the accelerator with the device tool");
        std::unique_ptr<sim::smoke::SmokeSimulation> cpu = test::plumeSimulation(32, nullptr);
        std::unique_ptr<sim::smoke::SmokeSimulation> gpu =
            test::plumeSimulation(32, plugin->smokeBackendFactory()(cpu->grid()));
        for (int step = 0; step < 10; ++step)
        {
            const double dt = cpu->stableStep(1.0 / 30.0);
            QVERIFY(cpu->step(dt).guard.empty());
            QVERIFY(gpu->step(dt).guard.empty());
        }
        double largest = 0.0, difference = 0.0;
        for (std::size_t c = 0; c < cpu->grid().density.size(); ++c)
        {
            largest = std::max(largest, std::abs(double(cpu->grid().density[c])));
            difference = std::max(difference, std::abs(double(cpu->grid().density[c]) - gpu->grid().density[c]));
        }
        qInfo("32^3 plume, 10 steps through the plugin: density difference %.2e of the largest", difference / largest);
        QVERIFY(largest > 0.0);
        QVERIFY(difference / largest < 1e-4);
    }
};

QTEST_APPLESS_MAIN(TestGpuPlugin)
#include "tst_gpu_plugin.moc"
