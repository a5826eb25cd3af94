#pragma once
// From a Preset to what BowedStringVoice::prepare() and makeFrictionLaw() take.
#include <string>
#include <vector>

#include "core/config/Preset.h"
#include "core/physics/laws/FrictionLawFactory.h"
#include "core/physics/voice/VoiceConfig.h"

namespace rosin::config
{

struct VoiceSetup
{
    physics::VoiceConfig voice;
    physics::ContactParameters contact;
    physics::FrictionModel friction = physics::FrictionModel::Plastic;
};

/// "cello", "violin", "rigid" (physics::bodyByName accepts exactly these).
const std::vector<std::string>& bodyNames();
/// "galluzzo", "schumacher": the [Galluzzo2017] Table 2 contacts; "cantilever": [Smith2000]'s rig
/// (CantileverContact.h).
const std::vector<std::string>& contactNames();
/// physics::frictionModelNames(), for validation messages.
std::vector<std::string> frictionNames();

/// Builds the voice configuration, contact and friction model. Throws ConfigError (file = preset.source)
/// if a name is not known, which only happens for presets built in code or overridden on the command line.
VoiceSetup buildVoiceSetup(const Preset& preset);

} // namespace rosin::config
