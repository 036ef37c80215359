#pragma once

#include "CliCommands.h"

namespace vsim::cli {

/// `simulate sph --study S [--inlet 5ml/s|0.3m/s|90mmHg[@NODE]] [--outlet 0mmHg] [--waveform FILE] [--profile
/// parabolic|plug] [--spacing 0.5mm] [--until 0.2s] [--ramp 0.05s] [--void-fraction 0] [--compare 6mm]
/// [--frames 20] [--backend auto|cpu|cuda] [--centerlines ID] [--param key=value ...] [--out DIR]`: blood flow through
/// the study's vessels with SPH (app/BloodFlowPipeline.h), added to the study as a Run with its stenosis figures;
/// prints the run as JSON and writes its frames to DIR.
int simulateSph(const Arguments& arguments, const Progress& progress);

} // namespace vsim::cli
