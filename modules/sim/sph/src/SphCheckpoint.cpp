#include "vsim/sim/sph/SphCheckpoint.h"

#include "vsim/core/Error.h"

#include <cstring>
#include <fstream>
#include <type_traits>

namespace vsim::sim::sph {
namespace {

constexpr char kHeader[] = "VSIM-SPH-CHECKPOINT 2\n";
static_assert(sizeof(Eigen::Vector3d) == 3 * sizeof(double), "positions are written as three doubles each");

class Writer
{
public:
    explicit Writer(std::ostream& out) : m_out(out) {}
    template <class T> void value(const T& v)
    {
        static_assert(std::is_trivially_copyable_v<T>);
        m_out.write(reinterpret_cast<const char*>(&v), sizeof(T));
    }
    /// A long double as two doubles (its leading part and the rest): the format does not depend on its width.
    void wide(long double v)
    {
        const double lead = double(v);
        value(lead), value(double(v - lead));
    }
    template <class T> void array(const std::vector<T>& values)
    {
        value(std::uint64_t(values.size()));
        if (!values.empty())
            m_out.write(reinterpret_cast<const char*>(values.data()), std::streamsize(values.size() * sizeof(T)));
    }
    void text(const std::string& s)
    {
        value(std::uint64_t(s.size()));
        m_out.write(s.data(), std::streamsize(s.size()));
    }

private:
    std::ostream& m_out;
};

class Reader
{
public:
    Reader(std::istream& in, std::filesystem::path file) : m_in(in), m_file(std::move(file)) {}
    template <class T> T value()
    {
        T v{};
        m_in.read(reinterpret_cast<char*>(&v), sizeof(T));
        check();
        return v;
    }
    long double wide()
    {
        const double lead = value<double>();
        return (long double)lead + value<double>();
    }
    std::uint64_t count()
    {
        const auto n = value<std::uint64_t>();
        if (n > (std::uint64_t(1) << 34))
            cutShort();
        return n;
    }
    template <class T> void array(std::vector<T>& values)
    {
        values.resize(count());
        if (!values.empty())
            m_in.read(reinterpret_cast<char*>(values.data()), std::streamsize(values.size() * sizeof(T)));
        check();
    }
    std::string text()
    {
        std::string s(count(), '\0');
        m_in.read(s.data(), std::streamsize(s.size()));
        check();
        return s;
    }
    [[noreturn]] void cutShort() const
    {
        throw Error("the SPH checkpoint is cut short or damaged", {{"file", m_file.string()}});
    }

private:
    void check() const
    {
        if (!m_in)
            cutShort();
    }
    std::istream& m_in;
    std::filesystem::path m_file;
};

void writeSums(Writer& w, const SectionFlow& f)
{
    w.value(f.areaM2), w.value(f.flowRateM3S), w.value(f.meanVelocityMS), w.value(f.peakVelocityMS),
        w.value(f.meanPressurePa), w.value(std::int64_t(f.particles));
}

SectionFlow readSums(Reader& r)
{
    SectionFlow f;
    f.areaM2 = r.value<double>(), f.flowRateM3S = r.value<double>(), f.meanVelocityMS = r.value<double>();
    f.peakVelocityMS = r.value<double>(), f.meanPressurePa = r.value<double>();
    f.particles = int(r.value<std::int64_t>());
    return f;
}

void writeSums(Writer& w, const WallLoadAverage& a)
{
    w.value(a.tawssPa), w.value(a.meanShearPa.x()), w.value(a.meanShearPa.y()), w.value(a.meanShearPa.z());
    w.value(a.osi), w.value(a.meanPressurePa), w.value(a.largestShearPa), w.value(a.sampledTimeS);
}

WallLoadAverage readWallSums(Reader& r)
{
    WallLoadAverage a;
    a.tawssPa = r.value<double>();
    for (int c = 0; c < 3; ++c)
        a.meanShearPa[c] = r.value<double>();
    a.osi = r.value<double>(), a.meanPressurePa = r.value<double>(), a.largestShearPa = r.value<double>();
    a.sampledTimeS = r.value<double>();
    return a;
}

void writeSchedule(Writer& w, const SampleSchedule::State& state)
{
    w.value(state.pendingS), w.value(std::int64_t(state.calls));
}

SampleSchedule::State readSchedule(Reader& r)
{
    SampleSchedule::State state;
    state.pendingS = r.value<double>(), state.calls = long(r.value<std::int64_t>());
    return state;
}

} // namespace

bool isSphCheckpoint(const std::filesystem::path& file)
{
    std::ifstream in(file, std::ios::binary);
    char header[sizeof(kHeader) - 1] = {};
    return in.read(header, sizeof(header)) && std::memcmp(header, kHeader, sizeof(header)) == 0;
}

void writeSphCheckpoint(const SphCheckpoint& c, const std::filesystem::path& file)
{
    std::error_code error;
    if (std::filesystem::exists(file, error) && !isSphCheckpoint(file))
        throw Error("will not replace a file that is not an SPH checkpoint", {{"file", file.string()}});
    std::filesystem::path part = file;
    part += ".part";
    {
        std::ofstream out(part, std::ios::binary | std::ios::trunc);
        Writer w(out);
        out.write(kHeader, sizeof(kHeader) - 1);
        w.value(c.timeS), w.value(std::int64_t(c.steps)), w.value(std::int64_t(c.nextId));
        w.value(std::uint64_t(c.ledger.inflowKg.size()));
        for (std::size_t k = 0; k < c.ledger.inflowKg.size(); ++k)
            w.wide(c.ledger.inflowKg[k]), w.wide(k < c.ledger.outflowKg.size() ? c.ledger.outflowKg[k] : 0.0L);
        w.wide(c.ledger.absorbedKg), w.wide(c.initialFluidMassKg);
        w.value(std::uint64_t(c.particles.size()));
        c.particles.forEachArray([&w](const auto& array) { w.array(array); });
        w.array(c.rates.acceleration), w.array(c.rates.densityRate), w.array(c.rates.shiftVelocity);
        w.array(c.rates.wallDistance);
        w.value(c.rates.largestAcceleration), w.value(c.rates.largestViscousRate);
        w.value(c.rates.largestKinematicViscosity);
        w.array(c.boundaryFlowRateM3S), w.array(c.boundaryPressurePa);
        w.value(c.sections.weightS);
        w.value(std::uint64_t(c.sections.flows.size()));
        for (const SectionFlow& f : c.sections.flows)
            writeSums(w, f);
        w.array(c.sections.largestPeaks);
        writeSchedule(w, c.sections.schedule);
        w.value(c.sections.phaseWeightS);
        w.value(std::uint64_t(c.sections.phaseFlows.size()));
        for (const SectionFlow& f : c.sections.phaseFlows)
            writeSums(w, f);
        w.value(std::uint64_t(c.wallLoads.points.size()));
        for (const WallLoadAverage& a : c.wallLoads.points)
            writeSums(w, a);
        writeSchedule(w, c.wallLoads.schedule);
        w.value(std::uint64_t(c.counters.size()));
        for (const auto& [name, number] : c.counters)
            w.text(name), w.value(number);
        out.write(kHeader, sizeof(kHeader) - 1); // the end mark: a file cut short lacks it
        if (!out.flush())
            throw Error("cannot write the SPH checkpoint", {{"file", part.string()}});
    }
    std::filesystem::rename(part, file, error);
    if (error)
        throw Error("cannot write the SPH checkpoint", {{"file", file.string()}, {"reason", error.message()}});
}

SphCheckpoint readSphCheckpoint(const std::filesystem::path& file)
{
    std::ifstream in(file, std::ios::binary);
    if (!in)
        throw Error("cannot open the SPH checkpoint", {{"file", file.string()}});
    if (!isSphCheckpoint(file))
        throw Error("not an SPH checkpoint of this version (its first line is not 'VSIM-SPH-CHECKPOINT 2')",
                    {{"file", file.string()}});
    in.seekg(std::streamoff(sizeof(kHeader) - 1));
    Reader r(in, file);
    SphCheckpoint c;
    c.timeS = r.value<double>(), c.steps = long(r.value<std::int64_t>()), c.nextId = int(r.value<std::int64_t>());
    const std::uint64_t boundaries = r.count();
    for (std::uint64_t k = 0; k < boundaries; ++k)
        c.ledger.inflowKg.push_back(r.wide()), c.ledger.outflowKg.push_back(r.wide());
    c.ledger.absorbedKg = r.wide(), c.initialFluidMassKg = r.wide();
    const std::uint64_t n = r.count();
    c.particles.forEachArray([&](auto& array) {
        r.array(array);
        if (array.size() != n)
            r.cutShort();
    });
    r.array(c.rates.acceleration), r.array(c.rates.densityRate), r.array(c.rates.shiftVelocity);
    r.array(c.rates.wallDistance);
    c.rates.largestAcceleration = r.value<double>(), c.rates.largestViscousRate = r.value<double>();
    c.rates.largestKinematicViscosity = r.value<double>();
    r.array(c.boundaryFlowRateM3S), r.array(c.boundaryPressurePa);
    c.sections.weightS = r.value<double>();
    c.sections.flows.resize(r.count());
    for (SectionFlow& f : c.sections.flows)
        f = readSums(r);
    r.array(c.sections.largestPeaks);
    c.sections.schedule = readSchedule(r);
    c.sections.phaseWeightS = r.value<double>();
    c.sections.phaseFlows.resize(r.count());
    for (SectionFlow& f : c.sections.phaseFlows)
        f = readSums(r);
    c.wallLoads.points.resize(r.count());
    for (WallLoadAverage& a : c.wallLoads.points)
        a = readWallSums(r);
    c.wallLoads.schedule = readSchedule(r);
    const std::uint64_t counters = r.count();
    for (std::uint64_t k = 0; k < counters; ++k)
    {
        std::string name = r.text();
        c.counters[name] = r.value<double>();
    }
    char end[sizeof(kHeader) - 1] = {};
    if (!in.read(end, sizeof(end)) || std::memcmp(end, kHeader, sizeof(end)) != 0)
        r.cutShort();
    return c;
}

} // namespace vsim::sim::sph
