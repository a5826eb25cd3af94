// Gesture scripts ("rosin-gesture/1"): JSON text -> validated script -> the bow gesture it resolves to, read
// for its first samples. A script the reader accepts must prepare and give finite bow inputs.
#include "core/config/ConfigError.h"
#include "core/config/GestureScriptLoader.h"
#include "core/config/JsonFile.h"
#include "core/gesture/BowGesture.h"
#include "core/gesture/GestureLimits.h"
#include "fuzz/FuzzTarget.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    using namespace rosin;
    try
    {
        const auto root = config::parseJsonText(fuzz::asText(data, size), "fuzz.json");
        const gesture::GestureScript script = config::parseGestureScript(root, "fuzz.json");
        gesture::BowGesture bow;
        bow.prepare(script, {}, 8000.0);
        for (int n = 0; n < 256 && !bow.finished(); ++n)
        {
            const physics::BowInput in = bow.next();
            fuzz::requireFinite(in.bowForce, "bow force");
            fuzz::requireFinite(in.bowVelocity, "bow velocity");
        }
    }
    catch (const config::ConfigError&)
    {
    }
    catch (const gesture::GestureError&)
    {
    }
    return 0;
}
