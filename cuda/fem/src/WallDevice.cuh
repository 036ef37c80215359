#pragma once

// The wall model's device state shared by the CUDA implicit step (CudaBackwardEuler.cu) and the CUDA static wall
// (CudaStaticWall.cu): the same buffers, matrix storage, element pass, assembly and PCG graphs.

#include "vsim/cuda_common/DeviceBuffer.cuh"
#include "DeviceMultigrid.cuh"
#include "FemKernels.cuh"
#include "vsim/cuda_common/CudaCheck.h"
#include "vsim/sim/fem/AggregationMultigrid.h"
#include "vsim/sim/fem/BackwardEuler.h"
#include "vsim/sim/fem/CorotationalFem.h"

#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <cstdint>
#include <memory>
#include <vector>

namespace vsim::cuda {

inline constexpr int kThreads = 256;
/// PCG iterations per graph replay with the multigrid preconditioner (tens of iterations a step).
inline constexpr int kMultigridRun = 4;

inline int blocksFor(std::size_t count) { return int((count + kThreads - 1) / kThreads); }

/// The wall model on the GPU and the graphs of its implicit step (CudaBackwardEuler) or of its static tangent
/// solve (CudaStaticWall): buffers, the symmetric matrix storage, the PCG with block Jacobi or the multigrid V-cycle.
struct WallDevice
{
    /// Copies the model (rest data, state, gather lists), the constraints and the pressure faces to the GPU and
    /// records the graphs. `staticTangent`: the matrix is the tangent R K R^T + the rotations' derivative (no mass;
    /// the settings' time step 1 and no damping), else the step's (1 + h alpha) M + (h beta + h^2) R K R^T. Throws
    /// vsim::Error without a CUDA device, for a model other than the co-rotational linear one, or out of memory.
    WallDevice(const sim::fem::CorotationalFem& model, const sim::fem::BackwardEulerSettings& settings,
               const std::vector<std::uint8_t>& constrained, const std::vector<std::array<int, 3>>& pressureFaces,
               bool staticTangent = false);

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
    } assembly, pcgStart, iterations, finish, elementPass;
    bool staticTangent = false;
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

    ~WallDevice()
    {
        for (Graph* g : {&assembly, &pcgStart, &iterations, &finish, &elementPass})
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
        const double massFactor = staticTangent ? 0.0 : 1.0 + h * alpha;
        const double stiffnessFactor = staticTangent ? 1.0 : h * beta + h * h;
        const int dofs = int(3 * nodes);
        capture(assembly, [&] { recordAssembly(h, alpha, beta, massFactor, stiffnessFactor, dofs, scalars.data); });
        recordPcg();
        capture(elementPass, [&] {
            fem::resetKernel<<<1, 1, 0, stream>>>(scalars.data);
            fem::elementKernel<<<blocksFor(std::size_t(model.elements)), kThreads, 0, stream>>>(model, x.data, scalars.data);
            fem::forceKernel<<<blocksFor(nodes), kThreads, 0, stream>>>(model, force.data);
        });
        capture(finish, [&] {
            fem::finishKernel<<<blocksFor(std::size_t(dofs)), kThreads, 0, stream>>>(dofs, dv.data, h, v.data, x.data);
        });
    }

    /// The PCG on the matrix and right-hand side in place: its start, then runs of iterations replayed until it
    /// stops (converged, broken down or at the cap); the last scalars.
    fem::DeviceScalars runPcg()
    {
        VSIM_CUDA_CHECK(cudaGraphLaunch(pcgStart.exec, stream));
        fem::DeviceScalars last{};
        do
        {
            VSIM_CUDA_CHECK(cudaGraphLaunch(iterations.exec, stream));
            VSIM_CUDA_CHECK(cudaMemcpyAsync(&last, scalars.data, sizeof last, cudaMemcpyDeviceToHost, stream));
            VSIM_CUDA_CHECK(cudaStreamSynchronize(stream));
        } while (!last.done && last.residual > settings.cgTolerance && last.iterations < settings.cgMaxIterations);
        return last;
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
        fem::assembleKernel<<<blocksFor(std::size_t(model.storedBlocks)), kThreads, 0, stream>>>(
            model, stiffnessFactor, staticTangent ? x.data : nullptr);
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


} // namespace vsim::cuda
