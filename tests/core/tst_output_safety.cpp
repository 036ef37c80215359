// Where VascuSim may write (OutputSafety.h). Truth: the files a stranger put in place, which must survive.
#include "TestOutput.h"
#include "vsim/core/Error.h"
#include "vsim/core/OutputSafety.h"

#include <QtTest>

#include <filesystem>
#include <fstream>

namespace fs = std::filesystem;

namespace {

fs::path fresh(const std::string& name)
{
    const fs::path folder = fs::path(vsim::test::outputFolder("output-safety").toStdString()) / name;
    fs::remove_all(folder);
    return folder;
}

} // namespace

class TestOutputSafety : public QObject
{
    Q_OBJECT
private slots:
    void newAndEmptyFoldersAreClaimedAndMarked()
    {
        const fs::path created = fresh("new/deeper");
        vsim::claimOutputFolder(created, "run");
        QVERIFY(vsim::isOwnedFolder(created, "run"));
        const fs::path empty = fresh("empty");
        fs::create_directories(empty);
        vsim::claimOutputFolder(empty, "run");
        QVERIFY(vsim::isOwnedFolder(empty, "run"));
        vsim::claimOutputFolder(empty, "run"); // its own folder again: accepted
        QVERIFY(!vsim::isOwnedFolder(empty, "phantom"));
        QVERIFY_THROWS_EXCEPTION(vsim::Error, vsim::claimOutputFolder(empty, "phantom")); // another purpose
    }

    void aStrangersFolderIsRefusedAndKept()
    {
        const fs::path folder = fresh("stranger");
        fs::create_directories(folder);
        std::ofstream(folder / "notes.txt") << "mine";
        try
        {
            vsim::claimOutputFolder(folder, "run");
            QFAIL("a folder holding a stranger's file must be refused");
        }
        catch (const vsim::Error& error)
        {
            QCOMPARE(error.contextValue("folder"), folder.string());
        }
        QVERIFY(fs::exists(folder / "notes.txt"));
        QVERIFY(!fs::exists(folder / vsim::kOwnedFolderMarker));
        const fs::path file = folder / "notes.txt";
        QVERIFY_THROWS_EXCEPTION(vsim::Error, vsim::claimOutputFolder(file, "run")); // a file is no folder
    }

    // The check before a run refuses what the claim would and writes nothing: a run that fails leaves no folder.
    void checkingWritesNothing()
    {
        const fs::path missing = fresh("checked/deeper");
        vsim::checkOutputFolder(missing, "run");
        QVERIFY(!fs::exists(missing) && !fs::exists(missing.parent_path()));
        const fs::path empty = fresh("checked-empty");
        fs::create_directories(empty);
        vsim::checkOutputFolder(empty, "run");
        QVERIFY(fs::is_empty(empty));
        const fs::path stranger = fresh("checked-stranger");
        fs::create_directories(stranger);
        std::ofstream(stranger / "notes.txt") << "mine";
        QVERIFY_THROWS_EXCEPTION(vsim::Error, vsim::checkOutputFolder(stranger, "run"));
        QVERIFY_THROWS_EXCEPTION(vsim::Error, vsim::checkOutputFolder(stranger / "notes.txt", "run"));
        QVERIFY_THROWS_EXCEPTION(vsim::Error, vsim::checkOutputFolder(stranger / "notes.txt" / "below", "run"));
        QVERIFY(fs::exists(stranger / "notes.txt") && !fs::exists(stranger / vsim::kOwnedFolderMarker));
    }

    void existingFilesNeedOverwriteAndFoldersAreNeverFiles()
    {
        const fs::path folder = fresh("files");
        fs::create_directories(folder / "sub");
        std::ofstream(folder / "report.pdf") << "old";
        vsim::checkOutputFile(folder / "new.pdf", false);
        QVERIFY_THROWS_EXCEPTION(vsim::Error, vsim::checkOutputFile(folder / "report.pdf", false));
        vsim::checkOutputFile(folder / "report.pdf", true);
        QVERIFY_THROWS_EXCEPTION(vsim::Error, vsim::checkOutputFile(folder / "sub", true));
    }

    void removeWrittenFilesRemovesOnlyThose()
    {
        const fs::path root = fresh("written");
        fs::create_directories(root / "dicom");
        std::ofstream(root / "dicom" / "IM0001") << "ours";
        std::ofstream(root / "dicom" / "IM0002") << "ours";
        std::ofstream(root / "dicom" / "readme.txt") << "theirs";
        QCOMPARE(vsim::removeWrittenFiles({root / "dicom" / "IM0001", root / "dicom" / "IM0002"}, root / "dicom"),
                 std::size_t(2));
        QVERIFY(fs::exists(root / "dicom" / "readme.txt"));
        fs::remove(root / "dicom" / "readme.txt");
        std::ofstream(root / "dicom" / "IM0003") << "ours";
        vsim::removeWrittenFiles({root / "dicom" / "IM0003"}, root / "dicom");
        QVERIFY(!fs::exists(root / "dicom")); // left empty: removed
        QVERIFY(fs::exists(root));            // above the root: never
    }
};

QTEST_APPLESS_MAIN(TestOutputSafety)
#include "tst_output_safety.moc"
