#include "core/config/GestureScriptLoader.h"

#include "core/config/JsonFile.h"
#include "core/config/JsonObject.h"
#include "core/gesture/GestureLimits.h"

namespace rosin::config
{

using gesture::Ramp;
using physics::Range;

namespace
{
// A quantity is a number (constant over the segment) or {"from": a, "to": b} / {"to": b} (a ramp; without
// "from" it starts where the previous segment left it).
std::optional<Ramp> parseQuantity(const JsonObject& segment, const std::string& key, const Range& range)
{
    if (!segment.has(key))
        return std::nullopt;
    const auto& v = segment.at(key);
    if (v.is_number())
        return Ramp::constant(*segment.optionalNumber(key, range));
    if (!v.is_object())
        segment.fail(key, range.describe() + " or a ramp {\"from\": x, \"to\": y}", describeJson(v));
    const JsonObject ramp = segment.object(key);
    ramp.allowOnly({"from", "to"});
    Ramp r;
    r.from = ramp.optionalNumber("from", range);
    r.to = ramp.number("to", range);
    return r;
}

gesture::Segment parseSegment(const JsonObject& s)
{
    s.allowOnly({"seconds", "force", "speed", "acceleration", "beta", "finger", "label"});
    gesture::Segment seg;
    seg.seconds = s.number("seconds", gesture::limits::seconds);
    seg.force = parseQuantity(s, "force", gesture::limits::force);
    seg.speed = parseQuantity(s, "speed", gesture::limits::speed);
    seg.acceleration = s.optionalNumber("acceleration", gesture::limits::acceleration);
    seg.beta = parseQuantity(s, "beta", gesture::limits::beta);
    seg.finger = parseQuantity(s, "finger", gesture::limits::finger);
    s.optionalString("label");
    if (seg.speed && seg.acceleration)
        s.fail("acceleration", "either \"speed\" or \"acceleration\" in one segment, not both",
               "both (speed " + describeJson(s.at("speed")) + ")");
    return seg;
}
} // namespace

gesture::GestureScript parseGestureScript(const nlohmann::json& root, const std::string& file,
                                          const gesture::GestureStart& start)
{
    requireFormat(root, file, "rosin-gesture/1");
    const JsonObject r(root, file, "");
    r.allowOnly({"format", "description", "segments"});
    r.optionalString("description");
    if (!r.has("segments") || !r.at("segments").is_array() || r.at("segments").empty())
        r.fail("segments", "a non-empty array of segments",
               r.has("segments") ? describeJson(r.at("segments")) : "nothing (the field is required)");

    gesture::GestureScript script;
    const auto& list = r.at("segments");
    for (std::size_t i = 0; i < list.size(); ++i)
        script.segments.push_back(
            parseSegment(JsonObject(list[i], file, "segments[" + std::to_string(i) + "]")));

    // Cross-segment checks (speed reached by acceleration, total duration) live with the limits.
    try
    {
        gesture::validateScript(script, start);
    }
    catch (const gesture::GestureError& e)
    {
        throw ConfigError(file, e.field(), e.expected(), e.got());
    }
    return script;
}

gesture::GestureScript loadGestureScript(const std::string& path, const gesture::GestureStart& start)
{
    return parseGestureScript(readJsonFile(path), path, start);
}

} // namespace rosin::config
