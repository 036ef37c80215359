#include "vsim/core/StoredText.h"

#include "vsim/core/Localized.h"

#include <cstddef>
#include <cstdio>
#include <map>
#include <regex>
#include <vector>

namespace vsim {
namespace detail {
// translations/ErrorTexts.cpp (written by scripts/error_texts.py): every literal and pattern of Error and storedText.
extern const char* const kLibraryTexts[];
extern const std::size_t kLibraryTextCount;
} // namespace detail

namespace {

/// A pattern cut at its placeholders: pieces[0] %slots[0] pieces[1] ... %slots[n-1] pieces[n].
struct KnownPattern
{
    const char* words = nullptr;
    std::vector<std::string> pieces;
    std::vector<int> slots; // 0-based argument numbers
    std::size_t literalLength = 0;
};

bool placeholderAt(const std::string& text, std::size_t i)
{
    return text[i] == '%' && i + 1 < text.size() && text[i + 1] >= '1' && text[i + 1] <= '9';
}

std::vector<KnownPattern> cutPatterns()
{
    std::vector<KnownPattern> patterns;
    for (std::size_t t = 0; t < detail::kLibraryTextCount; ++t)
    {
        const std::string text = detail::kLibraryTexts[t];
        KnownPattern pattern;
        pattern.words = detail::kLibraryTexts[t];
        pattern.pieces.emplace_back();
        for (std::size_t i = 0; i < text.size(); ++i)
            if (placeholderAt(text, i))
            {
                pattern.slots.push_back(text[i + 1] - '1');
                pattern.pieces.emplace_back();
                ++i;
            }
            else
            {
                pattern.pieces.back() += text[i];
                ++pattern.literalLength;
            }
        // A pattern is recognised by its words: one with too few, or with two placeholders side by side, would
        // claim texts that other code wrote.
        bool adjacent = false;
        for (std::size_t p = 1; p + 1 < pattern.pieces.size(); ++p)
            adjacent = adjacent || pattern.pieces[p].empty();
        if (!pattern.slots.empty() && !adjacent && pattern.literalLength >= 8)
            patterns.push_back(std::move(pattern));
    }
    return patterns;
}

const std::vector<KnownPattern>& knownPatterns()
{
    static const std::vector<KnownPattern> patterns = cutPatterns();
    return patterns;
}

/// Matches text[at...] against the pattern's slots from `slot` on, filling `values`; tries every place the next
/// piece occurs (a value may hold the words that follow it).
bool matchFrom(const std::string& text, std::size_t at, const KnownPattern& pattern, std::size_t slot,
               std::map<int, std::string>& values)
{
    if (slot == pattern.slots.size())
        return at == text.size();
    const std::string& next = pattern.pieces[slot + 1];
    const bool last = slot + 1 == pattern.slots.size();
    for (std::size_t end = text.find(next, at + 1); end != std::string::npos; end = text.find(next, end + 1))
    {
        if (last && end + next.size() != text.size())
            continue;
        std::string value = text.substr(at, end - at);
        const auto known = values.find(pattern.slots[slot]);
        if (known != values.end() && known->second != value)
            continue;
        std::map<int, std::string> tried = values;
        tried[pattern.slots[slot]] = std::move(value);
        if (matchFrom(text, end + next.size(), pattern, slot + 1, tried))
        {
            values = std::move(tried);
            return true;
        }
    }
    return false;
}

} // namespace

std::string storedValueForPeople(const std::string& value)
{
    // A number, perhaps with its unit ("12.5 MPa").
    static const std::regex number(R"([-+]?[0-9]+\.[0-9]+([eE][-+]?[0-9]+)?( [A-Za-z/%]+)?)");
    if (std::regex_match(value, number))
        return localizedNumber(value);
    return storedTextForPeople(value);
}

std::string storedText(const Pattern& pattern)
{
    return withArguments(pattern.text, pattern.values);
}

std::string storedNumber(double value, int decimals)
{
    char text[64];
    std::snprintf(text, sizeof text, "%.*f", decimals, value);
    return text;
}

std::string storedTextForPeople(const std::string& english)
{
    if (english.empty())
        return english;
    if (std::string translated = localizedText("vsim::Error", english); translated != english)
        return translated;
    const KnownPattern* best = nullptr;
    std::map<int, std::string> bestValues;
    for (const KnownPattern& pattern : knownPatterns())
    {
        if (best && pattern.literalLength <= best->literalLength)
            continue;
        if (english.compare(0, pattern.pieces.front().size(), pattern.pieces.front()) != 0)
            continue;
        std::map<int, std::string> values;
        if (matchFrom(english, pattern.pieces.front().size(), pattern, 0, values))
        {
            best = &pattern;
            bestValues = std::move(values);
        }
    }
    if (!best)
    {
        // Texts joined by "; " (a run's several reasons), each read on its own.
        const std::size_t joint = english.find("; ");
        if (joint == std::string::npos)
            return english;
        return storedTextForPeople(english.substr(0, joint)) + "; " + storedTextForPeople(english.substr(joint + 2));
    }
    std::vector<std::string> arguments;
    for (const auto& [slot, value] : bestValues)
    {
        arguments.resize(std::size_t(slot) + 1);
        arguments[std::size_t(slot)] = storedValueForPeople(value);
    }
    return withArguments(localizedText("vsim::Error", best->words), arguments);
}

} // namespace vsim
