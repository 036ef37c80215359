#pragma once

// The CUDA backend of the wall solver: the same algorithm as sim::fem::BackwardEuler on the CPU (element pass
// with the Newton-scaled rotation extraction, gather assembly of the 3x3-block matrix, PCG with the constraint
// filter and block Jacobi or the multigrid V-cycle, warm start), in double precision, with the implicit step
// (element pass, assembly, pressure, right-hand side, PCG iterations that stop on the device when converged,
// update) recorded as CUDA graphs and replayed each step. No CUDA types in this header.

#include "vsim/sim/fem/BackwardEuler.h"
#include "vsim/sim/fem/CorotationalFem.h"
#include "vsim/sim/fem/ImplicitStepper.h"

#include <Eigen/Core>

#include <array>
#include <cstdint>
#include <memory>
#include <vector>

namespace vsim::cuda {

class CudaBackwardEuler final : public sim::fem::ImplicitStepper
{
public:
    /// Copies the model (rest data, state, gather lists), the constraints and the faces the pressure acts on to
    /// the GPU. Throws vsim::Error when there is no CUDA device, memory runs out or the model is not the
    /// co-rotational linear one.
    CudaBackwardEuler(const sim::fem::CorotationalFem& model, const sim::fem::BackwardEulerSettings& settings,
                      const std::vector<std::uint8_t>& constrained,
                      const std::vector<std::array<int, 3>>& pressureFaces);
    ~CudaBackwardEuler() override;
    CudaBackwardEuler(const CudaBackwardEuler&) = delete;
    CudaBackwardEuler& operator=(const CudaBackwardEuler&) = delete;

    /// One implicit step under `pressurePa` on the pressure faces (a follower load, as addPressureForces).
    sim::fem::StepReport step(double pressurePa) override;
    /// Copies the positions and velocities (m, m/s; 3 per node) back.
    void download(Eigen::VectorXd& positions, Eigen::VectorXd& velocities) const override;
    /// Bytes of GPU memory this solver holds.
    std::size_t deviceBytes() const;

private:
    struct Device;
    std::unique_ptr<Device> m_device;
};

/// The factory WallSimulation / the run driver take (sim::fem::StepperFactory): a CudaBackwardEuler per model.
sim::fem::StepperFactory cudaStepperFactory();

} // namespace vsim::cuda
