#include "vsim/cuda_fem/CudaBackwardEuler.h"

#include "vsim/cuda_common/DeviceBuffer.cuh"
#include "DeviceMultigrid.cuh"
#include "FemKernels.cuh"
#include "vsim/cuda_common/CudaCheck.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <vector>

namespace vsim::cuda {

namespace {

constexpr int kThreads = 256;
/// PCG iterations per graph replay with the multigrid preconditioner (tens of iterations a step).
constexpr int kMultigridRun = 4;

int blocksFor(std::size_t count) { return int((count + kThreads - 1) / kThreads); }

std::vector<double> toVector(const Eigen::VectorXd& v) { return std::vector<double>(v.data(), v.data() + v.size()); }

/// The index lists of the symmetric storage (FemKernels.cuh, DeviceModel) built from the full block pattern.
struct SymmetricPattern
{
    std::vector<std::uint32_t> rowStart{0}, columns, lowerRowStart{0}, lowerSlots, lowerColumns;
    std::vector<std::uint32_t> assembledSource; // full-pattern slot of each stored block (kDiagonalBlock: none)
};

SymmetricPattern symmetricPattern(const sim::fem::BlockSparseMatrix& full)
{
    const std::size_t nodes = full.rowStart().size() - 1;
    SymmetricPattern p;
    std::vector<std::vector<std::pair<std::uint32_t, std::uint32_t>>> lower(nodes); // (stored block, column)
    for (std::uint32_t row = 0; row < nodes; ++row)
    {
        const std::uint32_t begin = full.rowStart()[row], end = full.rowStart()[row + 1];
        for (std::uint32_t s = begin; s < end; ++s) // the diagonal block first
            if (full.columns()[s] == row)
                p.columns.push_back(row), p.assembledSource.push_back(fem::kDiagonalBlock);
        for (std::uint32_t s = begin; s < end; ++s)
        {
            const std::uint32_t column = full.columns()[s];
            if (column > row)
            {
                lower[column].emplace_back(std::uint32_t(p.columns.size()), row); // rows ascending
                p.columns.push_back(column);
                p.assembledSource.push_back(s);
            }
        }
        p.rowStart.push_back(std::uint32_t(p.columns.size()));
    }
    for (const auto& row : lower)
    {
        for (const auto& [block, column] : row)
            p.lowerSlots.push_back(block), p.lowerColumns.push_back(column);
        p.lowerRowStart.push_back(std::uint32_t(p.lowerSlots.size()));
    }
    return p;
}

} // namespace

struct CudaBackwardEuler::Device
{
    sim::fem::BackwardEulerSettings settings;
    std::size_t nodes = 0;
    Buffer<int> tets, faces;
    Buffer<double> rest, elementRecords, mass, freeMask, elementForces;
    Buffer<double> matrix;
    Buffer<std::uint32_t> rowStart, columns, lowerRowStart, lowerSlots, lowerColumns, assembledSource;
    Buffer<std::uint32_t> blockEntryStart, blockEntries, nodeEntryStart, forceSlots;
    Buffer<double> x, v, dv, force, external, av, rhs, inverseDiagonal, r, z, p, q, partials;
    int rowBlocks = 0, nodeBlocks = 0; // grids of the PCG kernels: what the GPU holds at once, or fewer
    Buffer<fem::DeviceScalars> scalars;
    fem::DeviceModel model;
    cudaStream_t stream = nullptr;
    // The step as four graphs: the element pass, assembly and right-hand side; the PCG's start; a run of
    // iterations (replayed until the PCG stops: all of them in one run with block Jacobi, kMultigridRun with
    // multigrid, whose V-cycles make idle iterations dear); and the update.
    struct Graph
    {
        cudaGraph_t graph = nullptr;
        cudaGraphExec_t exec = nullptr;
    } assembly, pcgStart, iterations, finish;
    int iterationsPerRun = 0;
    std::size_t bytes = 0;
    // Multigrid (CgPreconditioner::Multigrid): the hierarchy, and what setting it up again from the device's matrix
    // takes (BackwardEuler's rule: again at the step after one whose iterations more than doubled those of the first
    // solve with the hierarchy, from that step's own matrix).
    std::unique_ptr<DeviceMultigrid> multigrid;
    std::vector<std::array<int, 4>> hostTets;
    std::vector<std::uint32_t> hostRowStart, hostColumns; // the symmetric storage's pattern
    std::vector<std::uint8_t> constrained;
    int iterationsAfterSetup = -1;
    bool setUpAgain = false;

    static void release(Graph& g)
    {
        if (g.exec)
            cudaGraphExecDestroy(g.exec);
        if (g.graph)
            cudaGraphDestroy(g.graph);
        g = Graph{};
    }

    ~Device()
    {
        for (Graph* g : {&assembly, &pcgStart, &iterations, &finish})
            release(*g);
        if (stream)
            cudaStreamDestroy(stream);
    }

    void setUpMultigrid(const sim::fem::BlockSparseMatrix& matrix, const Eigen::VectorXd& positions)
    {
        if (multigrid)
            bytes -= multigrid->bytes();
        multigrid.reset();
        multigrid = std::make_unique<DeviceMultigrid>(sim::fem::AggregationMultigrid(matrix, positions, constrained));
        bytes += multigrid->bytes();
        iterationsAfterSetup = -1;
    }

    /// The hierarchy from the matrix the assembly graph just formed, at the step's positions; the PCG's graphs
    /// recorded again for it.
    void setUpMultigridFromDevice()
    {
        std::vector<double> blocks(matrix.count), positions(3 * nodes);
        VSIM_CUDA_CHECK(cudaStreamSynchronize(stream));
        VSIM_CUDA_CHECK(cudaMemcpy(blocks.data(), matrix.data, matrix.bytes(), cudaMemcpyDeviceToHost));
        VSIM_CUDA_CHECK(cudaMemcpy(positions.data(), x.data, positions.size() * sizeof(double), cudaMemcpyDeviceToHost));
        sim::fem::BlockSparseMatrix full(nodes, hostTets);
        for (std::size_t row = 0; row < nodes; ++row)
            for (std::uint32_t t = hostRowStart[row]; t < hostRowStart[row + 1]; ++t)
            {
                const std::size_t column = hostColumns[t];
                const Eigen::Matrix3d block =
                    Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(blocks.data() + fem::kBlockStride * t);
                full.block(full.slotOf(row, column)) = block;
                if (column != row)
                    full.block(full.slotOf(column, row)) = block.transpose();
            }
        setUpMultigrid(full, Eigen::Map<const Eigen::VectorXd>(positions.data(), Eigen::Index(positions.size())));
        recordPcg();
    }

    template <typename Body>
    void capture(Graph& g, Body body)
    {
        release(g);
        VSIM_CUDA_CHECK(cudaStreamBeginCapture(stream, cudaStreamCaptureModeThreadLocal));
        body();
        VSIM_CUDA_CHECK(cudaStreamEndCapture(stream, &g.graph));
        VSIM_CUDA_CHECK(cudaGraphInstantiate(&g.exec, g.graph, 0));
    }

    /// z = M r with the multigrid V-cycle, then r.z (the PCG's rz and beta).
    void recordCycle()
    {
        const fem::CycleGuard guard{scalars.data, settings.cgTolerance, settings.cgMaxIterations};
        multigrid->record(stream, model, inverseDiagonal.data, r.data, z.data, guard);
        fem::cgDotKernel<<<nodeBlocks, kThreads, 0, stream>>>(int(3 * nodes), r.data, z.data, partials.data,
                                                              scalars.data, settings.cgTolerance,
                                                              settings.cgMaxIterations);
    }

    void record()
    {
        const double h = settings.timeStep, alpha = settings.rayleighAlpha, beta = settings.rayleighBeta;
        const double massFactor = 1.0 + h * alpha, stiffnessFactor = h * beta + h * h;
        const int dofs = int(3 * nodes);
        capture(assembly, [&] { recordAssembly(h, alpha, beta, massFactor, stiffnessFactor, dofs, scalars.data); });
        recordPcg();
        capture(finish, [&] {
            fem::finishKernel<<<blocksFor(std::size_t(dofs)), kThreads, 0, stream>>>(dofs, dv.data, h, v.data, x.data);
        });
    }

    void recordPcg()
    {
        fem::DeviceScalars* s = scalars.data;
        capture(pcgStart, [&] {
            fem::cgInitKernel<<<rowBlocks, kThreads, 0, stream>>>(model, rhs.data, dv.data, inverseDiagonal.data,
                                                                  r.data, z.data, p.data, q.data, partials.data, s);
            if (multigrid)
                recordCycle();
        });
        iterationsPerRun = multigrid ? std::min(kMultigridRun, settings.cgMaxIterations) : settings.cgMaxIterations;
        capture(iterations, [&] {
            for (int k = 0; k < iterationsPerRun; ++k)
            {
                fem::cgDirectionKernel<<<rowBlocks, kThreads, 0, stream>>>(model, z.data, p.data, q.data, partials.data,
                                                                           s, settings.cgTolerance, settings.cgMaxIterations);
                fem::cgUpdateKernel<<<nodeBlocks, kThreads, 0, stream>>>(
                    model, multigrid ? nullptr : inverseDiagonal.data, dv.data, r.data, z.data, p.data, q.data,
                    partials.data, s, settings.cgTolerance, settings.cgMaxIterations);
                if (multigrid)
                    recordCycle();
            }
        });
    }

    void recordAssembly(double h, double alpha, double beta, double massFactor, double stiffnessFactor, int dofs,
                        fem::DeviceScalars* s)
    {
        fem::resetKernel<<<1, 1, 0, stream>>>(s);
        fem::elementKernel<<<blocksFor(std::size_t(model.elements)), kThreads, 0, stream>>>(model, x.data, s);
        fem::assembleKernel<<<blocksFor(std::size_t(model.storedBlocks)), kThreads, 0, stream>>>(model, stiffnessFactor);
        fem::diagonalKernel<<<blocksFor(nodes * fem::kRowLanes), kThreads, 0, stream>>>(model, massFactor);
        fem::forceKernel<<<blocksFor(nodes), kThreads, 0, stream>>>(model, force.data);
        VSIM_CUDA_CHECK(cudaMemsetAsync(external.data, 0, std::size_t(dofs) * sizeof(double), stream));
        if (model.faces > 0)
            fem::pressureKernel<<<blocksFor(std::size_t(model.faces)), kThreads, 0, stream>>>(model, x.data, s, external.data);
        fem::productKernel<<<blocksFor(nodes * fem::kRowLanes), kThreads, 0, stream>>>(model, v.data, av.data);
        fem::rightHandSideKernel<<<blocksFor(std::size_t(dofs)), kThreads, 0, stream>>>(
            model, force.data, external.data, v.data, av.data, h, alpha, beta, massFactor, stiffnessFactor, rhs.data, dv.data);
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
    if (model.material().model != sim::fem::ElasticMaterial::Model::CorotationalLinear)
        throw Error("the CUDA backend runs the co-rotational linear model only: run St. Venant-Kirchhoff on the CPU "
                    "(--backend cpu)");
    Device& d = *m_device;
    d.settings = settings;
    d.nodes = model.nodeCount();
    const std::size_t elements = model.elementCount();

    std::vector<int> tets;
    tets.reserve(4 * elements);
    for (const auto& tet : model.tets())
        tets.insert(tets.end(), tet.begin(), tet.end());
    std::vector<double> rest, elementRecords(16 * elements, 0.0);
    const double lambda = model.material().lambda(), mu = model.material().mu();
    for (const Eigen::Vector3d& point : model.restPositions())
        rest.insert(rest.end(), {point.x(), point.y(), point.z()});
    for (std::size_t e = 0; e < elements; ++e)
    {
        const sim::fem::TetRest& element = model.elements()[e];
        for (int r = 0; r < 3; ++r)
            for (int c = 0; c < 3; ++c)
                elementRecords[16 * e + std::size_t(4 + 3 * r + c)] = element.restEdgesInverse(r, c);
        elementRecords[16 * e + 13] = element.volume * lambda;
        elementRecords[16 * e + 14] = element.volume * mu;
        const Eigen::Quaterniond q(model.rotation(e));
        elementRecords[16 * e] = q.w(), elementRecords[16 * e + 1] = q.x(), elementRecords[16 * e + 2] = q.y(),
                        elementRecords[16 * e + 3] = q.z();
    }
    std::vector<double> freeMask(3 * d.nodes, 1.0);
    for (std::size_t i = 0; i < constrained.size() && i < freeMask.size(); ++i)
        freeMask[i] = constrained[i] ? 0.0 : 1.0;
    std::vector<int> faces;
    for (const auto& face : pressureFaces)
        faces.insert(faces.end(), face.begin(), face.end());
    const SymmetricPattern symmetric = symmetricPattern(model.makeMatrix());

    VSIM_CUDA_CHECK(cudaStreamCreate(&d.stream));
    d.tets.upload(tets);
    d.faces.upload(faces);
    d.rest.upload(rest);
    d.elementRecords.upload(elementRecords);
    d.mass.upload(toVector(model.lumpedMass()));
    d.freeMask.upload(freeMask);
    d.elementForces.zero(12 * elements);
    d.matrix.zero(std::size_t(fem::kBlockStride) * symmetric.assembledSource.size());
    d.rowStart.upload(symmetric.rowStart);
    d.columns.upload(symmetric.columns);
    d.lowerRowStart.upload(symmetric.lowerRowStart);
    d.lowerSlots.upload(symmetric.lowerSlots);
    d.lowerColumns.upload(symmetric.lowerColumns);
    d.assembledSource.upload(symmetric.assembledSource);
    d.blockEntryStart.upload(model.blockEntryStart());
    d.blockEntries.upload(model.blockEntries());
    d.nodeEntryStart.upload(model.nodeEntryStart());
    std::vector<std::uint32_t> forceSlots(4 * elements);
    for (std::uint32_t i = 0; i < model.nodeEntries().size(); ++i)
        forceSlots[model.nodeEntries()[i]] = i; // node entry 4 e + a
    d.forceSlots.upload(forceSlots);
    d.x.upload(toVector(model.positions()));
    d.v.upload(toVector(model.velocities()));
    for (Buffer<double>* buffer : {&d.dv, &d.force, &d.external, &d.av, &d.rhs, &d.r, &d.z, &d.p, &d.q})
        buffer->zero(3 * d.nodes);
    d.inverseDiagonal.zero(9 * d.nodes);
    d.scalars.zero(1);
    // The PCG kernels stride over the rows: one wave of resident blocks keeps every multiprocessor busy and the
    // grid-wide sums short.
    int multiprocessors = 0, device = 0, rowResident = 0, nodeResident = 0;
    VSIM_CUDA_CHECK(cudaGetDevice(&device));
    VSIM_CUDA_CHECK(cudaDeviceGetAttribute(&multiprocessors, cudaDevAttrMultiProcessorCount, device));
    VSIM_CUDA_CHECK(cudaOccupancyMaxActiveBlocksPerMultiprocessor(&rowResident, fem::cgDirectionKernel, kThreads, 0));
    VSIM_CUDA_CHECK(cudaOccupancyMaxActiveBlocksPerMultiprocessor(&nodeResident, fem::cgUpdateKernel, kThreads, 0));
    d.rowBlocks = std::max(1, std::min(blocksFor(d.nodes * fem::kRowLanes), multiprocessors * rowResident));
    const std::size_t updateThreads = 32 * ((d.nodes + fem::kNodesPerWarp - 1) / fem::kNodesPerWarp);
    d.nodeBlocks = std::max(1, std::min(blocksFor(updateThreads), multiprocessors * nodeResident));
    d.partials.zero(3 * std::size_t(std::max(d.rowBlocks, d.nodeBlocks)));

    fem::DeviceModel& m = d.model;
    m.nodes = int(d.nodes), m.elements = int(elements), m.storedBlocks = int(symmetric.columns.size()), m.faces = int(pressureFaces.size());
    m.tets = d.tets.data, m.rest = d.rest.data, m.elementRecords = d.elementRecords.data;
    m.mass = d.mass.data, m.freeMask = d.freeMask.data, m.faces3 = d.faces.data;
    m.elementForces = d.elementForces.data, m.matrix = d.matrix.data;
    m.rowStart = d.rowStart.data, m.columns = d.columns.data, m.lowerRowStart = d.lowerRowStart.data;
    m.lowerSlots = d.lowerSlots.data, m.lowerColumns = d.lowerColumns.data;
    m.assembledSource = d.assembledSource.data, m.blockEntryStart = d.blockEntryStart.data;
    m.blockEntries = d.blockEntries.data, m.nodeEntryStart = d.nodeEntryStart.data, m.forceSlots = d.forceSlots.data;
    d.bytes = 0;
    for (std::size_t n : {d.tets.count * 4, d.faces.count * 4, d.rest.count * 8, d.elementRecords.count * 8,
                          d.mass.count * 8, d.freeMask.count * 8, d.elementForces.count * 8,
                          d.matrix.count * 8,
                          d.rowStart.count * 4, d.columns.count * 4, d.lowerRowStart.count * 4,
                          d.lowerSlots.count * 4, d.lowerColumns.count * 4, d.assembledSource.count * 4,
                          d.blockEntryStart.count * 4, d.blockEntries.count * 4, d.nodeEntryStart.count * 4,
                          d.forceSlots.count * 4, d.inverseDiagonal.count * 8, 13 * 3 * d.nodes * 8})
        d.bytes += n;
    if (settings.preconditioner == sim::fem::CgPreconditioner::Multigrid)
    {
        // The hierarchy from the first step's matrix, as the CPU path sets it up (BackwardEuler::step).
        sim::fem::CorotationalFem first = model;
        first.updateElements();
        sim::fem::BlockSparseMatrix matrix = first.makeMatrix();
        const double h = settings.timeStep;
        first.assemble(matrix, 1.0 + h * settings.rayleighAlpha, h * settings.rayleighBeta + h * h);
        d.constrained = constrained;
        d.hostTets = model.tets();
        d.hostRowStart = symmetric.rowStart;
        d.hostColumns = symmetric.columns;
        d.setUpMultigrid(matrix, first.positions());
    }
    d.record();
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
    VSIM_CUDA_CHECK(cudaGraphLaunch(d.pcgStart.exec, d.stream));
    fem::DeviceScalars scalars{};
    do
    {
        VSIM_CUDA_CHECK(cudaGraphLaunch(d.iterations.exec, d.stream));
        VSIM_CUDA_CHECK(cudaMemcpyAsync(&scalars, d.scalars.data, sizeof scalars, cudaMemcpyDeviceToHost, d.stream));
        VSIM_CUDA_CHECK(cudaStreamSynchronize(d.stream));
    } while (!scalars.done && scalars.residual > d.settings.cgTolerance &&
             scalars.iterations < d.settings.cgMaxIterations);
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
