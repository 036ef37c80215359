#include "vsim/cuda_fem/CudaBackwardEuler.h"

#include "WallDevice.cuh"

namespace vsim::cuda {

struct CudaBackwardEuler::Device : WallDevice
{
    using WallDevice::WallDevice;
};

CudaBackwardEuler::CudaBackwardEuler(const sim::fem::CorotationalFem& model, const sim::fem::BackwardEulerSettings& settings,
                                     const std::vector<std::uint8_t>& constrained,
                                     const std::vector<std::array<int, 3>>& pressureFaces)
    : m_device(std::make_unique<Device>(model, settings, constrained, pressureFaces))
{
}

CudaBackwardEuler::~CudaBackwardEuler() = default;

sim::fem::StepReport CudaBackwardEuler::step(double pressurePa)
{
    Device& d = *m_device;
    VSIM_CUDA_CHECK(cudaMemcpyAsync(&d.scalars.data->pressure, &pressurePa, sizeof(double), cudaMemcpyHostToDevice, d.stream));
    VSIM_CUDA_CHECK(cudaGraphLaunch(d.assembly.exec, d.stream));
    if (d.setUpAgain)
    {
        d.setUpMultigridFromDevice();
        d.setUpAgain = false;
    }
    const fem::DeviceScalars scalars = d.runPcg();
    VSIM_CUDA_CHECK(cudaGraphLaunch(d.finish.exec, d.stream));
    VSIM_CUDA_CHECK(cudaStreamSynchronize(d.stream));
    if (d.multigrid)
    {
        if (d.iterationsAfterSetup < 0)
            d.iterationsAfterSetup = scalars.iterations;
        else if (scalars.iterations > d.settings.multigridSetUpAgainFactor * d.iterationsAfterSetup + 5)
            d.setUpAgain = true;
    }
    sim::fem::StepReport report;
    report.cgIterations = scalars.iterations;
    report.cgResidual = scalars.residual;
    report.cgConverged = scalars.residual <= d.settings.cgTolerance;
    report.invertedElements = std::size_t(scalars.inverted);
    return report;
}

void CudaBackwardEuler::download(Eigen::VectorXd& positions, Eigen::VectorXd& velocities) const
{
    const Device& d = *m_device;
    positions.resize(Eigen::Index(3 * d.nodes));
    velocities.resize(Eigen::Index(3 * d.nodes));
    VSIM_CUDA_CHECK(cudaMemcpy(positions.data(), d.x.data, 3 * d.nodes * sizeof(double), cudaMemcpyDeviceToHost));
    VSIM_CUDA_CHECK(cudaMemcpy(velocities.data(), d.v.data, 3 * d.nodes * sizeof(double), cudaMemcpyDeviceToHost));
}

std::size_t CudaBackwardEuler::deviceBytes() const { return m_device->bytes; }

sim::fem::StepperFactory cudaStepperFactory()
{
    return [](const sim::fem::CorotationalFem& model, const sim::fem::BackwardEulerSettings& settings,
              const std::vector<std::uint8_t>& constrained, const std::vector<std::array<int, 3>>& pressureFaces) {
        return std::unique_ptr<sim::fem::ImplicitStepper>(
            std::make_unique<CudaBackwardEuler>(model, settings, constrained, pressureFaces));
    };
}

} // namespace vsim::cuda
