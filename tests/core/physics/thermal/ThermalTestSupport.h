#pragma once
// What the heat-balance tests share: [Woodhouse-thermal]'s steady-sliding friction curve, and [Notes §2.6b]'s
// prescribed Helmholtz sliding through a HeatBalance.
#include <algorithm>
#include <cmath>

#include "core/physics/thermal/ContactParameters.h"
#include "core/physics/thermal/HeatBalance.h"

namespace rosin::test::thermal
{

/// [Woodhouse-thermal] eq. 11: mu_steady(v) = 0.2 (v + 0.011)^-0.4.
inline double muSteady(double v)
{
    return 0.2 * std::pow(v + 0.011, -0.4);
}

struct HelmholtzTemperatures
{
    double mean = 0.0;                 ///< K, over the last 10 periods
    double low = 1e300, high = -1e300; ///< K, over the last period
    bool finite = true;
    double swing() const { return high - low; }
};

/// [Notes §2.6b] / helm_demo.py: prescribed Helmholtz sliding on the cello D string, F = 1 N, v_b = 0.1 m/s,
/// beta = 0.1 (slip at v_b/beta = 1 m/s for a fraction beta of each period), mu = 0.45, for 60 periods.
inline HelmholtzTemperatures helmholtzSliding(const physics::ContactParameters& contact, double sampleRate)
{
    const double F = 1.0, vb = 0.1, beta = 0.1, mu = 0.45, f0 = 146.8;
    physics::HeatBalance heat;
    heat.prepare(contact, sampleRate);
    const double dt = 1.0 / sampleRate;
    const long n = static_cast<long>(60 * sampleRate / f0);
    const long lastPeriods = static_cast<long>(10.0 * sampleRate / f0);
    const long onePeriod = static_cast<long>(sampleRate / f0);
    HelmholtzTemperatures r;
    double sum = 0.0;
    for (long k = 0; k < n; ++k)
    {
        const double v = std::fmod(k * dt * f0, 1.0) < beta ? vb / beta : 0.0;
        heat.commit(mu * F * v, v, F);
        const double T = heat.temperature();
        r.finite = r.finite && std::isfinite(T);
        if (k >= n - lastPeriods)
            sum += T;
        if (k >= n - onePeriod)
            r.low = std::min(r.low, T), r.high = std::max(r.high, T);
    }
    r.mean = sum / lastPeriods;
    return r;
}

} // namespace rosin::test::thermal
