#include "core/physics/bow/SlipNoise.h"

#include <algorithm>
#include <cmath>

namespace rosin::physics
{

namespace
{
constexpr double kReferenceRate = 48000.0;
}

void SlipNoise::prepare(double relativeRms, double sampleRate, std::uint64_t seed)
{
    perSampleRms_ = relativeRms > 0.0 ? relativeRms * std::sqrt(sampleRate / kReferenceRate) : 0.0;
    seed_ = seed;
    reset();
}

void SlipNoise::reset() noexcept
{
    engine_.seed(seed_);
    normal_.reset();
}

double SlipNoise::forceFactor(bool sliding) noexcept
{
    if (!sliding || perSampleRms_ <= 0.0)
        return 1.0;
    return std::max(0.0, 1.0 + perSampleRms_ * normal_(engine_));
}

} // namespace rosin::physics
