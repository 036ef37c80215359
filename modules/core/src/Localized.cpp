#include "vsim/core/Localized.h"

#include <atomic>

namespace vsim {
namespace {

std::atomic<Localizer>& installedLocalizer()
{
    static std::atomic<Localizer> localizer{nullptr};
    return localizer;
}

} // namespace

void setLocalizer(Localizer localizer)
{
    installedLocalizer().store(localizer);
}

std::string localized(const char* context, const char* english)
{
    const Localizer localizer = installedLocalizer().load();
    return localizer ? localizer(context, english) : std::string(english);
}

std::string LocalizedWhen::operator()(const char* context, const char* english) const
{
    return forPeople ? localized(context, english) : std::string(english);
}

std::string localizedText(const char* context, const std::string& english)
{
    return localized(context, english.c_str());
}

std::string withArguments(const std::string& pattern, const std::vector<std::string>& arguments)
{
    std::string filled;
    for (std::size_t i = 0; i < pattern.size(); ++i)
    {
        const bool placeholder = pattern[i] == '%' && i + 1 < pattern.size() && pattern[i + 1] >= '1' &&
                                 pattern[i + 1] <= '9' && std::size_t(pattern[i + 1] - '1') < arguments.size();
        if (!placeholder)
        {
            filled += pattern[i];
            continue;
        }
        filled += arguments[std::size_t(pattern[i + 1] - '1')];
        ++i;
    }
    return filled;
}

} // namespace vsim
