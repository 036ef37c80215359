#include "vsim/cuda_fem/CudaStaticWall.h"

#include "WallDevice.cuh"

#include "vsim/core/Error.h"

#include <Eigen/Geometry>

namespace vsim::cuda {

struct CudaStaticWall::Device : WallDevice
{
    using WallDevice::WallDevice;
    bool recordedFor(const sim::fem::StaticSolveSettings& s, double tolerance) const
    {
        return settings.cgTolerance == tolerance && settings.cgMaxIterations == s.cgMaxIterations &&
               settings.preconditioner == s.cgPreconditioner;
    }
};

namespace {

/// The implicit step's settings that make its graphs the static tangent's solve: a unit time step without damping
/// (WallDevice's staticTangent drops the mass), the PCG's tolerance and preconditioner as the static solve asks.
sim::fem::BackwardEulerSettings tangentSettings(double tolerance, int maxIterations, sim::fem::CgPreconditioner p)
{
    sim::fem::BackwardEulerSettings settings;
    settings.timeStep = 1.0;
    settings.rayleighAlpha = settings.rayleighBeta = 0.0;
    settings.cgTolerance = tolerance;
    settings.cgMaxIterations = maxIterations;
    settings.preconditioner = p;
    return settings;
}

} // namespace

CudaStaticWall::CudaStaticWall(const sim::fem::CorotationalFem& model, const std::vector<std::uint8_t>& constrained)
    : m_device(std::make_unique<Device>(model, tangentSettings(1e-9, 20000, sim::fem::CgPreconditioner::BlockJacobi),
                                        constrained, std::vector<std::array<int, 3>>{}, true)),
      m_host(model), m_positions(model.positions()), m_forces(Eigen::VectorXd::Zero(model.positions().size()))
{
}

CudaStaticWall::~CudaStaticWall() = default;

void CudaStaticWall::takeStateOf(const sim::fem::CorotationalFem& model)
{
    Device& d = *m_device;
    if (model.nodeCount() != d.nodes || model.elementCount() != std::size_t(d.model.elements))
        throw Error("the static wall on the GPU was made for another mesh");
    m_positions = model.positions();
    // The rotations into the element records' first four doubles (w, x, y, z), the element kernel's warm start.
    std::vector<double> quaternions(4 * model.elementCount());
    for (std::size_t e = 0; e < model.elementCount(); ++e)
    {
        const Eigen::Quaterniond q(model.rotation(e));
        quaternions[4 * e] = q.w(), quaternions[4 * e + 1] = q.x(), quaternions[4 * e + 2] = q.y(),
                        quaternions[4 * e + 3] = q.z();
    }
    VSIM_CUDA_CHECK(cudaMemcpy2D(d.elementRecords.data, 16 * sizeof(double), quaternions.data(), 4 * sizeof(double),
                                 4 * sizeof(double), model.elementCount(), cudaMemcpyHostToDevice));
}

std::size_t CudaStaticWall::updateElements()
{
    Device& d = *m_device;
    VSIM_CUDA_CHECK(cudaMemcpyAsync(d.x.data, m_positions.data(), 3 * d.nodes * sizeof(double), cudaMemcpyHostToDevice,
                                    d.stream));
    VSIM_CUDA_CHECK(cudaGraphLaunch(d.elementPass.exec, d.stream));
    fem::DeviceScalars scalars{};
    VSIM_CUDA_CHECK(cudaMemcpyAsync(m_forces.data(), d.force.data, 3 * d.nodes * sizeof(double), cudaMemcpyDeviceToHost,
                                    d.stream));
    VSIM_CUDA_CHECK(cudaMemcpyAsync(&scalars, d.scalars.data, sizeof scalars, cudaMemcpyDeviceToHost, d.stream));
    VSIM_CUDA_CHECK(cudaStreamSynchronize(d.stream));
    return std::size_t(scalars.inverted);
}

Eigen::Vector3d CudaStaticWall::firstInvertedCentroid() const
{
    sim::fem::CorotationalFem host = m_host; // the same test (det F <= 0) on the host, for the message only
    host.positions() = m_positions;
    host.updateElements();
    return host.firstInvertedCentroid();
}

sim::fem::TangentSolveResult CudaStaticWall::solveTangent(const Eigen::VectorXd& f, Eigen::VectorXd& dx,
                                                          double tolerance, const sim::fem::StaticSolveSettings& settings)
{
    Device& d = *m_device;
    sim::fem::TangentSolveResult result;
    const bool multigrid = settings.cgPreconditioner == sim::fem::CgPreconditioner::Multigrid;
    if (!d.recordedFor(settings, tolerance))
    {
        d.settings = tangentSettings(tolerance, settings.cgMaxIterations, settings.cgPreconditioner);
        m_setUpRule = sim::fem::MultigridSetUpRule(settings.multigridSetUpAgainFactor);
        d.multigrid.reset();
        d.setUpAgain = multigrid; // the hierarchy from the first update's tangent, as TangentSolver sets it up
        d.record();
    }
    // The tangent at the positions of the last element pass (the graph's element pass repeats it).
    VSIM_CUDA_CHECK(cudaGraphLaunch(d.assembly.exec, d.stream));
    if (d.setUpAgain)
    {
        d.setUpMultigridFromDevice();
        d.setUpAgain = false;
        m_setUpRule.setUp();
    }
    VSIM_CUDA_CHECK(cudaMemcpyAsync(d.rhs.data, f.data(), 3 * d.nodes * sizeof(double), cudaMemcpyHostToDevice, d.stream));
    VSIM_CUDA_CHECK(cudaMemsetAsync(d.dv.data, 0, 3 * d.nodes * sizeof(double), d.stream)); // from dx = 0
    const fem::DeviceScalars scalars = d.runPcg(); // d.settings carry the tolerance and the cap (recordedFor)
    dx.resize(Eigen::Index(3 * d.nodes));
    VSIM_CUDA_CHECK(cudaMemcpy(dx.data(), d.dv.data, 3 * d.nodes * sizeof(double), cudaMemcpyDeviceToHost));
    if (multigrid && m_setUpRule.setUpAgainAfter(scalars.iterations))
        d.setUpAgain = true;
    result.iterations = scalars.iterations;
    result.relativeResidual = scalars.residual;
    result.converged = scalars.residual <= tolerance;
    return result;
}

sim::fem::StaticModelFactory cudaStaticWallFactory()
{
    return [](const sim::fem::CorotationalFem& model, const std::vector<std::uint8_t>& constrained) {
        return std::unique_ptr<sim::fem::RemoteStaticModel>(std::make_unique<CudaStaticWall>(model, constrained));
    };
}

} // namespace vsim::cuda
