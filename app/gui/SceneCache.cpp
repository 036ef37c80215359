#include "SceneCache.h"

#include "vsim/app/NetworkPipeline.h"
#include "vsim/mesh/VesselSurface.h"

namespace vsim::gui {
namespace {

bool isWallRun(const study::Artifact& a)
{
    return a.kind == study::ArtifactKind::TetMesh && a.provenance.command == "simulate fem";
}

bool isDrugRun(const study::Artifact& a)
{
    return a.kind == study::ArtifactKind::Network && a.provenance.command == "simulate network";
}

/// What the dock shows of a recorded drug run's choices (the run's source as it recorded them).
DrugDeliveryRequest recordedRequest(const study::Artifact& run)
{
    auto text = [&](const char* key) {
        const auto found = run.provenance.parameters.find(key);
        return found == run.provenance.parameters.end() ? QString() : QString::fromStdString(found->second);
    };
    const QString tip = text("tip");
    return {tip == "root" ? QString() : tip,
            text("tumour_mm"),
            text("control_points"),
            text("liver_label").section(':', 0, 0),
            text("tumour_label").section(':', 0, 0),
            text("inlet"),
            text("feeders_added"),
            text("feeders_removed")};
}

} // namespace

TriangleMesh displaySurface(const LabelVolume& label, const Progress& progress)
{
    ParameterSet parameters(mesh::surfaceParameters());
    parameters.set("target_vertices", 20000); // enough for display
    return mesh::extractVesselSurface(label, 1, parameters, progress).surface;
}

bool isShowable(const study::Artifact& a)
{
    return a.kind == study::ArtifactKind::Image || a.kind == study::ArtifactKind::Label ||
           a.kind == study::ArtifactKind::Skeleton || a.kind == study::ArtifactKind::Measurement || isWallRun(a) ||
           isDrugRun(a);
}

SceneContent sceneContent(const study::Study& study, const std::set<std::string>& hidden)
{
    SceneContent content;
    for (const study::Artifact& a : study.artifacts()) // oldest first: later ones take the roles
    {
        if (a.damaged)
            continue;
        if (a.kind == study::ArtifactKind::Skeleton && a.provenance.command == "centerline")
            content.measuredCenterlines = a.id;
        if (hidden.count(a.id) || !isShowable(a))
            continue;
        if (a.kind == study::ArtifactKind::Image)
            content.image = a.id;
        else if (a.kind == study::ArtifactKind::Label)
            content.label = a.id, content.main = SceneContent::Main::Vessels;
        else if (a.kind == study::ArtifactKind::Skeleton)
        {
            (a.provenance.command == "centerline" ? content.centerlines : content.skeleton) = a.id;
            content.main = SceneContent::Main::Vessels;
        }
        else if (isWallRun(a))
            content.wallRun = a.id, content.main = SceneContent::Main::WallRun;
        else if (isDrugRun(a))
            content.networkRun = a.id, content.main = SceneContent::Main::NetworkRun;
    }
    if (!content.measuredCenterlines.empty() && app::labelOfCenterlines(study, content.measuredCenterlines).empty())
        content.measuredCenterlines.clear();
    return content;
}

bool SceneCache::holds(const SceneContent& c) const
{
    auto has = [](const auto& map, const std::string& id) { return id.empty() || map.count(id); };
    return has(labels, c.label) && has(lumenSurfaces, c.label) && has(skeletons, c.skeleton) &&
           has(skeletons, c.centerlines) && has(wallFrames, c.wallRun) && has(networkRuns, c.networkRun) &&
           has(measurements, c.measuredCenterlines);
}

SceneCache fillSceneCache(const study::Study& study, const SceneContent& c, const SceneCache& cache,
                          const Progress& progress)
{
    SceneCache more;
    if (!c.label.empty() && !cache.lumenSurfaces.count(c.label))
    {
        progress.report(0.0, "vessel surface");
        const LabelVolume label = cache.labels.count(c.label) ? cache.labels.at(c.label) : study.loadLabel(c.label);
        more.labels[c.label] = label;
        more.lumenSurfaces[c.label] = displaySurface(label, progress.subRange(0.0, 0.4));
    }
    for (const std::string& id : {c.skeleton, c.centerlines})
        if (!id.empty() && !cache.skeletons.count(id))
            more.skeletons[id] = study.loadSkeleton(id);
    if (!c.measuredCenterlines.empty() && !cache.measurements.count(c.measuredCenterlines))
    {
        progress.report(0.4, "measurements");
        const std::string labelId = app::labelOfCenterlines(study, c.measuredCenterlines);
        more.measurements[c.measuredCenterlines] =
            imaging::measureVessels(study.loadLabel(labelId), study.loadSkeleton(c.measuredCenterlines),
                                    ParameterSet(imaging::measurementParameters()), progress.subRange(0.4, 0.6));
    }
    if (!c.wallRun.empty() && !cache.wallFrames.count(c.wallRun))
        more.wallFrames[c.wallRun] = study.loadTetMesh(c.wallRun);
    if (!c.networkRun.empty() && !cache.networkRuns.count(c.networkRun))
    {
        progress.report(0.6, "drug run");
        std::vector<std::string> warnings;
        const study::Artifact& recorded = study.artifact(c.networkRun);
        const DrugDeliveryRequest request = recordedRequest(recorded);
        const sim::network::NetworkRunSetup setup =
            app::recordedNetworkSetup(study, recorded, warnings, progress.subRange(0.6, 0.8));
        auto run = std::make_shared<sim::network::NetworkRunResult>(sim::network::runNetwork(setup, progress.subRange(0.8, 1.0)));
        run->warnings.insert(run->warnings.begin(), warnings.begin(), warnings.end()); // as the first run had them
        more.networkRuns[c.networkRun] = std::move(run);
        more.networkRequests[c.networkRun] = request;
    }
    progress.report(1.0, "views ready");
    return more;
}

void mergeSceneCache(SceneCache& cache, SceneCache more)
{
    cache.labels.merge(more.labels);
    cache.lumenSurfaces.merge(more.lumenSurfaces);
    cache.skeletons.merge(more.skeletons);
    cache.wallFrames.merge(more.wallFrames);
    cache.networkRuns.merge(more.networkRuns);
    cache.networkRequests.merge(more.networkRequests);
    cache.measurements.merge(more.measurements);
}

} // namespace vsim::gui
