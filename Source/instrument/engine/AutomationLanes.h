#pragma once
// Automation lanes for offline renders: per parameter, breakpoints (time s, value in the parameter's own
// unit), linear in between, held before the first and after the last point. JSON "rosin-automation/1":
//     {"format": "rosin-automation/1",
//      "lanes": {"bowForce": [[0, 1.0], [2.5, 2.0]], "friction": [[0, "plastic"], [4, "classical"]]}}
// Choice parameters take their choice name (or index), booleans true/false. Values are applied on a fixed
// grid of control points (MidiRenderSettings::controlInterval samples), never at block boundaries, so a
// render does not depend on its block size.
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace rosin::engine
{

struct AutomationPoint
{
    double seconds = 0.0;
    double value = 0.0; ///< plain (denormalised) parameter value; a choice's index
};

struct AutomationLane
{
    std::string parameterId;
    std::vector<AutomationPoint> points; ///< ascending in time, at least one
    bool stepped = false;                ///< choices and booleans jump at each point instead of ramping
    double valueAt(double seconds) const noexcept;
};

struct AutomationLanes
{
    std::vector<AutomationLane> lanes;
};

/// Validates and reads a document; ConfigError names `file`, the field ("lanes.bowForce[1]") and the
/// expectation. Unknown parameter IDs, out-of-range values and unsorted times are rejected.
AutomationLanes parseAutomation(const nlohmann::json& root, const std::string& file);
AutomationLanes loadAutomation(const std::string& path);

} // namespace rosin::engine
