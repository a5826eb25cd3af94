#include "core/config/VoiceSetup.h"

#include <algorithm>

#include "core/config/JsonObject.h"
#include "core/physics/body/BodyParameters.h"
#include "core/physics/body/RadiationGains.h"
#include "core/physics/rig/CantileverContact.h"
#include "core/physics/thermal/RosinMaterial.h"

namespace rosin::config
{

const std::vector<std::string>& bodyNames()
{
    static const std::vector<std::string> names = {"cello", "violin", "rigid"};
    return names;
}

const std::vector<std::string>& contactNames()
{
    static const std::vector<std::string> names = {"galluzzo", "schumacher", "cantilever"};
    return names;
}

std::vector<std::string> frictionNames()
{
    return physics::frictionModelNames();
}

namespace
{
void requireOneOf(const Preset& preset, const std::string& field, const std::string& value,
                  const std::vector<std::string>& allowed)
{
    if (std::find(allowed.begin(), allowed.end(), value) == allowed.end())
        throw ConfigError(preset.source, field, oneOfText(allowed), nlohmann::json(value).dump());
}
} // namespace

VoiceSetup buildVoiceSetup(const Preset& preset)
{
    requireOneOf(preset, "body", preset.body, bodyNames());
    requireOneOf(preset, "friction", preset.friction, frictionNames());
    requireOneOf(preset, "contact", preset.contact, contactNames());
    requireOneOf(preset, "rosin", preset.rosin, physics::rosinMaterialNames());

    VoiceSetup setup;
    setup.voice.string = preset.string;
    setup.voice.body = physics::bodyByName(preset.body);
    physics::applyRadiationGains(setup.voice.body, preset.radiationGains);
    setup.voice.torsion = preset.torsion;
    setup.voice.bendingStiffness = preset.bendingStiffness;
    setup.voice.bow = preset.bow;

    setup.contact = preset.contact == "schumacher"   ? physics::schumacherContact()
                    : preset.contact == "cantilever" ? physics::cantileverContact()
                                                     : physics::galluzzoContact();
    const ContactOverrides& o = preset.contactOverrides;
    setup.contact.rig.radius = o.radius.value_or(setup.contact.rig.radius);
    setup.contact.rig.referenceForce = o.referenceForce.value_or(setup.contact.rig.referenceForce);
    setup.contact.rig.layerThickness = o.layerThickness.value_or(setup.contact.rig.layerThickness);
    setup.contact.rig.scaling = o.scaling.value_or(setup.contact.rig.scaling);
    if (preset.contact == "cantilever")
        setup.contact.calibration = setup.contact.rig; // [Smith2000] calibrated on the rig's own contact
    setup.contact.ambientOffset = preset.ambientOffset;
    setup.contact.materials = physics::withRosin(
        setup.contact.materials, physics::rosinMaterial(physics::rosinMaterialFromName(preset.rosin)));

    setup.friction = physics::frictionModelFromName(preset.friction);
    return setup;
}

} // namespace rosin::config
