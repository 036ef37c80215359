// One writer per study (StudyLock: an open-file-description fcntl lock). Truths: the kernel's lock semantics —
// a second writer is refused while the first lives, and proceeds once the first is killed with SIGKILL; readers
// are never refused; a save never destroys what another program wrote into the bundle.
#include "TestOutput.h"
#include "vsim/core/Error.h"
#include "vsim/study/Study.h"
#include "vsim/study/StudyLock.h"

#include <QtTest>

#include <csignal>
#include <filesystem>
#include <fstream>
#include <sys/wait.h>
#include <unistd.h>

namespace fs = std::filesystem;
using vsim::study::Access;
using vsim::study::Study;
using vsim::study::StudyLock;

namespace {

fs::path freshBundle(const std::string& name)
{
    const fs::path bundle = fs::path(vsim::test::outputFolder("study-lock").toStdString()) / name;
    fs::remove_all(bundle);
    return bundle;
}

vsim::LabelVolume smallLabel()
{
    vsim::VolumeGeometry geometry;
    geometry.dims = {4, 4, 4};
    return vsim::LabelVolume(geometry);
}

} // namespace

class TestStudyLock : public QObject
{
    Q_OBJECT
private slots:
    void secondWriterIsRefusedNamingTheHolder()
    {
        const fs::path bundle = freshBundle("two-writers.vsim");
        Study first = Study::create(bundle, "two writers");
        first.addLabel(smallLabel(), "label", {});
        first.save();
        try
        {
            Study second = Study::open(bundle); // another open file description: refused even in one process
            QFAIL("a second writer must be refused");
        }
        catch (const vsim::Error& error)
        {
            QVERIFY2(error.message().find("being written by") != std::string::npos, error.message().c_str());
            QVERIFY(error.contextValue("holder").find("process " + std::to_string(getpid())) != std::string::npos);
        }
        const Study reader = Study::open(bundle, Access::ReadOnly); // readers still work
        QCOMPARE(reader.artifacts().size(), std::size_t(1));
        QCOMPARE(StudyLock::currentHolder(bundle).pid, long(getpid()));
    }

    void readOnlyStudyRefusesToSave()
    {
        const fs::path bundle = freshBundle("read-only.vsim");
        Study::create(bundle, "read only").save();
        Study reader = Study::open(bundle, Access::ReadOnly);
        QVERIFY(reader.isReadOnly());
        reader.addLabel(smallLabel(), "label", {});
        QVERIFY_THROWS_EXCEPTION(vsim::Error, reader.save());
        QCOMPARE(Study::open(bundle, Access::ReadOnly).artifacts().size(), std::size_t(0));
    }

    void holderKilledWithSigkillReleasesTheLock()
    {
        const fs::path bundle = freshBundle("stale.vsim");
        Study::create(bundle, "stale").save();
        int ready[2];
        QVERIFY(pipe(ready) == 0);
        const pid_t child = fork();
        QVERIFY(child >= 0);
        if (child == 0)
        {
            try
            {
                Study held = Study::open(bundle);
                (void)!write(ready[1], "1", 1);
                for (;;)
                    pause();
            }
            catch (...)
            {
                _exit(3);
            }
        }
        char byte = 0;
        QCOMPARE(read(ready[0], &byte, 1), ssize_t(1));
        QCOMPARE(StudyLock::currentHolder(bundle).pid, long(child));
        QVERIFY_THROWS_EXCEPTION(vsim::Error, Study::open(bundle, Access::Write, 0.2));
        kill(child, SIGKILL);
        int status = 0;
        waitpid(child, &status, 0);
        QVERIFY(WIFSIGNALED(status));
        // The lock file still names the dead holder; the kernel released its lock: the next writer proceeds.
        Study next = Study::open(bundle);
        next.addLabel(smallLabel(), "after the kill", {});
        next.save();
        QCOMPARE(StudyLock::currentHolder(bundle).pid, long(getpid()));
    }

    void waitingWriterProceedsWhenTheHolderFinishes()
    {
        const fs::path bundle = freshBundle("wait.vsim");
        Study::create(bundle, "wait").save();
        int ready[2];
        QVERIFY(pipe(ready) == 0);
        const pid_t child = fork();
        QVERIFY(child >= 0);
        if (child == 0)
        {
            Study held = Study::open(bundle);
            (void)!write(ready[1], "1", 1);
            usleep(300000);
            _exit(0); // the kernel releases the lock with the process
        }
        char byte = 0;
        QCOMPARE(read(ready[0], &byte, 1), ssize_t(1));
        QVERIFY_THROWS_EXCEPTION(vsim::Error, Study::open(bundle, Access::Write, 0.0));
        Study waited = Study::open(bundle, Access::Write, 5.0);
        QVERIFY(!waited.isReadOnly());
        int status = 0;
        waitpid(child, &status, 0);
    }

    void aConfirmedBreakMovesTheLockAsideAndTakesANewOne()
    {
        // What the GUI does after the user confirmed that a holder on another host is dead: the old lock file is
        // kept beside (for the record), a new one is locked. (Here the holder lives: breaking is the user's call.)
        const fs::path bundle = freshBundle("break.vsim");
        Study::create(bundle, "break").save();
        const Study held = Study::open(bundle);
        QVERIFY_THROWS_EXCEPTION(vsim::Error, Study::open(bundle));
        Study broken = Study::openBreakingLock(bundle);
        QVERIFY(!broken.isReadOnly());
        bool movedAside = false;
        for (const auto& entry : fs::directory_iterator(bundle))
            movedAside = movedAside || entry.path().filename().string().rfind("study.lock.broken-", 0) == 0;
        QVERIFY(movedAside);
        broken.addLabel(smallLabel(), "after the break", {});
        broken.save();
    }

    void saveKeepsFilesItDidNotWrite()
    {
        const fs::path bundle = freshBundle("stranger.vsim");
        Study study = Study::create(bundle, "stranger");
        const std::string id = study.addLabel(smallLabel(), "label", {});
        study.save();
        std::ofstream(bundle / "labels" / "notes.txt") << "a radiologist's notes";
        std::ofstream(bundle / "labels" / "label-99.nrrd.bak") << "a copy someone made";
        study.removeArtifact(id);
        study.save();
        QVERIFY(fs::exists(bundle / "labels" / "notes.txt"));
        QVERIFY(fs::exists(bundle / "labels" / "label-99.nrrd.bak"));
        QVERIFY(!fs::exists(bundle / "labels" / (id + ".nrrd"))); // its own removed artifact's file goes
    }

    void saveRefusesWhenStudyJsonChangedUnderIt()
    {
        const fs::path bundle = freshBundle("changed.vsim");
        Study study = Study::create(bundle, "changed");
        study.save();
        std::string text;
        {
            std::ifstream in(bundle / "study.json");
            text.assign(std::istreambuf_iterator<char>(in), {});
        }
        std::ofstream(bundle / "study.json", std::ios::trunc) << text << " "; // another program's edit
        study.addLabel(smallLabel(), "label", {});
        QVERIFY_THROWS_EXCEPTION(vsim::Error, study.save());
        QVERIFY(!fs::exists(bundle / "labels"));
    }

    void createRefusesAFolderOfSomeoneElse()
    {
        const fs::path bundle = freshBundle("someone.vsim");
        fs::create_directories(bundle);
        std::ofstream(bundle / "thesis.docx") << "years of work";
        QVERIFY_THROWS_EXCEPTION(vsim::Error, Study::create(bundle, "someone"));
        QVERIFY(fs::exists(bundle / "thesis.docx"));
        QVERIFY(!fs::exists(bundle / "study.json"));
        // Save As (File > Save As) into that folder is refused the same way; the study stays where it was.
        const fs::path mine = freshBundle("mine.vsim");
        Study study = Study::create(mine, "mine");
        study.save();
        QVERIFY_THROWS_EXCEPTION(vsim::Error, study.saveAs(bundle));
        QVERIFY(fs::exists(bundle / "thesis.docx"));
        QCOMPARE(study.bundlePath(), mine);
    }
};

QTEST_APPLESS_MAIN(TestStudyLock)
#include "tst_study_lock.moc"
