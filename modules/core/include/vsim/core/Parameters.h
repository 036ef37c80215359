#pragma once

#include <map>
#include <string>
#include <vector>

namespace vsim {

/// One tunable number of an algorithm or solver, declared once: it feeds the GUI form, `--param key=value`
/// on the CLI, the study's provenance JSON and the report's parameter table.
struct ParameterSpec
{
    enum class Kind { Real, Integer };

    std::string key;         ///< stable identifier, e.g. "young_modulus"
    std::string label;       ///< for people, e.g. "Young's modulus"
    std::string unit;        ///< e.g. "MPa", "mm", "" for dimensionless
    double defaultValue = 0.0;
    double minimum = 0.0;    ///< inclusive
    double maximum = 0.0;    ///< inclusive
    std::string group;       ///< GUI group box / report section
    std::string description; ///< one sentence, with the reference if any
    Kind kind = Kind::Real;
};

/// Values for a list of ParameterSpec, every value validated against its declaration.
class ParameterSet
{
public:
    ParameterSet() = default;
    /// Starts from the declared defaults. Throws vsim::Error if a declaration is inconsistent
    /// (duplicate key, default outside its range).
    explicit ParameterSet(std::vector<ParameterSpec> specs);

    /// Sets a value; throws vsim::Error naming the key, the value and the range when it is out of range,
    /// not an integer for an integer parameter, not finite, or the key is unknown.
    void set(const std::string& key, double value);
    /// Parses "key=value" (as given to --param); throws vsim::Error on malformed text.
    void setFromText(const std::string& assignment);
    /// Returns the current value; throws vsim::Error for an unknown key.
    double get(const std::string& key) const;
    /// Returns the declaration of a key; throws vsim::Error for an unknown key.
    const ParameterSpec& spec(const std::string& key) const;

    const std::vector<ParameterSpec>& specs() const { return m_specs; }
    /// Values by key (sorted), for provenance records.
    const std::map<std::string, double>& values() const { return m_values; }
    /// Values by key as text (numberText), for provenance records.
    std::map<std::string, std::string> valuesAsText() const;

private:
    std::vector<ParameterSpec> m_specs;
    std::map<std::string, double> m_values;
};

/// The text a number is recorded in (provenance, artifact attributes, CLI messages): the default stream form.
std::string numberText(double value);
/// A number as text with 15 significant digits, for results kept as text (run metrics in a study's attributes):
/// it reads back to the value within 1e-15.
std::string preciseNumberText(double value);

} // namespace vsim
