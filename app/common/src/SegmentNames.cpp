// Segment names of a centerlines artifact: the user's (artifact attributes) over the automatic anatomical ones.

#include "vsim/app/SegmentNames.h"

#include "vsim/app/NetworkPipeline.h"
#include "vsim/core/Error.h"
#include "vsim/core/Localized.h"
#include "vsim/core/StoredText.h"
#include "vsim/imaging/VesselNames.h"

namespace vsim::app {
namespace {

std::string attributeKey(std::size_t index)
{
    return "segment_name." + std::to_string(index);
}

/// Names are read from the aortic and hepatic patterns unless the label was segmented with target "all" (a
/// pulmonary or peripheral tree).
imaging::NamingScope scopeOf(const study::Study& study, const std::string& centerlinesId)
{
    const std::string labelId = labelOfCenterlines(study, centerlinesId);
    if (labelId.empty() || !study.hasArtifact(labelId))
        return imaging::NamingScope::AorticAndHepatic;
    const auto& parameters = study.artifact(labelId).provenance.parameters;
    const auto target = parameters.find("target");
    return target != parameters.end() && target->second == "all" ? imaging::NamingScope::None
                                                                 : imaging::NamingScope::AorticAndHepatic;
}

} // namespace

std::vector<std::string> segmentNames(const study::Study& study, const std::string& centerlinesId,
                                      const SkeletonGraph& centerlines)
{
    std::vector<std::string> names = imaging::nameVesselSegments(centerlines, scopeOf(study, centerlinesId));
    const auto& attributes = study.artifact(centerlinesId).attributes;
    for (std::size_t e = 0; e < names.size(); ++e)
        if (const auto given = attributes.find(attributeKey(e)); given != attributes.end() && !given->second.empty())
            names[e] = given->second;
    return names;
}

void renameSegment(study::Study& study, const std::string& centerlinesId, std::size_t index, const std::string& name)
{
    const study::Artifact& artifact = study.artifact(centerlinesId);
    if (artifact.kind != study::ArtifactKind::Skeleton)
        throw Error("not a centerlines artifact", {{"artifact", centerlinesId}});
    const std::size_t count = study.loadSkeleton(centerlinesId).edges.size();
    if (index >= count)
        throw Error(Pattern{"no such segment: the centerlines have segments 0 to %1", {std::to_string(count - 1)}},
                    {{"segment", std::to_string(index)}});
    if (name.find_first_not_of(" \t") == std::string::npos)
        throw Error("a segment's name cannot be empty");
    std::map<std::string, std::string> attributes = artifact.attributes;
    attributes[attributeKey(index)] = name;
    study.setArtifactAttributes(centerlinesId, attributes);
}

std::string segmentTitle(const std::string& name, int fromNode, int toNode)
{
    if (name != imaging::kUnnamedSegment)
        return storedTextForPeople(name); // an anatomical name in the reader's language; a user's as typed
    return withArguments(localized("vsim::app::SegmentNames", "unnamed (nodes %1-%2)"),
                         {std::to_string(fromNode), std::to_string(toNode)});
}

} // namespace vsim::app
