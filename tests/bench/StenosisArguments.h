#pragma once

// The stenosis benches' solver arguments (parameter=value): a smoothing ratio among them shapes the pipe's open ends
// too, whose buffers are a kernel support deep (OpenBoundaries::initialize refuses another depth), so it goes into
// the StenosisPipe before its open ends and particles are made.

#include "vsim/sim/sph/StenosisPipe.h"

#include <string>

namespace vsim::bench {

inline void takeSmoothingRatio(sim::sph::StenosisPipe& pipe, int first, int argc, char** argv)
{
    const std::string key = "smoothing_ratio=";
    for (int a = first; a < argc; ++a)
        if (const std::string text = argv[a]; text.rfind(key, 0) == 0)
            pipe.smoothingRatio = std::stod(text.substr(key.size()));
}

} // namespace vsim::bench
