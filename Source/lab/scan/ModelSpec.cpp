#include "lab/scan/ModelSpec.h"

#include "core/config/VoiceSetup.h"
#include "core/physics/body/BodyParameters.h"
#include "core/physics/laws/FrictionLawFactory.h"

namespace rosin::scan
{

ModelSpec modelFromPreset(const config::Preset& preset)
{
    // buildVoiceSetup validates the names and resolves the contact's base and overrides.
    const config::VoiceSetup setup = config::buildVoiceSetup(preset);
    ModelSpec m;
    m.preset = preset.name;
    m.string = preset.string;
    m.body = preset.body;
    m.friction = preset.friction;
    m.contact = setup.contact;
    m.torsion = preset.torsion;
    m.bendingStiffness = preset.bendingStiffness;
    m.bow = preset.bow;
    // A scan measures the deterministic model (its lanes draw no noise, and a cell must repeat): the
    // program's slip noise, a property of the instrument's sound, is left out.
    m.bow.slipNoise = 0.0;
    return m;
}

physics::VoiceConfig voiceConfig(const ModelSpec& model)
{
    physics::VoiceConfig cfg;
    cfg.string = model.string;
    if (model.fingerDamping)
        cfg.string.lossF = cfg.string.stoppedLossF;
    cfg.body = physics::bodyByName(model.body);
    cfg.torsion = model.torsion;
    cfg.bendingStiffness = model.bendingStiffness;
    cfg.bow = model.bow;
    return cfg;
}

std::unique_ptr<physics::FrictionLaw> frictionLaw(const ModelSpec& model)
{
    return physics::makeFrictionLaw(physics::frictionModelFromName(model.friction), model.contact);
}

} // namespace rosin::scan
