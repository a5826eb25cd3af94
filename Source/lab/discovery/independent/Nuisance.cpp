#include "lab/discovery/independent/Nuisance.h"

#include "lab/discovery/independent/IndependentStreams.h"

namespace rosin::discovery
{

Nuisance drawNuisance(std::uint64_t seed)
{
    using namespace nuisance_tolerance;
    SeededRandom r(seed, independent_streams::kNuisance);
    auto around = [&r](double tolerance) { return r.uniform(1.0 - tolerance, 1.0 + tolerance); };
    Nuisance n;
    n.contactRadius = around(kContactRadius);
    n.rosinConductivity = around(kRosin);
    n.rosinHeatCapacity = around(kRosin);
    n.lossF = around(kLoss);
    n.lossB = around(kLoss);
    n.lossA = around(kLoss);
    n.tension = around(kTension);
    n.massPerLength = around(kMass);
    return n;
}

physics::StringParameters Nuisance::apply(physics::StringParameters s) const
{
    s.tension *= tension;
    s.massPerLength *= massPerLength;
    s.lossF *= lossF;
    s.stoppedLossF *= lossF;
    s.lossB *= lossB;
    s.lossA *= lossA;
    return s;
}

std::vector<std::pair<std::string, double>> Nuisance::values() const
{
    return {{"contactRadius", contactRadius},
            {"rosinConductivity", rosinConductivity},
            {"rosinHeatCapacity", rosinHeatCapacity},
            {"lossF", lossF},
            {"lossB", lossB},
            {"lossA", lossA},
            {"tension", tension},
            {"massPerLength", massPerLength}};
}

} // namespace rosin::discovery
