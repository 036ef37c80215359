#pragma once

// A saved SPH run to go on from (issue 18): a GPU run longer than one call of the device it runs on (the
// benches' --checkpoint), written at a step's end, read back by SphSolver::setStartState before its
// initialize(). The leapfrog step takes its first kick with rates evaluated between the last step's two kicks,
// so the checkpoint holds them beside the particles (in their order), the time and the counters: a CPU run
// gone on from one is the run that did not stop, to the last bit (tst_sph_stepper); a GPU run, to its single
// precision's rounding (the particles are sorted afresh, so their sums run in another order; tst_gpu_sph).
//
// The file is binary, in the writing machine's byte order and double precision (the same program on a machine
// of the same kind reads it back; not an exchange format): the header line "VSIM-SPH-CHECKPOINT 2", then the
// counters, the mass ledger, the particles (every ParticleState array), the rates of the next kick, the open
// boundaries' last flow rates and pressures, the time averages' sums (the sections' phase window's too: new in
// version 2) and the caller's named numbers, and the header again as the end mark. It is written beside its name
// and renamed over it, so that a run stopped while writing leaves the last whole checkpoint.

#include "vsim/sim/sph/CrossSections.h"
#include "vsim/sim/sph/OpenBoundary.h"
#include "vsim/sim/sph/ParticleState.h"
#include "vsim/sim/sph/SphRates.h"
#include "vsim/sim/sph/WallShear.h"

#include <filesystem>
#include <map>
#include <string>

namespace vsim::sim::sph {

struct SphCheckpoint
{
    double timeS = 0.0;
    long steps = 0;
    int nextId = 0;                    ///< the number the next particle an inlet creates takes
    MassLedger ledger;                 ///< since the run's start
    long double initialFluidMassKg = 0.0; ///< the fluid's mass at the run's start (the mass balance's origin)
    ParticleState particles;
    /// The rates the next step's first kick takes, in the particles' order (SphRates: acceleration, densityRate,
    /// shiftVelocity, wallDistance and the three largest values; the rest is recomputed before it is read). The
    /// step evaluates them between its two kicks, so they cannot be recomputed from the particles. The GPU's
    /// stepper gives its own (single precision) and takes them back. Empty from a stepper that does not give
    /// them: the resumed run then evaluates them at the saved state, half a kick's difference in the viscous and
    /// density terms, once.
    SphRates rates;
    std::vector<double> boundaryFlowRateM3S, boundaryPressurePa; ///< each open boundary's last (OpenBoundaries)
    SectionSeries::Sums sections;      ///< the time averages so far
    WallLoadSeries::Sums wallLoads;
    std::map<std::string, double> counters; ///< the caller's own (a bench's timings, its largest density variation)
};

/// Writes `checkpoint` to `file` (through `file`.part, renamed). Refuses (vsim::Error naming the file) to replace
/// a file that is not a checkpoint: it never overwrites what it did not write.
void writeSphCheckpoint(const SphCheckpoint& checkpoint, const std::filesystem::path& file);

/// Reads a checkpoint; throws vsim::Error naming the file when it is missing, not a checkpoint, of another version
/// or cut short.
SphCheckpoint readSphCheckpoint(const std::filesystem::path& file);

/// Whether `file` starts with the checkpoint's header.
bool isSphCheckpoint(const std::filesystem::path& file);

} // namespace vsim::sim::sph
