#pragma once
// Optional friction effects beyond the source texts' laws ([Notes §8]; the discrepancy workflow's catalog),
// as wrappers any law can take. All off by default, so a law built without them is exactly the source text's.
#include <memory>

#include "core/physics/friction/BreakawayMarginLaw.h"
#include "core/physics/friction/FrictionLaw.h"
#include "core/physics/friction/JunctionGrowthLaw.h"

namespace rosin::physics
{

struct FrictionEffects
{
    double junctionGrowth = 0.0;          ///< JunctionGrowthLaw: fractional static-limit gain per e-fold
    double junctionGrowthTime = 0.005;    ///< s, tau_c: hold time at which ageing sets in
    double creepResistance = 0.0;         ///< StickingCreepLaw: eta in N s/m; 0 = no creep
    bool junctionGrowthSaturates = false; ///< JunctionGrowthLaw's AgeingForm::Saturating instead of log
    double breakawayMargin = 0.0;         ///< BreakawayMarginLaw: static-limit excess until the first slip

    bool any() const noexcept
    {
        return junctionGrowth > 0.0 || creepResistance > 0.0 || breakawayMargin > 0.0;
    }
};

/// Wraps `law` with the effects that are on (the breakaway margin innermost, then ageing: both raise the
/// force the law sees while held; creep outermost acts on the held contact).
std::unique_ptr<FrictionLaw> withEffects(std::unique_ptr<FrictionLaw> law, const FrictionEffects& effects);

} // namespace rosin::physics
