#pragma once

// Texts kept in English where they are stored (a study's warnings, a run's stop reason, metrics.json) and read by
// people in their language (issue 20, item 7). Code writes such a text as storedText(a string literal) or
// storedText(a Pattern with %1 ... and its values); scripts/error_texts.py collects the literals into the catalogues
// (translations/ErrorTexts.cpp, context "vsim::Error", shared with Error's messages) and into the list this code
// matches against, so that a stored English text -- of this version's studies or of older ones -- is translated
// on reading: storedTextForPeople().

#include "vsim/core/Error.h"

#include <string>

namespace vsim {

/// The English of a stored text written as one literal.
inline std::string storedText(const char* literal) { return literal; }
/// The English of a stored text written as a pattern: its values filled in.
std::string storedText(const Pattern& pattern);
/// A value for a stored text: `value` with `decimals` digits after the '.' ("12.50"); storedTextForPeople() gives it
/// the reader's decimal mark.
std::string storedNumber(double value, int decimals);

/// A stored English text in the reader's language: the catalogue's entry for a literal, or for the pattern that
/// wrote it with its values filled into the translation (each value itself read as a stored text, numbers in the
/// reader's decimal mark). The most specific pattern (the most literal characters) wins; a text no pattern wrote
/// is read as parts joined by "; ", and a part no pattern wrote comes back as it is.
std::string storedTextForPeople(const std::string& english);

/// A value filled into a text for people: a number (perhaps with its unit) in the reader's decimal mark, else
/// storedTextForPeople().
std::string storedValueForPeople(const std::string& value);

} // namespace vsim
