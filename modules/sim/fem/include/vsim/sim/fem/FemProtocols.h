#pragma once

// The protocols of `vascusim-cli simulate fem` and the GUI (parameters declared once, SI conversion here):
//  thesis-rupture  the thesis's experiment (ch. 4.7): E = 4.23 MPa, nu = 0.23, both ends fixed, a pressure ramp
//                  8 -> 12 MPa on the middle third of the lumen ("mid-vessel boundary pressure"), tearing at the
//                  tear strength, stopping on the fracture entropy; reports the tearing onset pressure (thesis:
//                  10.4 MPa) and the entropy curve, by the thesis's damped ramp; quasi_static 1 tears
//                  quasi-statically instead (QuasiStaticTearing.h: equilibrium at each pressure, the onset by
//                  bisection, one element released per equilibrium), which at the thesis's pressures finds no
//                  equilibrium (they are beyond what the wall holds). These pressures are about 600 times systolic: a reproduction,
//                  not physiology (SEED-NOTES.md).
//  physiological   wall stress at the patient's pressure (default 120 mmHg), static equilibrium, ends fixed (by
//                  default quadratic tets with the Raghavan-Vorp 2000 wall, StaticWallRun.h): peak wall stress and where, and the peak rupture potential index against the wall strength of Vande Geest
//                  et al. 2006 (J Biomech Eng 128:1055, "Towards a noninvasive method for determination of
//                  patient-specific wall strength distribution in AAA").

#include "vsim/core/Parameters.h"
#include "vsim/core/Progress.h"
#include "vsim/core/SkeletonGraph.h"
#include "vsim/core/TetMesh.h"
#include "vsim/sim/fem/FemRun.h"
#include "vsim/sim/fem/SacPeaks.h"
#include "vsim/sim/fem/StaticSolver.h"

#include <map>
#include <string>
#include <vector>

namespace vsim::sim::fem {

/// Every parameter of the wall runs (material, integration, both protocols, the patient's strength inputs).
std::vector<ParameterSpec> femParameters();
/// The parameters a protocol ("physiological", "thesis-rupture", "interactive") uses: the physiological protocol
/// steps with settle_time_step_ms instead of time_step_ms and has no ramp or tearing, the thesis protocol has no
/// blood pressure or strength inputs. Throws vsim::Error for an unknown protocol.
std::vector<ParameterSpec> femProtocolParameters(const std::string& protocol);
/// Whether `protocol` with these parameters runs the quadratic hyperelastic wall (StaticWallRun.h, CPU only):
/// the physiological protocol with wall_model 1.
bool femUsesQuadraticWall(const std::string& protocol, const ParameterSet& parameters);
/// Whether `protocol` with these parameters tears quasi-statically (QuasiStaticTearing.h, CPU only): the thesis
/// protocol with quasi_static 1.
bool femUsesQuasiStaticTearing(const std::string& protocol, const ParameterSet& parameters);
/// The values (as provenance text) of the parameters `protocol` uses with these values, nothing else.
std::map<std::string, std::string> femProtocolValues(const ParameterSet& parameters, const std::string& protocol);
/// The material and the integrator settings of a parameter set (SI).
ElasticMaterial femMaterial(const ParameterSet& parameters);
BackwardEulerSettings femIntegrator(const ParameterSet& parameters);

/// The thesis protocol on a wall mesh (mm).
/// `stepper`: where the implicit steps run (FemRunSetup::stepper; empty: this CPU), in both protocols;
/// `staticModel`: where the quasi-static tearing's equilibria run (with modified_newton 1; empty: this CPU).
FemRunResult runThesisRupture(const TetMesh& wall, const ParameterSet& parameters, const Progress& progress = {},
                              const StepperFactory& stepper = {}, const StaticModelFactory& staticModel = {});

/// The physiological protocol; `centerlines` (mm, with radii) give each element's local diameter for the
/// strength model. Adds metrics peak_rupture_index, its location, the strength there and max_diameter_mm; with a
/// `sac`, the figures inside it (SacPeaks.h): sac_elements, sac_pws_{p99,nodal_max}_kpa and
/// sac_pwri_{p99,nodal_max}, each nodal maximum's _x/_y/_z_mm, _along_centerline_mm and _clock_h; the sac's peaks
/// leave out the elements within held_end_band_mm (10 mm) of the wall's held ends (sac_elements_near_held_ends).
FemRunResult runPhysiological(const TetMesh& wall, const SkeletonGraph& centerlines, const ParameterSet& parameters,
                              const Progress& progress = {}, const StepperFactory& stepper = {},
                              const SacRegion* sac = nullptr);

/// AAA wall strength (Pa) by Vande Geest et al. 2006: 71.9 - 37.9 (ILT^1/2 - 0.81) - 15.6 (NORD - 2.46)
/// - 21.3 HIST + 19.3 SEX N/cm^2, with ILT the local thrombus thickness (cm), NORD the local diameter over the
/// non-aneurysmal reference, HIST +-0.5 (family history yes / no), SEX +-0.5 (female / male).
double vandeGeestWallStrength(double thrombusCm, double normalizedDiameter, bool familyHistory, bool female);

} // namespace vsim::sim::fem
