#include "SimulationModel.h"

#include "lab/scan/ModelSpec.h"

namespace rosin::discovery
{

// Through the scan's ModelSpec, so a trial here is built exactly as a cell of `rosin scan` is.
physics::VoiceConfig voiceConfig(const SimulationModel& model)
{
    physics::VoiceConfig cfg = scan::voiceConfig(scan::modelFromPreset(model.preset));
    cfg.lossScale = model.lossScale;
    return cfg;
}

std::unique_ptr<physics::FrictionLaw> frictionLaw(const SimulationModel& model)
{
    return physics::withEffects(scan::frictionLaw(scan::modelFromPreset(model.preset)),
                                model.frictionEffects);
}

} // namespace rosin::discovery
