#include "core/physics/units/Range.h"

#include <charconv>
#include <cmath>

namespace rosin::physics
{

bool Range::contains(double value) const noexcept
{
    if (!std::isfinite(value))
        return false;
    if (minOpen ? value <= min : value < min)
        return false;
    if (maxOpen ? value >= max : value > max)
        return false;
    if (integer && std::trunc(value) != value)
        return false;
    return !(nonZero && value == 0.0);
}

std::string Range::describe() const
{
    std::string text = nonZero ? "a non-zero number" : integer ? "an integer" : "a number";
    const bool hasMin = std::isfinite(min), hasMax = std::isfinite(max);
    if (hasMin && hasMax && !minOpen && !maxOpen)
        text += " in " + formatNumber(min) + ".." + formatNumber(max);
    else
    {
        if (hasMin)
            text += (minOpen ? " > " : " >= ") + formatNumber(min);
        if (hasMax)
            text += std::string(hasMin ? " and" : "") + (maxOpen ? " < " : " <= ") + formatNumber(max);
    }
    if (*unit)
        text += std::string(" (") + unit + ")";
    return text;
}

std::string formatNumber(double value)
{
    if (std::isnan(value))
        return "nan";
    if (std::isinf(value))
        return value > 0 ? "inf" : "-inf";
    char buffer[32];
    const auto result = std::to_chars(buffer, buffer + sizeof(buffer), value);
    return std::string(buffer, result.ptr);
}

} // namespace rosin::physics
