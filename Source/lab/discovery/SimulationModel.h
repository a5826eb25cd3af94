#pragma once
// The model the discrepancy workflow simulates and the effect catalog changes: a preset (string, body,
// friction law, contact and its area scaling, rosin temperature at rest) plus the parts of the physics that
// a preset does not carry (the friction-law wrappers of FrictionEffects, the string loss scale). One place
// turns it into a voice, so rosin synth-data (which hides effects) and rosin discover (which tries them)
// simulate exactly the same model for the same effects.
#include <memory>

#include "core/config/Preset.h"
#include "core/physics/friction/FrictionEffects.h"
#include "core/physics/friction/FrictionLaw.h"
#include "core/physics/voice/VoiceConfig.h"
#include "lab/discovery/NuisanceParameters.h"

namespace rosin::discovery
{

struct SimulationModel
{
    config::Preset preset;                    ///< default: the galluzzo-rig (cello D3, cello body, plastic)
    physics::FrictionEffects frictionEffects; ///< junction growth, sticking creep (off by default)
    double lossScale = 1.0;                   ///< VoiceConfig::lossScale: string losses x this
    /// The rig's and the chain's uncertain numbers (rosin discover's calibration); nominal by default. The
    /// sensor's two act only where discover simulates the measurement chain.
    NuisanceValues nuisance;
};

/// The voice's configuration: the preset's string, body and model switches (as rosin scan builds them) with
/// the loss scale. Throws config::ConfigError for an unknown body or law name in the preset.
physics::VoiceConfig voiceConfig(const SimulationModel& model);
/// A new, unprepared friction law: the preset's law on its contact, wrapped with the friction effects.
std::unique_ptr<physics::FrictionLaw> frictionLaw(const SimulationModel& model);

} // namespace rosin::discovery
