#include "instrument/engine/InstrumentSetup.h"

#include <cmath>

#include "core/config/VoiceSetup.h"
#include "core/physics/body/BodyParameters.h"
#include "core/physics/body/RadiationGains.h"

namespace rosin::engine
{

int instrumentIndexForPreset(const config::Preset& preset)
{
    return preset.string.name.rfind("violin", 0) == 0 ? 1 : 0;
}

physics::InstrumentConfig buildInstrumentConfig(const InstrumentKey& key, const ProgramExtras& extras)
{
    physics::InstrumentConfig config =
        key.instrument == 1 ? physics::violinInstrument() : physics::celloInstrument();
    if (extras.preset && instrumentIndexForPreset(*extras.preset) == key.instrument)
    {
        const config::VoiceSetup setup = config::buildVoiceSetup(*extras.preset);
        config.contact = setup.contact;
        config.torsion = setup.voice.torsion;
        config.bendingStiffness = setup.voice.bendingStiffness;
        config.bow = setup.voice.bow;
        // The preset's string replaces the instrument string nearest in pitch (log distance).
        std::size_t nearest = 0;
        double best = 1e9;
        for (std::size_t i = 0; i < config.strings.size(); ++i)
        {
            const double d =
                std::abs(std::log(config.strings[i].fundamental() / setup.voice.string.fundamental()));
            if (d < best)
                best = d, nearest = i;
        }
        config.strings[nearest] = setup.voice.string;
        physics::applyRadiationGains(config.body, extras.preset->radiationGains);
    }
    config.friction = key.friction;
    if (!key.body)
        config.body = physics::rigidBody();
    config.contact.ambientOffset = key.ambientCelsius - kCalibrationAmbientCelsius;
    config.modeBandwidthHz = key.quality == ModelQuality::Live ? kLiveBandwidthHz : 0.0;
    return config;
}

} // namespace rosin::engine
