#pragma once

// The anatomical names of a centerlines artifact's segments as the CLI, the measurement dock and the report show
// them: a name the user gave (kept as the artifact's "segment_name.<index>" attribute) else the automatic name from
// topology and position (imaging::nameVesselSegments; none for a label segmented with target "all").

#include "vsim/core/SkeletonGraph.h"
#include "vsim/study/Study.h"

#include <string>
#include <vector>

namespace vsim::app {

/// One name per edge of `centerlines` (the data of artifact `centerlinesId`).
std::vector<std::string> segmentNames(const study::Study& study, const std::string& centerlinesId,
                                      const SkeletonGraph& centerlines);

/// Records the user's name for segment `index` (0-based edge index) of a centerlines artifact, saved with the
/// study. Throws vsim::Error for an unknown artifact, an index out of range or an empty name.
void renameSegment(study::Study& study, const std::string& centerlinesId, std::size_t index, const std::string& name);

/// How a segment is titled in a table or a line of text: its name (an anatomical one in the reader's language,
/// one a user typed as typed), and for an unnamed one its node numbers ("unnamed (nodes 4-7)", likewise).
std::string segmentTitle(const std::string& name, int fromNode, int toNode);

} // namespace vsim::app
