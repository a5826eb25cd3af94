// Automation files ("rosin-automation/1", rosin render --automation): JSON text -> validated lanes, each
// read at a few times. Accepted lanes must give finite values.
#include "core/config/ConfigError.h"
#include "core/config/JsonFile.h"
#include "fuzz/FuzzTarget.h"
#include "instrument/engine/AutomationLanes.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    using namespace rosin;
    try
    {
        const auto root = config::parseJsonText(fuzz::asText(data, size), "automation.json");
        const engine::AutomationLanes lanes = engine::parseAutomation(root, "automation.json");
        for (const auto& lane : lanes.lanes)
            for (double t : {-1.0, 0.0, 0.37, 5.0, 1000.0})
                fuzz::requireFinite(lane.valueAt(t), "automation value");
    }
    catch (const config::ConfigError&)
    {
    }
    return 0;
}
