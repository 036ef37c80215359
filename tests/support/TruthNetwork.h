#pragma once

// A phantom's truth geometry as a drug network: its nodes, and each vessel segment as a conical pipe with the
// truth radii at its ends and its length; the root is the start of the segment without a parent. What an imaged
// network is measured against.

#include "vsim/core/VesselNetwork.h"
#include "vsim/dicom/PhantomModel.h"

namespace vsim::test {

inline VesselNetwork truthNetwork(const dicom::PhantomModel& model)
{
    VesselNetwork network;
    for (const dicom::VesselNode& node : model.nodes)
        network.nodes.push_back({node.position, {}});
    for (const dicom::VesselSegment& segment : model.segments)
    {
        VesselNetwork::Segment pipe;
        pipe.from = segment.from, pipe.to = segment.to;
        pipe.startRadiusMm = segment.radii.front(), pipe.endRadiusMm = segment.radii.back();
        pipe.lengthMm = segment.lengthMm();
        network.segments.push_back(pipe);
        if (segment.parent < 0)
            network.root = segment.from;
    }
    network.validate();
    return network;
}

} // namespace vsim::test
