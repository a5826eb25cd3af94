// Presets ("rosin-preset/1"): JSON text -> validated Preset -> voice configuration -> a prepared voice bowed
// for a few milliseconds. A preset the reader accepts must build and bow to finite output.
#include "core/config/ConfigError.h"
#include "core/config/JsonFile.h"
#include "core/config/PresetLoader.h"
#include "core/config/VoiceSetup.h"
#include "core/physics/voice/BowedStringVoice.h"
#include "fuzz/FuzzTarget.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    using namespace rosin;
    try
    {
        const auto root = config::parseJsonText(fuzz::asText(data, size), "fuzz.json");
        const config::Preset preset = config::parsePreset(root, "fuzz.json", "fuzz");
        const config::VoiceSetup setup = config::buildVoiceSetup(preset);
        physics::BowedStringVoice voice;
        voice.prepare(setup.voice, physics::makeFrictionLaw(setup.friction, setup.contact), 22050.0);
        physics::BowInput bow;
        bow.bowForce = 0.5;
        bow.bowVelocity = 0.1;
        for (int n = 0; n < 128; ++n)
            fuzz::requireFinite(voice.step(bow).bridgeForce, "bridge force");
    }
    catch (const config::ConfigError&)
    {
    }
    return 0;
}
