// Single-file volume import: NIfTI, NRRD and MetaImage written by ITK with a known LPS geometry come back with
// that geometry (1e-4 mm) and the same HU; float data is rounded with a warning; bad files give clear errors.
#include "StudyFixtures.h"
#include "TestOutput.h"
#include "vsim/core/Error.h"
#include "vsim/interop/ItkImage.h"
#include "vsim/study/Study.h"
#include "vsim/study/VolumeFileImport.h"

#include <QtTest>
#include <itkImageFileWriter.h>
#include <itkMetaImageIO.h>
#include <itkNiftiImageIO.h>
#include <itkNrrdImageIO.h>

#include <filesystem>
#include <fstream>

namespace fs = std::filesystem;

namespace {

template <typename T>
void writeWithItk(const vsim::ImageVolume<T>& volume, const fs::path& file, itk::ImageIOBase* io)
{
    auto writer = itk::ImageFileWriter<vsim::interop::ItkImage3<T>>::New();
    writer->SetImageIO(io);
    writer->SetInput(vsim::interop::toItk(volume));
    writer->SetFileName(file.string());
    writer->Update();
}

fs::path folder()
{
    return fs::path(vsim::test::outputFolder("volume-import").toStdString());
}

} // namespace

class TestVolumeImport : public QObject
{
    Q_OBJECT
private slots:
    void everyFormatKeepsGeometryAndHounsfieldUnits_data()
    {
        QTest::addColumn<QString>("fileName");
        QTest::newRow("NIfTI gz") << "ct.nii.gz";
        QTest::newRow("NIfTI") << "ct.nii";
        QTest::newRow("NRRD") << "ct.nrrd";
        QTest::newRow("MetaImage") << "ct.mha";
    }

    void everyFormatKeepsGeometryAndHounsfieldUnits()
    {
        QFETCH(QString, fileName);
        const vsim::CtVolume truth = vsim::test::patternedVolume(9, 7);
        const fs::path file = folder() / fileName.toStdString();
        itk::ImageIOBase::Pointer io;
        if (fileName.contains(".nii"))
            io = itk::NiftiImageIO::New();
        else if (fileName.endsWith(".nrrd"))
            io = itk::NrrdImageIO::New();
        else
            io = itk::MetaImageIO::New();
        writeWithItk(truth, file, io);

        const vsim::study::ImportedVolume imported = vsim::study::readVolumeFile(file);
        QVERIFY(imported.warnings.empty());
        // NIfTI stores RAS with float32 sform: 1e-4 mm covers its single precision.
        QVERIFY2(imported.image.geometry().isClose(truth.geometry(), 1e-4), qPrintable(fileName));
        QVERIFY(vsim::test::samePattern(imported.image, 7));
    }

    void floatVolumesAreRoundedWithAWarning()
    {
        vsim::RealVolume real(vsim::test::patternedVolume(4, 1).geometry());
        for (std::size_t v = 0; v < real.size(); ++v)
            real.data()[v] = 40.4f;
        real.data()[0] = 1e6f; // outside int16
        const fs::path file = folder() / "real.nrrd";
        writeWithItk(real, file, itk::NrrdImageIO::New());
        const vsim::study::ImportedVolume imported = vsim::study::readVolumeFile(file);
        QCOMPARE(imported.image.data()[1], std::int16_t(40));
        QCOMPARE(imported.image.data()[0], std::int16_t(32767));
        QCOMPARE(imported.warnings.size(), std::size_t(2));
        QVERIFY(QString::fromStdString(imported.warnings[0]).startsWith(QString::number(real.size() - 1)));
    }

    void importAddsAnImageWithProvenance()
    {
        const fs::path file = folder() / "for-study.nrrd";
        writeWithItk(vsim::test::patternedVolume(5, 2), file, itk::NrrdImageIO::New());
        vsim::study::Study study = vsim::study::Study::create(folder() / "imported.vsim", "import");
        const std::string id = vsim::study::importVolumeFile(study, file);
        QCOMPARE(study.artifact(id).provenance.command, std::string("import volume"));
        QCOMPARE(study.artifact(id).provenance.inputs, std::vector<std::string>{"for-study.nrrd"});
        QVERIFY(vsim::test::samePattern(study.loadImage(id), 2));
    }

    void badFilesGiveClearErrors()
    {
        QVERIFY_THROWS_EXCEPTION(vsim::Error, vsim::study::readVolumeFile(folder() / "missing.nii"));
        const fs::path junk = folder() / "junk.nrrd";
        std::ofstream(junk) << "this is not an image";
        QVERIFY_THROWS_EXCEPTION(vsim::Error, vsim::study::readVolumeFile(junk));
        const fs::path truncated = folder() / "truncated.mha";
        writeWithItk(vsim::test::patternedVolume(9, 7), truncated, itk::MetaImageIO::New());
        fs::resize_file(truncated, fs::file_size(truncated) / 2);
        QVERIFY_THROWS_EXCEPTION(vsim::Error, vsim::study::readVolumeFile(truncated));
    }
};

QTEST_APPLESS_MAIN(TestVolumeImport)
#include "tst_volume_import.moc"
