#pragma once

#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace vsim {

/// A message whose words are a literal with %1 ... %9 and whose values come apart, so that the catalogues can
/// translate the words (scripts/error_texts.py finds each Pattern's literal):
///     throw Error(Pattern{"the study has no artifact '%1'", {id}}, {{"artifact", id}});
struct Pattern
{
    const char* text;
    std::vector<std::string> values;
};

/// The one exception type of compute code: a message for a person plus machine-readable context
/// (file, tag, parameter key, ...). App and CLI catch it at their boundary.
class Error : public std::runtime_error
{
public:
    using Context = std::vector<std::pair<std::string, std::string>>;

    explicit Error(const std::string& message, Context context = {});
    explicit Error(const Pattern& message, Context context = {});

    /// The message without the context.
    const std::string& message() const { return m_message; }
    const Context& context() const { return m_context; }
    /// Returns the value of a context key, or an empty string.
    std::string contextValue(const std::string& key) const;

    /// The message in the reader's language (localized() under "vsim::Error"; the catalogues hold every message
    /// written as one literal or as a Pattern, translations/ErrorTexts.cpp); what() and message() stay English,
    /// for logs and the CLI.
    std::string messageForPeople() const;
    /// messageForPeople() and the context, its keys in the reader's language too.
    std::string textForPeople() const;

private:
    std::string m_message;
    Context m_context;
    std::string m_words;               // what the catalogues translate: the message, or its Pattern's text
    std::vector<std::string> m_values; // the Pattern's values, filled into the translated words
};

/// What a person reads of any exception: a vsim::Error's textForPeople(), else what().
std::string textForPeople(const std::exception& error);

/// Thrown when the user cancelled a long task; nothing was written.
class Cancelled : public Error
{
public:
    Cancelled() : Error("cancelled by the user") {}
};

} // namespace vsim
