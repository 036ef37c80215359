#pragma once

// The AAA sac as a study artifact, the same from the CLI (`sac`) and the workstation: its labels (1 lumen,
// 4 thrombus, 5 wall) with the figures in the provenance (the report and the measurement dock read them there).

#include "vsim/imaging/AneurysmSac.h"
#include "vsim/study/Study.h"

#include <map>
#include <optional>
#include <string>

namespace vsim::app {

/// Adds the sac measured from label `lumenId` on image `imageId` to the study (not saved); returns its id.
std::string recordAneurysmSac(study::Study& study, const imaging::AneurysmSac& sac, const std::string& imageId,
                              const std::string& lumenId, double wallThicknessMm);

/// The newest sac artifact's figures (key -> value, units in the keys); empty when the study has none.
std::map<std::string, double> newestSacFigures(const study::Study& study, std::string* sacId = nullptr);

/// The newest label that is a lumen (not a sac's labels); "" when none.
std::string newestLumenLabel(const study::Study& study);

} // namespace vsim::app
