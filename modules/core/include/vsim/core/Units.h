#pragma once

// Unit conversions. The study and all geometry use millimetres in the DICOM patient frame (LPS);
// solvers work in SI (m, kg, s, Pa) and convert at their boundary with these helpers.

namespace vsim::units {

inline constexpr double kMillimetre = 1e-3;            // m
inline constexpr double kPascalPerMmHg = 133.322387415; // Pa, conventional millimetre of mercury
inline constexpr double kPascalPerKilopascal = 1e3;
inline constexpr double kPascalPerMegapascal = 1e6;
inline constexpr double kCubicMetrePerMillilitre = 1e-6;

/// Millimetres -> metres.
constexpr double mmToM(double millimetres) { return millimetres * kMillimetre; }
/// Metres -> millimetres.
constexpr double mToMm(double metres) { return metres / kMillimetre; }
/// mmHg -> Pa.
constexpr double mmHgToPa(double mmHg) { return mmHg * kPascalPerMmHg; }
/// Pa -> mmHg.
constexpr double paToMmHg(double pascal) { return pascal / kPascalPerMmHg; }
/// MPa -> Pa.
constexpr double mpaToPa(double megapascal) { return megapascal * kPascalPerMegapascal; }
/// ml/min -> m^3/s.
constexpr double mlPerMinToM3PerS(double mlPerMinute) { return mlPerMinute * kCubicMetrePerMillilitre / 60.0; }
/// m^3/s -> ml/min.
constexpr double m3PerSToMlPerMin(double cubicMetresPerSecond)
{
    return cubicMetresPerSecond * 60.0 / kCubicMetrePerMillilitre;
}

} // namespace vsim::units
