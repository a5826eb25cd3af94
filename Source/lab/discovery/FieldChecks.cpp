#include "lab/discovery/FieldChecks.h"

#include <cmath>

namespace rosin::discovery
{

using config::JsonObject;
using physics::formatNumber;

double requiredNumber(const JsonObject& object, const std::string& key, const Range& range)
{
    if (!object.has(key))
        object.fail(key, range.describe(), "nothing (the field is required)");
    return *optionalNumber(object, key, range);
}

std::optional<double> optionalNumber(const JsonObject& object, const std::string& key, const Range& range)
{
    if (!object.has(key))
        return std::nullopt;
    const auto& value = object.at(key);
    if (!value.is_number() || !range.contains(value.get<double>()))
        object.fail(key, range.describe(), config::describeJson(value));
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
