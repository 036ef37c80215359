#include "vsim/core/Localized.h"

#include <atomic>
#include <utility>

namespace vsim {
namespace {

std::atomic<Localizer>& installedLocalizer()
{
    static std::atomic<Localizer> localizer{nullptr};
    return localizer;
}

std::atomic<char>& installedDecimalMark()
{
    static std::atomic<char> mark{'.'};
    return mark;
}

thread_local const ThreadTextLanguage* innermostScope = nullptr;

} // namespace

void setLocalizer(Localizer localizer)
{
    installedLocalizer().store(localizer);
}

std::string localized(const char* context, const char* english)
{
    if (const ThreadTextLanguage* scope = ThreadTextLanguage::current())
        return scope->lookup(context, english);
    const Localizer localizer = installedLocalizer().load();
    return localizer ? localizer(context, english) : std::string(english);
}

std::string LocalizedWhen::operator()(const char* context, const char* english) const
{
    return forPeople ? localized(context, english) : std::string(english);
}

std::string LocalizedWhen::number(std::string printed) const
{
    return forPeople ? localizedNumber(std::move(printed)) : printed;
}

std::string localizedText(const char* context, const std::string& english)
{
    return localized(context, english.c_str());
}

void setDecimalMark(char mark)
{
    installedDecimalMark().store(mark);
}

std::string localizedNumber(std::string printed)
{
    const ThreadTextLanguage* scope = ThreadTextLanguage::current();
    const char mark = scope ? scope->decimalMark() : installedDecimalMark().load();
    if (mark != '.')
        for (char& c : printed)
            if (c == '.')
                c = mark;
    return printed;
}

ThreadTextLanguage::ThreadTextLanguage(Lookup lookup, char decimalMark)
    : m_lookup(std::move(lookup)), m_decimalMark(decimalMark), m_outer(innermostScope)
{
    innermostScope = this;
}

ThreadTextLanguage::~ThreadTextLanguage()
{
    innermostScope = m_outer;
}

const ThreadTextLanguage* ThreadTextLanguage::current()
{
    return innermostScope;
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
