#pragma once

// One-way coupling of the blood flow to the wall (issue 18): a blood-flow run's time-averaged wall pressure
// ("Wall loads (SPH)", BloodFlowPipeline.h) put on a wall mesh's lumen points as the pressure added to the wall
// protocol's uniform lumen pressure (sim/fem/StaticWallRun.h: kLumenExtraPressureField). The flow's pressures are
// taken relative to its outlets, so the protocol's pressure stands for the outlets' level and the flow adds what
// the vessel's resistance, the jets and the bends put on top of it.

#include "vsim/core/TetMesh.h"
#include "vsim/study/Study.h"

#include <string>

namespace vsim::app {

struct FlowWallPressure
{
    std::string wallLoadsId;        ///< the "Wall loads (SPH)" artifact read
    std::string runId;              ///< its blood-flow run
    std::size_t lumenPoints = 0;    ///< the wall's points on the lumen (wall_layer 0)
    std::size_t coveredPoints = 0;  ///< those with a flow value within kFlowPressureReachMm
    double smallestPa = 0.0, largestPa = 0.0; ///< the added pressure over the covered points (relative to the outlets)
};

/// How far (mm) a lumen point may lie from the flow's nearest wall vertex with a value: the two surfaces are made
/// from the same label by different meshers (a voxel or two apart); farther points (a vessel the flow did not run
/// through, past an open end) get nothing added, and are counted.
inline constexpr double kFlowPressureReachMm = 2.0;

/// Puts the study's newest blood-flow wall pressure on `wall`'s lumen points (mm) as kLumenExtraPressureField: each
/// point the nearest flow vertex's wall_pressure_pa less the run's outlet pressure, 0 where none lies within reach.
/// Throws vsim::Error when the study has no blood-flow wall loads or the wall has no wall_layer field.
FlowWallPressure addFlowWallPressure(const study::Study& study, TetMesh& wall);

} // namespace vsim::app
