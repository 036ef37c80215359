#pragma once

// What the views draw for a study, worked out from its artifacts: which artifact fills each role (the newest label
// in the MPRs, the 3D content, the measured centerlines) given the artifacts the user hid, and the data each role
// needs, loaded or computed once per artifact and kept here. Redrawing after an undo, a visibility change or a
// reopened study then costs the GUI thread no file reading and no computing; what is missing is filled in the
// background (fillSceneCache).

#include "DrugDeliveryPanel.h"
#include "vsim/core/ImageVolume.h"
#include "vsim/core/Progress.h"
#include "vsim/core/SkeletonGraph.h"
#include "vsim/core/TetMesh.h"
#include "vsim/core/TriangleMesh.h"
#include "vsim/imaging/VesselMeasurements.h"
#include "vsim/sim/network/NetworkRun.h"
#include "vsim/study/Study.h"

#include <map>
#include <memory>
#include <set>
#include <string>

namespace vsim::gui {

/// The artifacts shown, by role ("" where none).
struct SceneContent
{
    enum class Main
    {
        Nothing,  ///< the volume rendering alone
        Vessels,  ///< the lumen surface, with the skeleton and centerlines inside it when shown
        WallRun,  ///< a wall run's last frame coloured by von Mises stress
        NetworkRun ///< a drug run's tree coloured by drug flow, with its dock
    };
    std::string image, label, skeleton, centerlines, wallRun, networkRun, measuredCenterlines;
    Main main = Main::Nothing;
};

/// The roles filled from the study's artifacts: for each, the newest undamaged artifact not in `hidden`; the 3D
/// content is the newest shown among the wall runs, drug runs, skeletons / centerlines and labels.
SceneContent sceneContent(const study::Study& study, const std::set<std::string>& hidden);

/// The lumen surface of label value 1 as the 3D view draws it (about 20,000 vertices).
TriangleMesh displaySurface(const LabelVolume& label, const Progress& progress = {});

/// True for the artifacts that have a picture and can be shown or hidden (images, labels, skeletons, wall runs,
/// drug runs).
bool isShowable(const study::Artifact& artifact);

struct SceneCache
{
    std::map<std::string, LabelVolume> labels;
    std::map<std::string, TriangleMesh> lumenSurfaces; ///< by label id: the display surface (20k vertices)
    std::map<std::string, SkeletonGraph> skeletons;    ///< skeletons and centerlines
    std::map<std::string, TetMesh> wallFrames;         ///< wall runs' last frames
    std::map<std::string, std::shared_ptr<const sim::network::NetworkRunResult>> networkRuns;
    std::map<std::string, DrugDeliveryRequest> networkRequests; ///< the dock's inputs of each drug run
    std::map<std::string, imaging::VesselMeasurements> measurements; ///< by centerlines id

    /// True when everything `content` shows is here. (Entries of artifacts an undo removed stay: ids are never
    /// reused, and a redo shows them again at once.)
    bool holds(const SceneContent& content) const;
};

/// Loads and computes what `content` needs and `cache` lacks, from the study (read only; run it in the background):
/// labels and their display surfaces, skeletons, wall frames, the measurements of the centerlines, and drug runs
/// run again from their recorded inputs (the same network from the same centerlines, tip, tumour and parameters).
/// Returns the new entries in a cache of their own, for the GUI thread to merge.
SceneCache fillSceneCache(const study::Study& study, const SceneContent& content, const SceneCache& cache,
                          const Progress& progress);

/// Puts `more` into `cache` (entries already there stay).
void mergeSceneCache(SceneCache& cache, SceneCache more);

} // namespace vsim::gui
