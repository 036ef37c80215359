#include "vsim/study/Study.h"

#include "ArtifactFiles.h"
#include "BundleFiles.h"
#include "Manifest.h"
#include "RunFiles.h"
#include "vsim/core/Error.h"
#include "vsim/core/OutputSafety.h"
#include "vsim/core/StoredText.h"
#include "vsim/core/Version.h"
#include "vsim/study/StudyLock.h"

#include <algorithm>
#include <optional>
#include <set>

namespace vsim::study {
namespace fs = std::filesystem;

namespace {

constexpr const char* kManifestFile = "study.json";

/// Checks an artifact's file against the manifest; returns why it is damaged, or an empty string.
std::string checkArtifactFile(const fs::path& bundle, const Artifact& artifact)
{
    const fs::path file = bundle / artifact.file;
    std::error_code error;
    if (!fs::exists(file, error))
        return storedText(Pattern{"file is missing: %1", {artifact.file}});
    if (fs::file_size(file, error) != artifact.bytes)
        return storedText(Pattern{"file size differs from the manifest: %1", {artifact.file}});
    if (fileChecksum(file) != artifact.checksum)
        return storedText(Pattern{"file checksum differs from the manifest (damaged): %1", {artifact.file}});
    if (artifact.kind == ArtifactKind::Run)
        return checkRunFrames(file);
    return {};
}

/// True for a file name that save() gives an artifact of `kind` ("label-12.nrrd"): the only files it may remove.
bool isArtifactFileName(ArtifactKind kind, const std::string& name)
{
    const std::string prefix = kindName(kind) + "-", suffix = fileExtension(kind);
    if (name.size() <= prefix.size() + suffix.size() || name.rfind(prefix, 0) != 0 ||
        name.compare(name.size() - suffix.size(), suffix.size(), suffix) != 0)
        return false;
    const std::string number = name.substr(prefix.size(), name.size() - prefix.size() - suffix.size());
    return std::all_of(number.begin(), number.end(), [](char c) { return c >= '0' && c <= '9'; });
}

/// Files of VascuSim's artifact names in the artifact folders that the manifest does not reference (leftovers of
/// an interrupted save, artifacts removed from the study). Anything else a person put there is never touched.
std::vector<fs::path> unreferencedFiles(const fs::path& bundle, const Manifest& manifest)
{
    std::set<fs::path> referenced;
    for (const Artifact& artifact : manifest.artifacts)
        referenced.insert(bundle / artifact.file);
    std::vector<fs::path> leftovers;
    std::error_code error;
    for (const auto& entry : fs::directory_iterator(bundle / folderName(ArtifactKind::Run), error))
        if (entry.is_directory() && isArtifactFileName(ArtifactKind::Run, entry.path().filename().string() + ".json") &&
            !referenced.count(entry.path() / "run.json"))
            for (const fs::path& file : runFolderFiles(entry.path()))
                leftovers.push_back(file);
    for (ArtifactKind kind : kArtifactKinds)
    {
        for (const auto& entry : fs::directory_iterator(bundle / folderName(kind), error))
            if (entry.is_regular_file() && !referenced.count(entry.path()) &&
                isArtifactFileName(kind, entry.path().filename().string()))
                leftovers.push_back(entry.path());
    }
    if (fs::exists(bundle / (std::string(kManifestFile) + ".tmp")))
        leftovers.push_back(bundle / (std::string(kManifestFile) + ".tmp"));
    return leftovers;
}

/// Removes the run folders (and their frames/ folders) that removing a run's files left empty.
void removeEmptyRunFolders(const fs::path& bundle)
{
    std::error_code error;
    for (const auto& entry : fs::directory_iterator(bundle / folderName(ArtifactKind::Run), error))
        if (entry.is_directory() && isArtifactFileName(ArtifactKind::Run, entry.path().filename().string() + ".json"))
        {
            std::error_code notEmpty; // remove() leaves a folder that still holds anything
            fs::remove(entry.path() / "frames", notEmpty);
            fs::remove(entry.path(), notEmpty);
        }
}

} // namespace

struct Study::State
{
    fs::path bundle;
    std::optional<StudyLock> lock; // held while the study is open for writing
    std::string manifestOnDisk;    // study.json as this study last read or wrote it ("" before the first save)
    Manifest manifest;
    std::map<std::string, ArtifactData> pending;                     // unsaved data by artifact id
    std::map<std::string, std::pair<Artifact, ArtifactData>> removed; // kept for undo
    std::vector<std::string> openWarnings;
    bool modified = false;

    Artifact& find(const std::string& id)
    {
        for (Artifact& artifact : manifest.artifacts)
            if (artifact.id == id)
                return artifact;
        throw Error(Pattern{"the study has no artifact '%1'", {id}}, {{"artifact", id}});
    }

    std::string add(ArtifactData data, const std::string& name, Provenance provenance, std::vector<std::string> warnings)
    {
        Artifact artifact;
        artifact.kind = kindOf(data);
        artifact.id = kindName(artifact.kind) + "-" + std::to_string(manifest.nextArtifactNumber++);
        artifact.name = name;
        provenance.time = utcTimestamp();
        provenance.softwareVersion = kVersion;
        artifact.provenance = std::move(provenance);
        artifact.warnings = std::move(warnings);
        pending.emplace(artifact.id, std::move(data));
        manifest.artifacts.push_back(artifact);
        modified = true;
        return artifact.id;
    }

    ArtifactData load(const std::string& id, ArtifactKind expected)
    {
        const Artifact& artifact = find(id);
        if (artifact.kind != expected)
            throw Error(Pattern{"artifact '%1' is a %2, not a %3", {id, kindName(artifact.kind), kindName(expected)}},
                        {{"artifact", id}});
        if (const auto found = pending.find(id); found != pending.end())
            return found->second;
        if (artifact.damaged)
            throw Error(Pattern{"artifact '%1' is damaged: %2", {artifact.name, artifact.damage}}, {{"artifact", id}});
        return readArtifactFile(artifact.kind, bundle / artifact.file);
    }
};

Study::Study(std::unique_ptr<State> state) : m_state(std::move(state)) {}
Study::Study(Study&&) noexcept = default;
Study& Study::operator=(Study&&) noexcept = default;
Study::~Study() = default;

Study Study::create(const fs::path& bundle, const std::string& name, double waitSeconds)
{
    if (fs::exists(bundle / kManifestFile))
        throw Error("the folder is a study already; open it instead of creating a new one", {{"folder", bundle.string()}});
    claimOutputFolder(bundle, "study");
    auto state = std::make_unique<State>();
    state->bundle = bundle;
    state->lock.emplace(StudyLock::acquire(bundle, waitSeconds));
    if (fs::exists(bundle / kManifestFile)) // another writer saved it while this one waited
        throw Error("the folder became a study while waiting for its lock; open it instead", {{"folder", bundle.string()}});
    state->manifest.name = name;
    state->modified = true;
    return Study(std::move(state));
}

Study Study::openBreakingLock(const fs::path& bundle)
{
    StudyLock lock = StudyLock::breakAndAcquire(bundle);
    Study study = open(bundle, Access::ReadOnly);
    study.m_state->lock.emplace(std::move(lock));
    return study;
}

Study Study::open(const fs::path& bundle, Access access, double waitSeconds)
{
    const fs::path manifestPath = bundle / kManifestFile;
    if (!fs::exists(manifestPath))
        throw Error("not a VascuSim study: study.json is missing", {{"folder", bundle.string()}});
    auto state = std::make_unique<State>();
    state->bundle = bundle;
    if (access == Access::Write) // the manifest is read under the lock: the next artifact number is this writer's
        state->lock.emplace(StudyLock::acquire(bundle, waitSeconds));
    state->manifestOnDisk = readTextFile(manifestPath);
    state->manifest = manifestFromText(state->manifestOnDisk);
    for (Artifact& artifact : state->manifest.artifacts)
    {
        artifact.damage = checkArtifactFile(bundle, artifact);
        artifact.damaged = !artifact.damage.empty();
        if (artifact.damaged)
            state->openWarnings.push_back(
                storedText(Pattern{"artifact '%1' (%2): %3", {artifact.name, artifact.id, artifact.damage}}));
    }
    for (const fs::path& leftover : unreferencedFiles(bundle, state->manifest))
        state->openWarnings.push_back(storedText(Pattern{"leftover of an interrupted save, removed at the next save: %1",
                                                         {fs::relative(leftover, bundle).string()}}));
    return Study(std::move(state));
}

const fs::path& Study::bundlePath() const { return m_state->bundle; }
const std::string& Study::name() const { return m_state->manifest.name; }
const std::map<std::string, std::string>& Study::metadata() const { return m_state->manifest.metadata; }
const std::vector<Artifact>& Study::artifacts() const { return m_state->manifest.artifacts; }
const std::vector<std::string>& Study::openWarnings() const { return m_state->openWarnings; }
bool Study::isModified() const { return m_state->modified; }
bool Study::isReadOnly() const { return !m_state->lock.has_value(); }
const Artifact& Study::artifact(const std::string& id) const { return m_state->find(id); }

void Study::setMetadata(const std::string& key, const std::string& value)
{
    m_state->manifest.metadata[key] = value;
    m_state->modified = true;
}

bool Study::hasArtifact(const std::string& id) const
{
    const auto& all = m_state->manifest.artifacts;
    return std::any_of(all.begin(), all.end(), [&](const Artifact& artifact) { return artifact.id == id; });
}

std::string Study::newestArtifact(ArtifactKind kind, const std::string& madeBy) const
{
    const auto& all = m_state->manifest.artifacts;
    for (auto it = all.rbegin(); it != all.rend(); ++it)
        if (it->kind == kind && !it->damaged && (madeBy.empty() || it->provenance.command == madeBy))
            return it->id;
    return {};
}

std::string Study::addImage(const CtVolume& image, const std::string& name, Provenance provenance,
                            std::vector<std::string> warnings)
{
    if (image.isEmpty())
        throw Error("cannot add an empty image to the study");
    return m_state->add(image, name, std::move(provenance), std::move(warnings));
}

std::string Study::addLabel(const LabelVolume& label, const std::string& name, Provenance provenance,
                            std::vector<std::string> warnings)
{
    if (label.isEmpty())
        throw Error("cannot add an empty label volume to the study");
    return m_state->add(label, name, std::move(provenance), std::move(warnings));
}

std::string Study::addSurface(const TriangleMesh& surface, const std::string& name, Provenance provenance,
                              std::vector<std::string> warnings)
{
    surface.validate();
    if (surface.triangles.empty())
        throw Error("cannot add an empty surface to the study");
    return m_state->add(surface, name, std::move(provenance), std::move(warnings));
}

std::string Study::addTetMesh(const TetMesh& mesh, const std::string& name, Provenance provenance,
                              std::vector<std::string> warnings)
{
    mesh.validate();
    if (mesh.tets.empty())
        throw Error("cannot add an empty tetrahedral mesh to the study");
    return m_state->add(mesh, name, std::move(provenance), std::move(warnings));
}

std::string Study::addSkeleton(const SkeletonGraph& skeleton, const std::string& name, Provenance provenance,
                               std::vector<std::string> warnings)
{
    skeleton.validate();
    return m_state->add(skeleton, name, std::move(provenance), std::move(warnings));
}

std::string Study::addMeasurement(const ViewMeasurement& measurement, const std::string& name, Provenance provenance)
{
    if (int(measurement.pointsMm.size()) != pointCount(measurement.kind))
        throw Error(Pattern{"a %1 takes %2 points",
                            {kindName(measurement.kind), std::to_string(pointCount(measurement.kind))}});
    return m_state->add(measurement, name, std::move(provenance), {});
}

std::string Study::addNetwork(const VesselNetwork& network, const std::string& name, Provenance provenance,
                              std::vector<std::string> warnings)
{
    network.validate();
    if (network.segments.empty())
        throw Error("cannot add an empty vessel network to the study");
    return m_state->add(network, name, std::move(provenance), std::move(warnings));
}

std::string Study::addRun(const SolverRun& run, const std::string& name, Provenance provenance,
                          std::vector<std::string> warnings)
{
    if (run.frames.empty() || run.frames.size() != run.keptFrameNumbers.size())
        throw Error("a run added to the study needs its frames");
    return m_state->add(run, name, std::move(provenance), std::move(warnings));
}

std::string Study::addReport(const std::string& pdf, const std::string& name, Provenance provenance,
                             std::vector<std::string> warnings)
{
    if (pdf.rfind("%PDF", 0) != 0)
        throw Error("a report added to the study must be a PDF");
    return m_state->add(Document{pdf}, name, std::move(provenance), std::move(warnings));
}

CtVolume Study::loadImage(const std::string& id) const
{
    return std::get<CtVolume>(m_state->load(id, ArtifactKind::Image));
}
LabelVolume Study::loadLabel(const std::string& id) const
{
    return std::get<LabelVolume>(m_state->load(id, ArtifactKind::Label));
}
TriangleMesh Study::loadSurface(const std::string& id) const
{
    return std::get<TriangleMesh>(m_state->load(id, ArtifactKind::Surface));
}
TetMesh Study::loadTetMesh(const std::string& id) const
{
    return std::get<TetMesh>(m_state->load(id, ArtifactKind::TetMesh));
}
SkeletonGraph Study::loadSkeleton(const std::string& id) const
{
    return std::get<SkeletonGraph>(m_state->load(id, ArtifactKind::Skeleton));
}
VesselNetwork Study::loadNetwork(const std::string& id) const
{
    return std::get<VesselNetwork>(m_state->load(id, ArtifactKind::Network));
}

ViewMeasurement Study::loadMeasurement(const std::string& id) const
{
    return std::get<ViewMeasurement>(m_state->load(id, ArtifactKind::Measurement));
}
std::string Study::loadReport(const std::string& id) const
{
    return std::get<Document>(m_state->load(id, ArtifactKind::Report)).bytes;
}

SolverRun Study::loadRun(const std::string& id, bool withFrames) const
{
    const Artifact& entry = m_state->find(id);
    if (entry.kind != ArtifactKind::Run || m_state->pending.count(id) || withFrames)
        return std::get<SolverRun>(m_state->load(id, ArtifactKind::Run));
    if (entry.damaged)
        throw Error(Pattern{"artifact '%1' is damaged: %2", {entry.name, entry.damage}}, {{"artifact", id}});
    return readRunFolder(m_state->bundle / entry.file, false);
}

RunFrame Study::loadRunFrame(const std::string& id, std::size_t index) const
{
    const Artifact& entry = m_state->find(id);
    if (entry.kind != ArtifactKind::Run)
        throw Error(Pattern{"artifact '%1' is a %2, not a run", {id, kindName(entry.kind)}}, {{"artifact", id}});
    if (const auto found = m_state->pending.find(id); found != m_state->pending.end())
    {
        const SolverRun& run = std::get<SolverRun>(found->second);
        if (index >= run.frames.size())
            throw Error(Pattern{"the run has no frame %1 (it kept %2)",
                                {std::to_string(index), std::to_string(run.frames.size())}});
        return run.frames[index];
    }
    if (entry.damaged)
        throw Error(Pattern{"artifact '%1' is damaged: %2", {entry.name, entry.damage}}, {{"artifact", id}});
    return readRunFrame(m_state->bundle / entry.file, index);
}

VolumeGeometry Study::volumeGeometry(const std::string& id) const
{
    const Artifact& entry = m_state->find(id);
    if (const auto found = m_state->pending.find(id); found != m_state->pending.end())
    {
        if (const auto* image = std::get_if<CtVolume>(&found->second))
            return image->geometry();
        if (const auto* label = std::get_if<LabelVolume>(&found->second))
            return label->geometry();
    }
    if (entry.kind != ArtifactKind::Image && entry.kind != ArtifactKind::Label)
        throw Error(Pattern{"artifact '%1' is not a volume", {id}}, {{"artifact", id}});
    if (entry.damaged)
        throw Error(Pattern{"artifact '%1' is damaged: %2", {entry.name, entry.damage}}, {{"artifact", id}});
    return readVolumeGeometry(m_state->bundle / entry.file);
}

void Study::renameArtifact(const std::string& id, const std::string& name)
{
    m_state->find(id).name = name;
    m_state->modified = true;
}

void Study::setArtifactAttributes(const std::string& id, std::map<std::string, std::string> attributes)
{
    m_state->find(id).attributes = std::move(attributes);
    m_state->modified = true;
}

void Study::removeArtifact(const std::string& id)
{
    const Artifact artifact = m_state->find(id);
    ArtifactData data = m_state->load(id, artifact.kind); // kept in memory: an undo must survive a save
    auto& all = m_state->manifest.artifacts;
    all.erase(std::remove_if(all.begin(), all.end(), [&](const Artifact& entry) { return entry.id == id; }), all.end());
    m_state->pending.erase(id);
    m_state->removed.insert_or_assign(id, std::make_pair(artifact, std::move(data)));
    m_state->modified = true;
}

void Study::restoreArtifact(const std::string& id)
{
    const auto found = m_state->removed.find(id);
    if (found == m_state->removed.end())
        throw Error(Pattern{"artifact '%1' was not removed; nothing to restore", {id}}, {{"artifact", id}});
    Artifact artifact = found->second.first;
    artifact.file.clear(); // written again at the next save
    m_state->pending.insert_or_assign(id, std::move(found->second.second));
    m_state->manifest.artifacts.push_back(std::move(artifact));
    m_state->removed.erase(found);
    m_state->modified = true;
}

void Study::save()
{
    State& state = *m_state;
    if (!state.lock)
        throw Error("the study is open read-only; save it under a new name, or reopen it for writing when "
                    "its writer has finished", {{"folder", state.bundle.string()}});
    const fs::path manifestPath = state.bundle / kManifestFile;
    std::error_code missing;
    const std::string onDisk = fs::exists(manifestPath, missing) ? readTextFile(manifestPath) : std::string();
    if (onDisk != state.manifestOnDisk)
        throw Error("study.json was changed by another program since this study was opened; nothing was written. "
                    "Save under a new name (Save As) to keep this version",
                    {{"folder", state.bundle.string()}});
    Manifest next = state.manifest;
    for (Artifact& artifact : next.artifacts)
    {
        const auto data = state.pending.find(artifact.id);
        if (data == state.pending.end())
            continue;
        const fs::path relative = artifactFilePath(artifact.kind, artifact.id);
        fs::create_directories(state.bundle / relative.parent_path());
        writeArtifactFile(data->second, state.bundle / relative);
        artifact.file = relative.string();
        artifact.bytes = fs::file_size(state.bundle / relative);
        artifact.checksum = fileChecksum(state.bundle / relative);
        artifact.damaged = false;
        artifact.damage.clear();
    }
    for (ArtifactKind kind : kArtifactKinds)
        if (fs::exists(state.bundle / folderName(kind)))
            syncDirectory(state.bundle / folderName(kind));
    for (const Artifact& artifact : next.artifacts)
        if (artifact.kind == ArtifactKind::Run && state.pending.count(artifact.id))
            syncDirectory(state.bundle / artifactFilePath(artifact.kind, artifact.id).parent_path());
    // The commit point: until this rename the bundle holds the previous study.
    const std::string manifestText = manifestToText(next);
    writeFileAtomically(manifestPath, manifestText);
    state.manifestOnDisk = manifestText;

    state.manifest = std::move(next);
    state.pending.clear();
    state.modified = false;
    state.openWarnings.clear();
    for (const fs::path& leftover : unreferencedFiles(state.bundle, state.manifest))
        fs::remove(leftover);
    removeEmptyRunFolders(state.bundle);
}

void Study::saveAs(const fs::path& bundle)
{
    std::error_code error;
    if (fs::exists(bundle, error) && !fs::is_empty(bundle, error))
        throw Error("the folder for the new study is not empty; choose a new folder", {{"folder", bundle.string()}});
    claimOutputFolder(bundle, "study");
    StudyLock lock = StudyLock::acquire(bundle);
    State& state = *m_state;
    for (const Artifact& artifact : state.manifest.artifacts)
    {
        if (state.pending.count(artifact.id) || artifact.file.empty() || !fs::exists(state.bundle / artifact.file))
            continue;
        const std::vector<fs::path> files = artifact.kind == ArtifactKind::Run
                                                ? runFolderFiles((state.bundle / artifact.file).parent_path())
                                                : std::vector<fs::path>{state.bundle / artifact.file};
        for (const fs::path& file : files)
        {
            const fs::path target = bundle / fs::relative(file, state.bundle);
            fs::create_directories(target.parent_path());
            fs::copy_file(file, target, fs::copy_options::overwrite_existing);
            syncFile(target);
        }
    }
    state.bundle = bundle;
    state.lock.emplace(std::move(lock)); // releases the old bundle's lock
    state.manifestOnDisk.clear();
    save();
}

} // namespace vsim::study
