#include "vsim/core/DicomUid.h"

#include "vsim/core/Error.h"

#include <mutex>
#include <random>

namespace vsim {
namespace {

__extension__ typedef unsigned __int128 Uint128; // GCC's and Clang's 128-bit integer (not ISO C++)

std::mutex g_mutex;
std::string g_root;

/// A uniformly random number below 2^bits (bits <= 128), from the system's entropy source.
Uint128 randomBits(int bits)
{
    static std::random_device device;
    Uint128 value = 0;
    for (int word = 0; word < 4; ++word)
        value = (value << 32) | device();
    return bits >= 128 ? value : value & ((Uint128(1) << bits) - 1);
}

std::string decimal(Uint128 value)
{
    std::string digits;
    do
    {
        digits.insert(digits.begin(), char('0' + int(value % 10)));
        value /= 10;
    } while (value != 0);
    return digits;
}

bool validPrefix(const std::string& root)
{
    if (root.empty() || root.size() > 32 || root.front() == '.' || root.back() == '.')
        return false;
    std::size_t start = 0;
    while (start <= root.size())
    {
        const std::size_t dot = std::min(root.find('.', start), root.size());
        const std::string component = root.substr(start, dot - start);
        if (component.empty() || component.find_first_not_of("0123456789") != std::string::npos ||
            (component.size() > 1 && component.front() == '0'))
            return false;
        start = dot + 1;
    }
    return true;
}

} // namespace

std::string newDicomUid()
{
    const std::string root = dicomUidRoot();
    if (root.empty())
    {
        // A version 4 UUID (RFC 4122: 4 bits of version, 2 of variant) as one decimal integer under 2.25.
        Uint128 uuid = randomBits(128);
        uuid &= ~(Uint128(0xF) << 76);
        uuid |= Uint128(0x4) << 76;
        uuid &= ~(Uint128(0x3) << 62);
        uuid |= Uint128(0x2) << 62;
        return "2.25." + decimal(uuid);
    }
    // 96 random bits plus 1: at most 29 digits, never the component "0"; decimal() writes no leading zeros.
    return root + "." + decimal(randomBits(96) + 1);
}

void setDicomUidRoot(const std::string& root)
{
    if (!root.empty() && !validPrefix(root))
        throw Error(Pattern{"a UID root is digits in components separated by dots, without leading zeros, at most 32 "
                            "characters (e.g. 1.2.826.0.1.3680043.10.1234), not '%1'",
                            {root}});
    std::lock_guard lock(g_mutex);
    g_root = root;
}

std::string dicomUidRoot()
{
    std::lock_guard lock(g_mutex);
    return g_root;
}

} // namespace vsim
