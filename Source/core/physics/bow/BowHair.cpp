#include "core/physics/bow/BowHair.h"

#include "core/physics/bow/BowParameters.h"

namespace rosin::physics
{

HairTerms hairTerms(const BowParameters& bow, double sampleRate) noexcept
{
    if (!bow.compliantHair)
        return {};
    const double halfStep = 0.5 / sampleRate;
    return {1.0 / (bow.hairDamping + bow.hairStiffness * halfStep), bow.hairStiffness, halfStep};
}

} // namespace rosin::physics
