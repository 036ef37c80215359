#include "WallDevice.cuh"

#include <Eigen/Geometry>

namespace vsim::cuda {

namespace {

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

WallDevice::WallDevice(const sim::fem::CorotationalFem& model, const sim::fem::BackwardEulerSettings& settings,
                       const std::vector<std::uint8_t>& constrained, const std::vector<std::array<int, 3>>& pressureFaces,
                       bool staticTangent)
    : staticTangent(staticTangent)
{
    int deviceCount = 0;
    if (cudaGetDeviceCount(&deviceCount) != cudaSuccess || deviceCount == 0)
        throw Error("no CUDA device: run the wall solver on the CPU (--backend cpu)");
    if (model.material().model != sim::fem::ElasticMaterial::Model::CorotationalLinear)
        throw Error("the CUDA backend runs the co-rotational linear model only: run St. Venant-Kirchhoff on the CPU "
                    "(--backend cpu)");
    WallDevice& d = *this;
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
    // What a multigrid set-up from the device's matrix needs (setUpMultigridFromDevice).
    d.constrained = constrained;
    d.hostTets = model.tets();
    d.hostRowStart = symmetric.rowStart;
    d.hostColumns = symmetric.columns;
    if (settings.preconditioner == sim::fem::CgPreconditioner::Multigrid)
    {
        // The hierarchy from the first step's matrix, as the CPU path sets it up (BackwardEuler::step).
        sim::fem::CorotationalFem first = model;
        first.updateElements();
        sim::fem::BlockSparseMatrix matrix = first.makeMatrix();
        const double h = settings.timeStep;
        if (staticTangent)
        {
            first.assemble(matrix, 0.0, 1.0);
            first.addRotationStiffness(matrix);
        }
        else
            first.assemble(matrix, 1.0 + h * settings.rayleighAlpha, h * settings.rayleighBeta + h * h);
        d.setUpMultigrid(matrix, first.positions());
    }
    d.record();
}

} // namespace vsim::cuda
