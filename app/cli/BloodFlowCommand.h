#pragma once

#include "CliCommands.h"

namespace vsim::cli {

/// `simulate sph --study S [--inlet 5ml/s|0.3m/s|90mmHg[@NODE]] [--outlet 0mmHg] [--waveform FILE] [--profile
/// parabolic|plug] [--spacing 0.5mm] [--until 0.2s] [--ramp 0.05s] [--void-fraction 0] [--compare 6mm]
/// [--frames 20] [--backend auto|cpu|cuda] [--centerlines ID] [--param key=value ...] [--out DIR]`: blood flow through
/// the study's vessels with SPH (app/BloodFlowPipeline.h), added to the study as a Run with its stenosis figures;
/// prints the run as JSON and writes its frames to DIR.
int simulateSph(const Arguments& arguments, const Progress& progress);

/// `simulate injection --study S [--needle-bore 1.2mm] [--rate 300] [--needle-end NODE] [--box-depth 15mm]
/// [--box-margin 10mm] [--spacing 0.4mm] [--until 0.3s] [--void-fraction 0.2] [--gauge 40mmHg] [--frames 10]
/// [--backend auto|cpu|cuda] [--centerlines ID] [--param key=value ...] [--out DIR]`: thesis scenario (a), the needle
/// injection (app/InjectionPipeline.h), added to the study as a Run; prints the run as JSON and writes its frames to
/// DIR.
int simulateInjection(const Arguments& arguments, const Progress& progress);

} // namespace vsim::cli
