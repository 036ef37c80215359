#include "vsim/study/Artifact.h"

#include "vsim/core/Error.h"

namespace vsim::study {

std::string kindName(ArtifactKind kind)
{
    switch (kind)
    {
    case ArtifactKind::Image: return "image";
    case ArtifactKind::Label: return "label";
    case ArtifactKind::Surface: return "surface";
    case ArtifactKind::TetMesh: return "tetmesh";
    case ArtifactKind::Skeleton: return "skeleton";
    case ArtifactKind::Network: return "network";
    case ArtifactKind::Report: return "report";
    case ArtifactKind::Run: return "run";
    case ArtifactKind::Measurement: return "measurement";
    }
    return "unknown";
}

ArtifactKind kindFromName(const std::string& name)
{
    for (ArtifactKind kind : kArtifactKinds)
        if (kindName(kind) == name)
            return kind;
    throw Error(Pattern{"unknown artifact kind '%1'", {name}}, {{"kind", name}});
}

} // namespace vsim::study
