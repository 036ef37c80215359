#include "vsim/cuda_fem/CudaBackwardEuler.h"

#include "FemKernels.cuh"
#include "vsim/cuda_common/CudaCheck.h"

#include <Eigen/Geometry>

#include <vector>

namespace vsim::cuda {

namespace {

constexpr int kThreads = 256;

int blocksFor(std::size_t count) { return int((count + kThreads - 1) / kThreads); }

/// A device buffer freed with its owner.
template <typename T>
struct Buffer
{
    T* data = nullptr;
    std::size_t count = 0;
    void allocate(std::size_t n)
    {
        count = n;
        VSIM_CUDA_CHECK(cudaMalloc(&data, std::max<std::size_t>(1, n) * sizeof(T)));
    }
    void upload(const std::vector<T>& host)
    {
        allocate(host.size());
        if (!host.empty())
            VSIM_CUDA_CHECK(cudaMemcpy(data, host.data(), host.size() * sizeof(T), cudaMemcpyHostToDevice));
    }
    void zero(std::size_t n)
    {
        allocate(n);
        VSIM_CUDA_CHECK(cudaMemset(data, 0, std::max<std::size_t>(1, n) * sizeof(T)));
    }
    ~Buffer() { cudaFree(data); }
};

std::vector<double> toVector(const Eigen::VectorXd& v) { return std::vector<double>(v.data(), v.data() + v.size()); }

} // namespace

struct CudaBackwardEuler::Device
{
    sim::fem::BackwardEulerSettings settings;
    std::size_t nodes = 0;
    Buffer<int> tets, faces;
    Buffer<double> rest, restInverse, stiffness, mass, freeMask, quaternions, elementForces;
    Buffer<fem::MatrixReal> elementBlocks, matrix;
    Buffer<std::uint32_t> rowStart, columns, diagonalSlot, blockEntryStart, blockEntries, nodeEntryStart, nodeEntries;
    Buffer<double> x, v, dv, force, external, av, rhs, inverseDiagonal, r, z, p, q;
    Buffer<fem::DeviceScalars> scalars;
    fem::DeviceModel model;
    cudaStream_t stream = nullptr;
    cudaGraph_t graph = nullptr;
    cudaGraphExec_t graphExec = nullptr;
    std::size_t bytes = 0;

    ~Device()
    {
        if (graphExec)
            cudaGraphExecDestroy(graphExec);
        if (graph)
            cudaGraphDestroy(graph);
        if (stream)
            cudaStreamDestroy(stream);
    }

    void record()
    {
        const double h = settings.timeStep, alpha = settings.rayleighAlpha, beta = settings.rayleighBeta;
        const double massFactor = 1.0 + h * alpha, stiffnessFactor = h * beta + h * h;
        const int dofs = int(3 * nodes);
        fem::DeviceScalars* s = scalars.data;
        VSIM_CUDA_CHECK(cudaStreamBeginCapture(stream, cudaStreamCaptureModeThreadLocal));
        fem::resetKernel<<<1, 1, 0, stream>>>(s);
        fem::elementKernel<<<blocksFor(std::size_t(model.elements)), kThreads, 0, stream>>>(model, x.data, s);
        fem::assembleKernel<<<blocksFor(std::size_t(model.blocks)), kThreads, 0, stream>>>(model, massFactor, stiffnessFactor);
        fem::addMassKernel<<<blocksFor(nodes), kThreads, 0, stream>>>(model, massFactor);
        fem::forceKernel<<<blocksFor(nodes), kThreads, 0, stream>>>(model, force.data);
        VSIM_CUDA_CHECK(cudaMemsetAsync(external.data, 0, std::size_t(dofs) * sizeof(double), stream));
        if (model.faces > 0)
            fem::pressureKernel<<<blocksFor(std::size_t(model.faces)), kThreads, 0, stream>>>(model, x.data, s, external.data);
        const int rowBlocks = blocksFor(nodes * fem::kRowLanes);
        fem::productKernel<<<rowBlocks, kThreads, 0, stream>>>(model, v.data, av.data);
        fem::rightHandSideKernel<<<blocksFor(std::size_t(dofs)), kThreads, 0, stream>>>(
            model, force.data, external.data, v.data, av.data, h, alpha, beta, massFactor, stiffnessFactor, rhs.data, dv.data);
        fem::cgInitKernel<<<rowBlocks, kThreads, 0, stream>>>(model, rhs.data, dv.data, inverseDiagonal.data, r.data,
                                                              z.data, p.data, q.data, s);
        for (int k = 0; k < settings.cgMaxIterations; ++k)
        {
            fem::cgDirectionKernel<<<rowBlocks, kThreads, 0, stream>>>(model, z.data, p.data, q.data, s,
                                                                       settings.cgTolerance, settings.cgMaxIterations);
            fem::cgUpdateKernel<<<blocksFor(nodes), kThreads, 0, stream>>>(model, inverseDiagonal.data, dv.data, r.data,
                                                                          z.data, p.data, q.data, s, settings.cgTolerance,
                                                                          settings.cgMaxIterations);
        }
        fem::finishKernel<<<blocksFor(std::size_t(dofs)), kThreads, 0, stream>>>(dofs, dv.data, h, v.data, x.data);
        VSIM_CUDA_CHECK(cudaStreamEndCapture(stream, &graph));
        VSIM_CUDA_CHECK(cudaGraphInstantiate(&graphExec, graph, 0));
    }
};

CudaBackwardEuler::CudaBackwardEuler(const sim::fem::CorotationalFem& model, const sim::fem::BackwardEulerSettings& settings,
                                     const std::vector<std::uint8_t>& constrained,
                                     const std::vector<std::array<int, 3>>& pressureFaces)
    : m_device(std::make_unique<Device>())
{
    int deviceCount = 0;
    if (cudaGetDeviceCount(&deviceCount) != cudaSuccess || deviceCount == 0)
        throw Error("no CUDA device: run the wall solver on the CPU (--backend cpu)");
    Device& d = *m_device;
    d.settings = settings;
    d.nodes = model.nodeCount();
    const std::size_t elements = model.elementCount();

    std::vector<int> tets;
    tets.reserve(4 * elements);
    for (const auto& tet : model.tets())
        tets.insert(tets.end(), tet.begin(), tet.end());
    std::vector<double> rest, restInverse(9 * elements), stiffness(144 * elements), quaternions(4 * elements);
    for (const Eigen::Vector3d& point : model.restPositions())
        rest.insert(rest.end(), {point.x(), point.y(), point.z()});
    for (std::size_t e = 0; e < elements; ++e)
    {
        const sim::fem::TetRest& element = model.elements()[e];
        for (int r = 0; r < 3; ++r)
            for (int c = 0; c < 3; ++c)
                restInverse[9 * e + std::size_t(3 * r + c)] = element.restEdgesInverse(r, c);
        for (int r = 0; r < 12; ++r)
            for (int c = 0; c < 12; ++c)
                stiffness[std::size_t(12 * r + c) * elements + e] = element.stiffness(r, c); // entry-major
        const Eigen::Quaterniond q(model.rotation(e));
        quaternions[4 * e] = q.w(), quaternions[4 * e + 1] = q.x(), quaternions[4 * e + 2] = q.y(),
                        quaternions[4 * e + 3] = q.z();
    }
    std::vector<double> freeMask(3 * d.nodes, 1.0);
    for (std::size_t i = 0; i < constrained.size() && i < freeMask.size(); ++i)
        freeMask[i] = constrained[i] ? 0.0 : 1.0;
    std::vector<int> faces;
    for (const auto& face : pressureFaces)
        faces.insert(faces.end(), face.begin(), face.end());
    const sim::fem::BlockSparseMatrix pattern = model.makeMatrix();
    std::vector<std::uint32_t> diagonalSlot(d.nodes);
    for (std::size_t n = 0; n < d.nodes; ++n)
        for (std::uint32_t s = pattern.rowStart()[n]; s < pattern.rowStart()[n + 1]; ++s)
            if (pattern.columns()[s] == n)
                diagonalSlot[n] = s;

    VSIM_CUDA_CHECK(cudaStreamCreate(&d.stream));
    d.tets.upload(tets);
    d.faces.upload(faces);
    d.rest.upload(rest);
    d.restInverse.upload(restInverse);
    d.stiffness.upload(stiffness);
    d.mass.upload(toVector(model.lumpedMass()));
    d.freeMask.upload(freeMask);
    d.quaternions.upload(quaternions);
    d.elementForces.zero(12 * elements);
    d.elementBlocks.zero(90 * elements);
    d.matrix.zero(9 * pattern.blockCount());
    d.rowStart.upload(pattern.rowStart());
    d.columns.upload(pattern.columns());
    d.diagonalSlot.upload(diagonalSlot);
    d.blockEntryStart.upload(model.blockEntryStart());
    d.blockEntries.upload(model.blockEntries());
    d.nodeEntryStart.upload(model.nodeEntryStart());
    d.nodeEntries.upload(model.nodeEntries());
    d.x.upload(toVector(model.positions()));
    d.v.upload(toVector(model.velocities()));
    for (Buffer<double>* buffer : {&d.dv, &d.force, &d.external, &d.av, &d.rhs, &d.r, &d.z, &d.p, &d.q})
        buffer->zero(3 * d.nodes);
    d.inverseDiagonal.zero(9 * d.nodes);
    d.scalars.zero(1);

    fem::DeviceModel& m = d.model;
    m.nodes = int(d.nodes), m.elements = int(elements), m.blocks = int(pattern.blockCount()), m.faces = int(pressureFaces.size());
    m.tets = d.tets.data, m.rest = d.rest.data, m.restEdgesInverse = d.restInverse.data, m.stiffness = d.stiffness.data;
    m.mass = d.mass.data, m.freeMask = d.freeMask.data, m.faces3 = d.faces.data, m.quaternions = d.quaternions.data;
    m.elementForces = d.elementForces.data, m.elementBlocks = d.elementBlocks.data, m.rowStart = d.rowStart.data;
    m.columns = d.columns.data, m.diagonalSlot = d.diagonalSlot.data, m.matrix = d.matrix.data;
    m.blockEntryStart = d.blockEntryStart.data, m.blockEntries = d.blockEntries.data;
    m.nodeEntryStart = d.nodeEntryStart.data, m.nodeEntries = d.nodeEntries.data;
    d.bytes = 0;
    for (std::size_t n : {d.tets.count * 4, d.faces.count * 4, d.rest.count * 8, d.restInverse.count * 8, d.stiffness.count * 8,
                          d.mass.count * 8, d.freeMask.count * 8, d.quaternions.count * 8, d.elementForces.count * 8,
                          d.elementBlocks.count * sizeof(fem::MatrixReal), d.matrix.count * sizeof(fem::MatrixReal),
                          d.rowStart.count * 4, d.columns.count * 4,
                          d.blockEntries.count * 4, d.nodeEntries.count * 4, d.inverseDiagonal.count * 8, 13 * 3 * d.nodes * 8})
        d.bytes += n;
    d.record();
}

CudaBackwardEuler::~CudaBackwardEuler() = default;

sim::fem::StepReport CudaBackwardEuler::step(double pressurePa)
{
    Device& d = *m_device;
    VSIM_CUDA_CHECK(cudaMemcpyAsync(&d.scalars.data->pressure, &pressurePa, sizeof(double), cudaMemcpyHostToDevice, d.stream));
    VSIM_CUDA_CHECK(cudaGraphLaunch(d.graphExec, d.stream));
    fem::DeviceScalars scalars{};
    VSIM_CUDA_CHECK(cudaMemcpyAsync(&scalars, d.scalars.data, sizeof scalars, cudaMemcpyDeviceToHost, d.stream));
    VSIM_CUDA_CHECK(cudaStreamSynchronize(d.stream));
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

} // namespace vsim::cuda
