#pragma once

#include "CliCommands.h"

namespace vsim::cli {

/// `mesh wall --study S [--label ID] [--centerlines ID] [--thickness mm] [--target-vertices N]`: the tetrahedral
/// wall around the lumen surface (decimated to N vertices), opened at the centerline ends, into the study;
/// `mesh sheet` a thin cloth-type sheet; `mesh import FILE.vtu` a mesh from outside with its pressure faces and held
/// nodes selected (app::asWall).
int meshWall(const Arguments& arguments, const Progress& progress);

/// `simulate fem --study S --protocol thesis-rupture|physiological [--mesh ID] [--centerlines ID] [--backend
/// auto|cpu|cuda] [--param key=value ...] [--out DIR]`: runs the wall solver, adds the last frame (stresses, rupture
/// index) to the study with the metrics, prints the metrics as JSON, and writes the frame series to DIR.
int simulateFem(const Arguments& arguments, const Progress& progress);

} // namespace vsim::cli
