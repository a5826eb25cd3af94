#include "lab/discovery/SimulationModel.h"

#include "lab/scan/ModelSpec.h"

namespace rosin::discovery
{

namespace
{
// The rosin's own constants scaled: the layer, and each solid made of the same rosin (a rosin-coated
// string surface), since a lab's uncertainty about rosin is about all of it at once.
void scaleRosin(physics::ContactMaterials& m, const NuisanceValues& n)
{
    const physics::ThermalMaterial rosin = m.layer;
    auto scale = [&](physics::ThermalMaterial& solid)
    {
        if (solid.conductivity != rosin.conductivity ||
            solid.volumetricHeatCapacity != rosin.volumetricHeatCapacity)
            return;
        solid.conductivity *= n.rosinConductivity;
        solid.volumetricHeatCapacity *= n.rosinHeatCapacity;
    };
    scale(m.stationary);
    scale(m.moving);
    scale(m.layer);
}

// Through the scan's ModelSpec, so a trial here is built exactly as a cell of `rosin scan` is.
scan::ModelSpec modelSpec(const SimulationModel& model)
{
    scan::ModelSpec spec = scan::modelFromPreset(model.preset);
    spec.string.tension *= model.nuisance.tension;
    spec.contact.rig.radius *= model.nuisance.contactRadius;
    scaleRosin(spec.contact.materials, model.nuisance);
    return spec;
}
} // namespace

physics::VoiceConfig voiceConfig(const SimulationModel& model)
{
    physics::VoiceConfig cfg = scan::voiceConfig(modelSpec(model));
    cfg.lossScale = model.lossScale * model.nuisance.stringLoss;
    return cfg;
}

std::unique_ptr<physics::FrictionLaw> frictionLaw(const SimulationModel& model)
{
    return physics::withEffects(scan::frictionLaw(modelSpec(model)), model.frictionEffects);
}

} // namespace rosin::discovery
