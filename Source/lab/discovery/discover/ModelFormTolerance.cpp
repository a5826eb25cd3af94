#include "lab/discovery/discover/ModelFormTolerance.h"

#include <cmath>

namespace rosin::discovery
{

const std::array<double, kFeatureCount>& modelFormTolerance() noexcept
{
    static const std::array<double, kFeatureCount> tau = []
    {
        std::array<double, kFeatureCount> t{};
        // The largest over the family's forty tuning controls, rounded up to two figures
        // (ModelFormTolerance.h).
        t[kStaticFriction] = 0.0099; // mu: 2 of 20 Guettler controls beyond their scatter
        t[kJump] = 0.021;            // mu: 4 of 20
        t[kCreep] = 0.0088;          // 2 of 20
        t[kFirstSlipTime] = 2.2e-3;  // s: 5 of 20
        t[kTransientPeriods] = 3.1;  // periods: 7 of 20 (next largest 1.8)
        t[kPitchCents] = 6.3;        // cents: 37 of 40
        t[kHarmonicTilt] = 2.4;      // dB: 40 of 40
        t[kSteadyLevel] = 1.4;       // dB: 18 of 20 Schelleng controls
        return t;
    }();
    return tau;
}

FeatureScatter withModelFormTolerance(FeatureScatter scatter)
{
    for (std::size_t f = 0; f < kFeatureCount; ++f)
        if (!isCategorical(f))
            scatter.sigma[f] = std::hypot(scatter.sigma[f], modelFormTolerance()[f]);
    return scatter;
}

} // namespace rosin::discovery
