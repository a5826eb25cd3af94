#include "core/physics/lanes/LaneFriction.h"

#include <stdexcept>

#include "core/physics/lanes/PlasticLanes.h"

namespace rosin::physics
{

ScalarLaneFriction::ScalarLaneFriction(std::vector<std::unique_ptr<FrictionLaw>> laws)
    : laws_(std::move(laws))
{
    if (laws_.size() != static_cast<std::size_t>(kLanes))
        throw std::invalid_argument("ScalarLaneFriction: one friction law per lane is required");
    for (const auto& law : laws_)
        if (!law)
            throw std::invalid_argument("ScalarLaneFriction: a lane has no friction law");
}

void ScalarLaneFriction::reset() noexcept
{
    for (auto& law : laws_)
        law->reset();
}

void ScalarLaneFriction::solve(const LaneJunctionInput& in, LaneJunctionSolution& out) noexcept
{
    for (int l = 0; l < kLanes; ++l)
        out[l] = laws_[l]->solve({in.dvHistory[l], in.loadSlope, in.bowForce[l]});
}

void StuckLanes::solve(const LaneJunctionInput& in, LaneJunctionSolution& out) noexcept
{
    for (int l = 0; l < kLanes; ++l)
        out[l] = {0.0, -in.loadSlope * in.dvHistory[l], true};
}

std::unique_ptr<LaneFriction> makeLaneFriction(const std::function<std::unique_ptr<FrictionLaw>()>& makeLaw,
                                               double sampleRate)
{
    std::unique_ptr<FrictionLaw> first = makeLaw();
    if (!first)
        throw std::invalid_argument("makeLaneFriction: no friction law");
    first->prepare(sampleRate);
    if (auto* plastic = dynamic_cast<PlasticThermalLaw*>(first.get()))
    {
        first.release();
        return std::make_unique<PlasticLanes>(std::unique_ptr<PlasticThermalLaw>(plastic));
    }
    std::vector<std::unique_ptr<FrictionLaw>> laws;
    laws.push_back(std::move(first));
    while (laws.size() < static_cast<std::size_t>(kLanes))
    {
        laws.push_back(makeLaw());
        laws.back()->prepare(sampleRate);
    }
    return std::make_unique<ScalarLaneFriction>(std::move(laws));
}

} // namespace rosin::physics
