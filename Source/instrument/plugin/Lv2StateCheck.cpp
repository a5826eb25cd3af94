#include "instrument/plugin/Lv2StateCheck.h"

#include <algorithm>
#include <cstring>

namespace rosin::plugin
{

namespace
{
/// JUCE's base-64 alphabet (juce_MemoryBlock.cpp: ".A-Za-z0-9+", in that order).
bool inJuceAlphabet(char c)
{
    return c == '.' || c == '+' || (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9');
}
} // namespace

std::optional<std::string> damagedStateString(const char* text, std::size_t size, std::size_t maxBytes)
{
    if (text == nullptr)
        return "no state string";
    while (size > 0 && text[size - 1] == '\0')
        --size;
    const char* dot = static_cast<const char*>(std::memchr(text, '.', size));
    if (dot == nullptr)
        return "no byte count (expected COUNT.PAYLOAD)";
    const auto digits = static_cast<std::size_t>(dot - text);
    if (digits == 0 || digits > 12)
        return "byte count \"" + std::string(text, std::min<std::size_t>(digits, 24)) +
               "\": expected a decimal number of at most " + std::to_string(maxBytes);
    std::size_t count = 0;
    for (std::size_t i = 0; i < digits; ++i)
    {
        if (text[i] < '0' || text[i] > '9')
            return "byte count \"" + std::string(text, digits) + "\": expected a decimal number of at most " +
                   std::to_string(maxBytes);
        count = count * 10 + static_cast<std::size_t>(text[i] - '0');
    }
    if (count > maxBytes)
        return "byte count " + std::to_string(count) + ": expected at most " + std::to_string(maxBytes);
    const std::size_t payload = size - digits - 1;
    for (std::size_t i = digits + 1; i < size; ++i)
        if (!inJuceAlphabet(text[i]))
            return "payload character " + std::to_string(i) + " is not base-64 (JUCE's alphabet)";
    if (payload != (8 * count + 5) / 6)
        return "payload of " + std::to_string(payload) + " characters for " + std::to_string(count) +
               " bytes: expected " + std::to_string((8 * count + 5) / 6);
    return std::nullopt;
}

} // namespace rosin::plugin
