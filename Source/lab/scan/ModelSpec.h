#pragma once
// The instrument a scan bows: one string on a body with one friction law and contact, and the model switches
// of [Galluzzo2017] Figs. 9-12, resolved from a preset so that a scan specification file describes the model
// completely (a changed preset file cannot silently change a resumed scan).
#include <memory>
#include <string>

#include "core/config/Preset.h"
#include "core/physics/friction/FrictionLaw.h"
#include "core/physics/string/StringParameters.h"
#include "core/physics/thermal/ContactParameters.h"
#include "core/physics/voice/VoiceConfig.h"

namespace rosin::scan
{

struct ModelSpec
{
    std::string preset = "galluzzo-rig"; ///< the preset's name (reports only)
    physics::StringParameters string = physics::stringFromCatalogue("cello-D3");
    std::string body = "cello";       ///< "cello", "violin" or "rigid"
    std::string friction = "plastic"; ///< a physics::frictionModelNames() entry
    physics::ContactParameters contact = physics::galluzzoContact();
    bool torsion = true;
    bool bendingStiffness = true;
    /// The open string with the intrinsic damping of a finger-stopped one ([Galluzzo2017] Fig. 12c: eta_F
    /// from the bracket of Table 1). The scan bows open strings, so the voice's own "stopped" switch never
    /// fires.
    bool fingerDamping = false;
    physics::BowParameters bow; ///< ribbon width and hair (default: the seeds' rigid point)
};

/// The model of a preset. Throws config::ConfigError if a name in it is unknown.
ModelSpec modelFromPreset(const config::Preset& preset);
/// What BowedStringVoice::prepare() takes (finger damping applied to the string's loss).
physics::VoiceConfig voiceConfig(const ModelSpec& model);
/// A new, unprepared friction law of the model.
std::unique_ptr<physics::FrictionLaw> frictionLaw(const ModelSpec& model);

} // namespace rosin::scan
