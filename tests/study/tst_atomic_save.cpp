// Atomic save: a child process saves the study over and over and is killed (SIGKILL) at a random moment,
// 50 times. After each kill the bundle must open with no damaged artifact and hold either the previous or the
// new version, checked voxel by voxel against the version number recorded in the same manifest.
#include "StudyFixtures.h"
#include "TestOutput.h"
#include "vsim/study/Study.h"

#include <QtTest>

#include <chrono>
#include <csignal>
#include <filesystem>
#include <random>
#include <sys/wait.h>
#include <unistd.h>

namespace fs = std::filesystem;
using vsim::study::Study;

namespace {

constexpr int kVolumeSize = 48; // ~0.2 MB of int16 per save, plus the label below

/// Replaces the study's image with version `version` and saves.
void saveVersion(Study& study, int version)
{
    for (const auto& artifact : std::vector(study.artifacts()))
        study.removeArtifact(artifact.id);
    study.addImage(vsim::test::patternedVolume(kVolumeSize, version), "CT v" + std::to_string(version), {});
    vsim::LabelVolume label(vsim::test::patternedVolume(kVolumeSize, version).geometry());
    label.data()[0] = static_cast<std::uint8_t>(version % 251);
    study.addLabel(label, "label v" + std::to_string(version), {});
    study.setMetadata("version", std::to_string(version));
    study.save();
}

/// Child process: saves versions first, first+1, ... until killed.
[[noreturn]] void saveForever(const fs::path& bundle, int first)
{
    try
    {
        Study study = Study::open(bundle);
        for (int version = first;; ++version)
            saveVersion(study, version);
    }
    catch (...)
    {
        _exit(3);
    }
}

} // namespace

class TestAtomicSave : public QObject
{
    Q_OBJECT
private slots:
    void killedSavesAlwaysLeaveAStudyThatOpens()
    {
        const fs::path bundle = fs::path(vsim::test::outputFolder("study").toStdString()) / "atomic.vsim";
        fs::remove_all(bundle);
        long saveMicroseconds = 0;
        { // released before the children write: one writer at a time
            Study study = Study::create(bundle, "atomic");
            const auto start = std::chrono::steady_clock::now();
            saveVersion(study, 1);
            saveMicroseconds =
                std::chrono::duration_cast<std::chrono::microseconds>(std::chrono::steady_clock::now() - start).count();
        }

        std::mt19937 random(20261122); // seeded: the same kill moments every run
        std::uniform_int_distribution<long> delay(0, 3 * std::max<long>(saveMicroseconds, 1000));
        int version = 2;
        int advanced = 0;
        for (int trial = 0; trial < 50; ++trial)
        {
            const pid_t child = fork();
            QVERIFY(child >= 0);
            if (child == 0)
                saveForever(bundle, version);
            usleep(static_cast<useconds_t>(delay(random)));
            kill(child, SIGKILL);
            int status = 0;
            waitpid(child, &status, 0);
            QVERIFY2(WIFSIGNALED(status), "the saving child must have been killed, not have failed");

            const Study reopened = Study::open(bundle, vsim::study::Access::ReadOnly);
            for (const auto& artifact : reopened.artifacts())
                QVERIFY2(!artifact.damaged, artifact.damage.c_str());
            QCOMPARE(reopened.artifacts().size(), std::size_t(2));
            const int saved = std::stoi(reopened.metadata().at("version"));
            QVERIFY(saved >= version - 1);
            const vsim::CtVolume image = reopened.loadImage(reopened.artifacts()[0].id);
            QVERIFY2(vsim::test::samePattern(image, saved), "the image must be the version the manifest names");
            QCOMPARE(int(reopened.loadLabel(reopened.artifacts()[1].id).data()[0]), saved % 251);
            advanced += saved >= version;
            version = saved + 1;
        }
        qInfo("one save takes %ld us; %d of 50 kills came after at least one completed save", long(saveMicroseconds),
              advanced);
    }
};

QTEST_APPLESS_MAIN(TestAtomicSave)
#include "tst_atomic_save.moc"
