#include "instrument/engine/AutomationLanes.h"

#include <algorithm>
#include <cmath>

#include "core/config/ConfigError.h"
#include "core/config/JsonFile.h"
#include "core/config/JsonObject.h"
#include "instrument/engine/EngineParameters.h"

namespace rosin::engine
{

double AutomationLane::valueAt(double seconds) const noexcept
{
    if (points.empty())
        return 0.0;
    if (seconds <= points.front().seconds)
        return points.front().value;
    for (std::size_t i = 1; i < points.size(); ++i)
    {
        const AutomationPoint& a = points[i - 1];
        const AutomationPoint& b = points[i];
        if (seconds < b.seconds)
        {
            if (stepped || b.seconds <= a.seconds)
                return a.value;
            return a.value + (b.value - a.value) * (seconds - a.seconds) / (b.seconds - a.seconds);
        }
    }
    return points.back().value;
}

namespace
{
std::string knownIds()
{
    std::string text;
    for (const char* id : allParameterIds())
        text += (text.empty() ? "" : ", ") + std::string(id);
    return text;
}
} // namespace

AutomationLanes parseAutomation(const nlohmann::json& root, const std::string& file)
{
    config::requireFormat(root, file, "rosin-automation/1");
    const config::JsonObject top(root, file, "");
    top.allowOnly({"format", "lanes"});
    const config::JsonObject lanes = top.object("lanes");
    AutomationLanes result;
    for (const auto& [id, points] : root.at("lanes").items())
    {
        const std::string field = lanes.path(id);
        const ParameterSpec* spec = findParameterSpec(id);
        if (spec == nullptr)
            throw config::ConfigError(file, field, "a parameter ID (one of " + knownIds() + ")",
                                      "\"" + id + "\"");
        const ParameterSpec& info = *spec;
        const bool boolean = info.kind == ParameterSpec::Kind::Switch;
        if (!points.is_array() || points.empty())
            throw config::ConfigError(file, field, "a non-empty array of [seconds, value] points",
                                      config::describeJson(points));
        AutomationLane lane;
        lane.parameterId = id;
        lane.stepped = info.kind != ParameterSpec::Kind::Continuous;
        for (std::size_t i = 0; i < points.size(); ++i)
        {
            const std::string at = field + "[" + std::to_string(i) + "]";
            const auto& p = points[i];
            if (!p.is_array() || p.size() != 2 || !p[0].is_number())
                throw config::ConfigError(file, at, "a [seconds, value] pair", config::describeJson(p));
            AutomationPoint point;
            point.seconds = p[0].get<double>();
            if (!std::isfinite(point.seconds) || point.seconds < 0.0 || point.seconds > 600.0 ||
                (!lane.points.empty() && point.seconds < lane.points.back().seconds))
                throw config::ConfigError(file, at, "a time in 0..600 s, not before the previous point",
                                          config::describeJson(p[0]));
            const auto& v = p[1];
            if (boolean && v.is_boolean())
                point.value = v.get<bool>() ? 1.0 : 0.0;
            else if (!info.choices.empty() && v.is_string())
            {
                const auto it = std::find(info.choices.begin(), info.choices.end(), v.get<std::string>());
                if (it == info.choices.end())
                    throw config::ConfigError(file, at, config::oneOfText(info.choices),
                                              config::describeJson(v));
                point.value = static_cast<double>(it - info.choices.begin());
            }
            else if (v.is_number() && std::isfinite(v.get<double>()) && v.get<double>() >= info.min &&
                     v.get<double>() <= info.max)
                point.value = lane.stepped ? std::round(v.get<double>()) : v.get<double>();
            else
                throw config::ConfigError(file, at,
                                          info.choices.empty() ? "a value in " + std::to_string(info.min) +
                                                                     ".." + std::to_string(info.max)
                                                               : config::oneOfText(info.choices),
                                          config::describeJson(v));
            lane.points.push_back(point);
        }
        result.lanes.push_back(std::move(lane));
    }
    return result;
}

AutomationLanes loadAutomation(const std::string& path)
{
    return parseAutomation(config::readJsonFile(path), path);
}

} // namespace rosin::engine
