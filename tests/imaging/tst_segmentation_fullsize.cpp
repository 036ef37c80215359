// Full size (label bench): the default 512 x 512 x 400 aaa phantom (20 HU noise) segmented with default
// parameters and the automatic seed. Prints time, peak memory of the process so far and Dice as JSON.

#include "vsim/dicom/PhantomRender.h"
#include "vsim/imaging/VesselSegmentation.h"

#include <sys/resource.h>

#include <QElapsedTimer>
#include <QtTest>

using namespace vsim;
using namespace vsim::dicom;

class SegmentationFullSize : public QObject
{
    Q_OBJECT

private slots:
    void aaa()
    {
        const PhantomOptions options; // 512 x 512 x 400, 0.7 x 0.7 x 1.0 mm, 20 HU, seed 1
        const PhantomModel model = buildPhantomModel(PhantomKind::Aaa, options);
        const VolumeGeometry geometry = phantomGeometry(options);
        const CtVolume ct = renderPhantomCt(model, stackOf(geometry), options);
        const LabelVolume truth = renderPhantomLabels(model, geometry);
        QElapsedTimer timer;
        timer.start();
        const imaging::SegmentationResult result =
            imaging::segmentVessels(ct, ParameterSet(imaging::segmentationParameters()));
        const double seconds = timer.elapsed() / 1000.0;
        const double dice = imaging::diceCoefficient(result.label, 1, truth, label::kVesselLumen);
        rusage usage{};
        getrusage(RUSAGE_SELF, &usage);
        std::printf("{\"case\": \"segment_aaa_512x512x400\", \"seconds\": %.2f, \"dice\": %.4f, \"volume_ml\": %.1f, "
                    "\"peak_rss_mib\": %.0f}\n",
                    seconds, dice, result.figures.at("volume_ml"), usage.ru_maxrss / 1024.0);
        QVERIFY(dice >= 0.95);
    }
};

QTEST_GUILESS_MAIN(SegmentationFullSize)
#include "tst_segmentation_fullsize.moc"
