// [Smith2000]'s single-mode rig: derived constants and validation.
#include "core/physics/rig/OscillatorRigParameters.h"

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace rosin::physics
{

double OscillatorRigParameters::angularFrequency() const
{
    return 2.0 * std::numbers::pi * frequency;
}

double OscillatorRigParameters::stiffness() const
{
    const double w = angularFrequency();
    return modalMass * w * w;
}

double OscillatorRigParameters::resistance() const
{
    return modalMass * angularFrequency() / qualityFactor;
}

void OscillatorRigParameters::validate() const
{
    auto require = [](bool ok, const char* field, const char* expected, double got)
    {
        if (!ok)
            throw std::invalid_argument(std::string("oscillator rig: field \"") + field + "\": expected " +
                                        expected + " but got " + std::to_string(got));
    };
    require(std::isfinite(frequency) && frequency >= 1.0 && frequency <= 10000.0, "frequency",
            "1..10000 (Hz)", frequency);
    // Q > 1/2: the impulse-invariant mode needs an underdamped pole pair.
    require(std::isfinite(qualityFactor) && qualityFactor >= 0.6 && qualityFactor <= 1e5, "qualityFactor",
            "0.6..100000", qualityFactor);
    require(std::isfinite(modalMass) && modalMass >= 1e-5 && modalMass <= 100.0, "modalMass",
            "1e-5..100 (kg)", modalMass);
}

} // namespace rosin::physics
