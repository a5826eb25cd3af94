#include "lab/discovery/independent/OwnEffects.h"

#include <cmath>

#include "lab/discovery/independent/IndependentStreams.h"
#include "lab/discovery/synth/SynthPlan.h"

namespace rosin::discovery
{

namespace
{
double uniform(SeededRandom& r, const double (&range)[2])
{
    return r.uniform(range[0], range[1]);
}
double logUniform(SeededRandom& r, const double (&range)[2])
{
    return range[0] * std::pow(range[1] / range[0], r.uniform());
}

void drawOne(const std::string& name, SeededRandom& r, OwnEffects& e)
{
    using namespace own_ranges;
    if (name == "junction-growth")
    {
        e.growthGain = uniform(r, kGrowthGain);
        e.growthTime = logUniform(r, kGrowthTime);
    }
    else if (name == "breakaway-jump")
    {
        e.breakawayMargin = uniform(r, kBreakawayMargin);
        e.breakawayWarmth = uniform(r, kBreakawayWarmth);
    }
    else if (name == "hertz-contact")
    {
        e.hertz = true;
        e.hertzExponent = uniform(r, kHertzExponent);
        e.hertzReferenceForce = logUniform(r, kHertzReference);
    }
    else if (name == "sticking-creep")
    {
        e.creepShare = uniform(r, kCreepShare);
        e.creepResistance = logUniform(r, kCreepResistance);
    }
    else if (name == "extra-string-damping")
    {
        if (r.uniform() < 0.5)
            e.extraEta = uniform(r, kExtraEta);
        else
            e.bendingLossFactor = uniform(r, kBendingLossFactor);
    }
}
} // namespace

OwnEffects drawOwnEffects(const SynthPlan& plan)
{
    OwnEffects e;
    for (const auto& hidden : plan.effects)
    {
        SeededRandom r(plan.seed, independent_streams::kOwnEffect, effectIndex(*hidden.effect));
        drawOne(hidden.effect->name, r, e);
    }
    e.ambientOffset = plan.model.preset.ambientOffset;
    e.viscous = plan.model.preset.friction == "viscous";
    return e;
}

std::vector<std::pair<std::string, double>> OwnEffects::values() const
{
    std::vector<std::pair<std::string, double>> v;
    if (growthGain > 0.0)
        v.insert(v.end(), {{"junction-growth.gain", growthGain}, {"junction-growth.time", growthTime}});
    if (breakawayMargin > 0.0)
        v.insert(v.end(),
                 {{"breakaway-jump.margin", breakawayMargin}, {"breakaway-jump.warmth", breakawayWarmth}});
    if (hertz)
        v.insert(v.end(), {{"hertz-contact.exponent", hertzExponent},
                           {"hertz-contact.referenceForce", hertzReferenceForce}});
    if (creepResistance > 0.0)
        v.insert(v.end(),
                 {{"sticking-creep.share", creepShare}, {"sticking-creep.resistance", creepResistance}});
    if (extraEta > 0.0)
        v.push_back({"extra-string-damping.extraEta", extraEta});
    if (bendingLossFactor != 1.0)
        v.push_back({"extra-string-damping.bendingLossFactor", bendingLossFactor});
    if (ambientOffset != 0.0)
        v.push_back({"ambient-temperature.offset", ambientOffset});
    if (viscous)
        v.push_back({"friction-law.viscous", 1.0});
    return v;
}

} // namespace rosin::discovery
