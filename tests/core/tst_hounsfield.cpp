// Is a volume CT in HU (Hounsfield.h)? Truths: CT-like volumes built with known values: a body with air, a crop of
// soft tissue and contrast without air (noise of 20 HU around 40 HU reaches below 0), the same as stored values
// (+1024), and an MR-like volume (0..2000); a rescale given restores the original values exactly.
#include "vsim/core/Error.h"
#include "vsim/core/Hounsfield.h"

#include <QtTest>

#include <random>

namespace {

/// 40 HU soft tissue with 20 HU noise, a 300 HU vessel, and air outside a body radius (when `withAir`).
vsim::CtVolume volume(bool withAir, int offset = 0)
{
    vsim::VolumeGeometry geometry;
    geometry.dims = {48, 48, 24};
    vsim::CtVolume ct(geometry);
    std::mt19937 random(11);
    std::normal_distribution<double> noise(0.0, 20.0);
    for (int z = 0; z < 24; ++z)
        for (int y = 0; y < 48; ++y)
            for (int x = 0; x < 48; ++x)
            {
                const double r = std::hypot(x - 24.0, y - 24.0);
                double hu = r < 5 ? 300.0 : 40.0;
                if (withAir && r > 22)
                    hu = -1000.0;
                ct.data()[std::size_t((z * 48 + y) * 48 + x)] = std::int16_t(std::lround(hu + noise(random)) + offset);
            }
    return ct;
}

} // namespace

class TestHounsfield : public QObject
{
    Q_OBJECT
private slots:
    void ctInHuPassesWithAndWithoutAir()
    {
        QCOMPARE(vsim::whyNotHounsfield(volume(true)), std::string());
        QCOMPARE(vsim::whyNotHounsfield(volume(false)), std::string()); // a crop without air
    }

    void storedValuesAndMrAreRefusedNamingTheRescale()
    {
        vsim::CtVolume stored = volume(false, 1024);
        QVERIFY(!vsim::whyNotHounsfield(stored).empty());
        std::vector<std::string> warnings;
        try
        {
            vsim::acceptAsHounsfield(stored, std::nullopt, warnings);
            QFAIL("stored values must be refused");
        }
        catch (const vsim::Error& error)
        {
            QCOMPARE(error.contextValue("option"), std::string("--rescale"));
        }
        vsim::CtVolume mr = volume(false);
        for (std::size_t v = 0; v < mr.size(); ++v)
            mr.data()[v] = std::int16_t(std::abs(mr.data()[v]) * 5); // MR-like: arbitrary, never negative
        QVERIFY(!vsim::whyNotHounsfield(mr).empty());
    }

    void aGivenRescaleRestoresTheValues()
    {
        const vsim::CtVolume original = volume(false);
        vsim::CtVolume stored = volume(false, 1024);
        std::vector<std::string> warnings;
        vsim::acceptAsHounsfield(stored, vsim::HounsfieldRescale{1.0, -1024.0}, warnings);
        QCOMPARE(warnings.size(), std::size_t(1));
        QVERIFY(std::equal(original.data(), original.data() + original.size(), stored.data()));
        vsim::CtVolume again = volume(false, 1024);
        QVERIFY_THROWS_EXCEPTION(vsim::Error, vsim::acceptAsHounsfield(again, vsim::HounsfieldRescale{0.0, 1.0}, warnings));
    }
};

QTEST_APPLESS_MAIN(TestHounsfield)
#include "tst_hounsfield.moc"
