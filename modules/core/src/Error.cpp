#include "vsim/core/Error.h"

#include "vsim/core/Localized.h"
#include "vsim/core/StoredText.h"

namespace vsim {
namespace {

std::string describe(const std::string& message, const Error::Context& context, bool forPeople = false)
{
    std::string text = message;
    for (const auto& [key, value] : context)
        text += "\n  " + (forPeople ? localizedText("vsim::Error", key) : key) + ": " + value;
    return text;
}

} // namespace

Error::Error(const std::string& message, Context context)
    : std::runtime_error(describe(message, context)), m_message(message), m_context(std::move(context)), m_words(message)
{
}

Error::Error(const Pattern& message, Context context)
    : Error(withArguments(message.text, message.values), std::move(context))
{
    m_words = message.text;
    m_values = message.values;
}

std::string Error::messageForPeople() const
{
    std::vector<std::string> values;
    for (const std::string& value : m_values)
        values.push_back(storedValueForPeople(value));
    return withArguments(localizedText("vsim::Error", m_words), values);
}

std::string Error::textForPeople() const
{
    return describe(messageForPeople(), m_context, true);
}

std::string textForPeople(const std::exception& error)
{
    const auto* ours = dynamic_cast<const Error*>(&error);
    return ours ? ours->textForPeople() : std::string(error.what());
}

std::string Error::contextValue(const std::string& key) const
{
    for (const auto& [name, value] : m_context)
        if (name == key)
            return value;
    return {};
}

} // namespace vsim
