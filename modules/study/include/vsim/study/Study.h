#pragma once

#include "vsim/core/ImageVolume.h"
#include "vsim/core/SkeletonGraph.h"
#include "vsim/core/SolverRun.h"
#include "vsim/core/TetMesh.h"
#include "vsim/core/TriangleMesh.h"
#include "vsim/core/UtcTime.h"
#include "vsim/core/VesselNetwork.h"
#include "vsim/core/ViewMeasurement.h"
#include "vsim/study/Artifact.h"

#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace vsim::study {

/// Schema version written into study.json; bump it with a migration in Manifest.cpp. Schema 2 adds the run kind
/// (runs/<id>/); a schema 1 study reads unchanged.
inline constexpr int kSchemaVersion = 2;

/// How a study is opened: for writing (its lock held until the Study is destroyed) or for reading only.
enum class Access
{
    Write,
    ReadOnly
};

/// The document: one patient's study as a `<name>.vsim/` bundle (study.json + images/, labels/, surfaces/,
/// meshes/, skeletons/, networks/, reports/, runs/). Artifacts added since the last save are held in memory until save(), which is atomic:
/// new files are written and synced first, the manifest is replaced by rename last, and files no longer
/// referenced are removed after that (only files of VascuSim's own artifact names). A kill at any moment leaves
/// the old or the new study. One writer at a time: a study opened for writing holds the bundle's StudyLock.
class Study
{
public:
    /// A new study that will be written to `bundle` (a folder, conventionally ending in .vsim): the folder is created
    /// and locked now; its files are written by save(). Throws vsim::Error when the folder is a study already, holds
    /// files VascuSim did not write, or is locked by another writer after `waitSeconds`.
    static Study create(const std::filesystem::path& bundle, const std::string& name, double waitSeconds = 0.0);
    /// Opens a bundle. Throws vsim::Error when study.json is missing, unreadable, or of a newer schema, and (for
    /// Access::Write) when another process still holds the study's lock after `waitSeconds` (the message names it).
    /// Missing or damaged artifact files do not throw: those artifacts are flagged (Artifact::damaged) and
    /// listed in openWarnings().
    static Study open(const std::filesystem::path& bundle, Access access = Access::Write, double waitSeconds = 0.0);
    /// Opens for writing after moving a stale lock aside (a holder on another host that the user confirmed dead).
    static Study openBreakingLock(const std::filesystem::path& bundle);

    Study(Study&&) noexcept;
    Study& operator=(Study&&) noexcept;
    ~Study();

    const std::filesystem::path& bundlePath() const;
    const std::string& name() const;
    /// Patient and study metadata (patient_name, patient_id, study_description, study_date, ...).
    const std::map<std::string, std::string>& metadata() const;
    void setMetadata(const std::string& key, const std::string& value);

    const std::vector<Artifact>& artifacts() const;
    /// Returns the artifact; throws vsim::Error for an unknown id.
    const Artifact& artifact(const std::string& id) const;
    /// The newest undamaged artifact of `kind` (made by the step `madeBy`, e.g. "centerline", when given); "" if none.
    std::string newestArtifact(ArtifactKind kind, const std::string& madeBy = {}) const;
    bool hasArtifact(const std::string& id) const;
    /// Problems found by open(): missing or damaged files, leftovers of an interrupted save.
    const std::vector<std::string>& openWarnings() const;
    /// True when there are changes that save() would write.
    bool isModified() const;
    /// True when the study was opened with Access::ReadOnly: save() refuses.
    bool isReadOnly() const;

    /// Adds an artifact held in memory until save(); returns its new id. Throws vsim::Error for empty data.
    std::string addImage(const CtVolume& image, const std::string& name, Provenance provenance,
                         std::vector<std::string> warnings = {});
    std::string addLabel(const LabelVolume& label, const std::string& name, Provenance provenance,
                         std::vector<std::string> warnings = {});
    std::string addSurface(const TriangleMesh& surface, const std::string& name, Provenance provenance,
                           std::vector<std::string> warnings = {});
    std::string addTetMesh(const TetMesh& mesh, const std::string& name, Provenance provenance,
                           std::vector<std::string> warnings = {});
    std::string addSkeleton(const SkeletonGraph& skeleton, const std::string& name, Provenance provenance,
                            std::vector<std::string> warnings = {});
    std::string addNetwork(const VesselNetwork& network, const std::string& name, Provenance provenance,
                           std::vector<std::string> warnings = {});
    /// A report's PDF as written (reports/<id>.pdf); throws vsim::Error when the bytes are not a PDF.
    std::string addReport(const std::string& pdf, const std::string& name, Provenance provenance,
                          std::vector<std::string> warnings = {});

    /// A ruler, angle or ROI drawn on a view (measurements/<id>.json). Throws vsim::Error for a wrong number of points.
    std::string addMeasurement(const ViewMeasurement& measurement, const std::string& name, Provenance provenance);
    /// A simulation run (runs/<id>/: run.json, frames, series.pvd) with its frames in memory until save(). Throws
    /// vsim::Error for a run without its frames (one whose frames were only streamed).
    std::string addRun(const SolverRun& run, const std::string& name, Provenance provenance,
                       std::vector<std::string> warnings = {});

    /// Loads an artifact's data (from memory if unsaved, else from its file). Throws vsim::Error for an unknown
    /// id, a kind mismatch, or a damaged artifact.
    CtVolume loadImage(const std::string& id) const;
    LabelVolume loadLabel(const std::string& id) const;
    TriangleMesh loadSurface(const std::string& id) const;
    TetMesh loadTetMesh(const std::string& id) const;
    SkeletonGraph loadSkeleton(const std::string& id) const;
    VesselNetwork loadNetwork(const std::string& id) const;
    ViewMeasurement loadMeasurement(const std::string& id) const;
    /// The PDF bytes of a report artifact.
    std::string loadReport(const std::string& id) const;
    /// A run: its record (axis, status, metrics, provenance, which frames were kept) and, with `withFrames`, every
    /// kept frame.
    SolverRun loadRun(const std::string& id, bool withFrames = true) const;
    /// Kept frame `index` of a run (0 = the first), read alone (the time player). Throws vsim::Error out of range.
    RunFrame loadRunFrame(const std::string& id, std::size_t index) const;

    /// The geometry of an image or label artifact, read from the file header only (no voxels).
    /// Throws vsim::Error for another kind or a damaged artifact.
    VolumeGeometry volumeGeometry(const std::string& id) const;

    /// Renames an artifact (the name shown to people); throws vsim::Error for an unknown id.
    void renameArtifact(const std::string& id, const std::string& name);
    /// Replaces an artifact's source attributes (Artifact::attributes); throws vsim::Error for an unknown id.
    void setArtifactAttributes(const std::string& id, std::map<std::string, std::string> attributes);
    /// Removes an artifact from the study; its data is returned so that an undo can put it back.
    /// Throws vsim::Error for an unknown id.
    void removeArtifact(const std::string& id);
    /// Puts back an artifact removed by removeArtifact() (same id, data kept in memory until the next save).
    void restoreArtifact(const std::string& id);

    /// Writes the study atomically to its bundle. Throws vsim::Error on an I/O failure (the bundle on disk then
    /// still holds the previous version), for a read-only study, and when study.json was changed by another program
    /// since this study read or wrote it (nothing is written then).
    void save();
    /// Writes the study to a new bundle (a new or empty folder, locked; saved artifact files copied) and makes it
    /// this study's bundle, releasing the old one's lock. Throws vsim::Error for a folder that is not new or empty.
    void saveAs(const std::filesystem::path& bundle);

private:
    struct State;
    explicit Study(std::unique_ptr<State> state);
    std::unique_ptr<State> m_state;
};

/// The current time as ISO 8601 UTC (vsim/core/UtcTime.h).
using vsim::utcTimestamp;

} // namespace vsim::study
