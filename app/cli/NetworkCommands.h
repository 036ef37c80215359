#pragma once

#include "CliCommands.h"

namespace vsim::cli {

/// `simulate network --study S --tip ID|x,y,z [--rate 2ml/min (or g/min, ml/s, mg/s) | --tip-pressure mmHg]
/// [--void-fraction 0.1] [--tumour x,y,z,r |
/// --tumour-label ID [--tumour-value N]]
/// [--control x,y,z ...] [--network FILE [--default-outlets murray]] [--centerlines ID] [--param key=value ...]
/// [--out DIR]`: the drug flow from the catheter tip through the study's vessel network (or the network file, whose
/// outlets need conditions unless --default-outlets murray), added to the study with its metrics; prints the run
/// as JSON and writes its files to DIR.
int simulateNetwork(const Arguments& arguments, const Progress& progress);

} // namespace vsim::cli
