#include "vsim/core/Error.h"

namespace vsim {
namespace {

std::string describe(const std::string& message, const Error::Context& context)
{
    std::string text = message;
    for (const auto& [key, value] : context)
        text += "\n  " + key + ": " + value;
    return text;
}

} // namespace

Error::Error(const std::string& message, Context context)
    : std::runtime_error(describe(message, context)), m_message(message), m_context(std::move(context))
{
}

std::string Error::contextValue(const std::string& key) const
{
    for (const auto& [name, value] : m_context)
        if (name == key)
            return value;
    return {};
}

} // namespace vsim
