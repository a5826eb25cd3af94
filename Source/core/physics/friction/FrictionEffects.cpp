#include "core/physics/friction/FrictionEffects.h"

#include "core/physics/friction/JunctionGrowthLaw.h"
#include "core/physics/friction/StickingCreepLaw.h"

namespace rosin::physics
{

std::unique_ptr<FrictionLaw> withEffects(std::unique_ptr<FrictionLaw> law, const FrictionEffects& effects)
{
    if (effects.breakawayMargin > 0.0)
        law = std::make_unique<BreakawayMarginLaw>(std::move(law), effects.breakawayMargin);
    if (effects.junctionGrowth > 0.0)
        law = std::make_unique<JunctionGrowthLaw>(
            std::move(law), effects.junctionGrowth, effects.junctionGrowthTime,
            effects.junctionGrowthSaturates ? AgeingForm::Saturating : AgeingForm::Logarithmic);
    if (effects.creepResistance > 0.0)
        law = std::make_unique<StickingCreepLaw>(std::move(law), effects.creepResistance);
    return law;
}

} // namespace rosin::physics
