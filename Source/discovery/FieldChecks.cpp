#include "FieldChecks.h"

#include <cmath>

#include "gesture/GestureLimits.h"

namespace rosin::discovery
{

using config::JsonObject;
using gesture::formatNumber;

bool Bounds::contains(double value) const
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

std::string Bounds::describe() const
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

double requiredNumber(const JsonObject& object, const std::string& key, const Bounds& bounds)
{
    if (!object.has(key))
        object.fail(key, bounds.describe(), "nothing (the field is required)");
    return *optionalNumber(object, key, bounds);
}

std::optional<double> optionalNumber(const JsonObject& object, const std::string& key, const Bounds& bounds)
{
    if (!object.has(key))
        return std::nullopt;
    const auto& value = object.at(key);
    if (!value.is_number() || !bounds.contains(value.get<double>()))
        object.fail(key, bounds.describe(), config::describeJson(value));
    return value.get<double>();
}

std::string requiredString(const JsonObject& object, const std::string& key)
{
    if (!object.has(key))
        object.fail(key, "a string", "nothing (the field is required)");
    return *object.optionalString(key);
}

const nlohmann::json& requiredArray(const JsonObject& object, const std::string& key)
{
    if (!object.has(key))
        object.fail(key, "a non-empty array", "nothing (the field is required)");
    const auto& value = object.at(key);
    if (!value.is_array() || value.empty())
        object.fail(key, "a non-empty array",
                    value.is_array() ? "an empty array" : config::describeJson(value));
    return value;
}

std::string elementPath(const std::string& arrayPath, std::size_t index)
{
    return arrayPath + "[" + std::to_string(index) + "]";
}

} // namespace rosin::discovery
