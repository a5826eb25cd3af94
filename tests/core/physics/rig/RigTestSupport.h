#pragma once
// What the rig tests share: [Smith2000]'s run (6.3 N, 0.042 m/s, from rest) with any law, and per-cycle
// views.
#include <algorithm>
#include <memory>
#include <string>
#include <vector>

#include "core/physics/laws/FrictionLawFactory.h"
#include "core/physics/rig/CantileverContact.h"
#include "core/physics/rig/RigCalibration.h"

namespace rosin::test::rig
{

constexpr double kSampleRate = 48000.0;
constexpr double kSeconds = 1.0;
/// The second half of the run: stick-slip has settled for every law (as in calibrateModalMass).
constexpr double kSettledFrom = 0.5;

inline physics::RigRun seedRun(physics::FrictionModel model,
                               const physics::ContactParameters& contact = physics::cantileverContact(),
                               double seconds = kSeconds)
{
    return physics::runRig(physics::OscillatorRigParameters{}, physics::makeFrictionLaw(model, contact),
                           kSampleRate, physics::CantileverLoad::normalForce,
                           physics::CantileverLoad::rodSpeed, seconds);
}

inline std::size_t sampleAt(const physics::RigRun& run, double seconds)
{
    return static_cast<std::size_t>(seconds * run.sampleRate + 0.5);
}

/// Signed area of the (sliding speed, friction coefficient) loop from `fromSeconds` on, shoelace formula:
/// > 0 anticlockwise with dv = v - v_rod on the horizontal axis (the sense of [Smith2000] Fig. 2c: sticking
/// at the right edge dv = 0, the coefficient falling as the slip speeds up, recovering lower on the way
/// back).
inline double loopSignedArea(const physics::RigRun& run, double fromSeconds)
{
    double twice = 0.0;
    for (std::size_t k = sampleAt(run, fromSeconds); k + 1 < run.samples.size(); ++k)
    {
        const auto& a = run.samples[k];
        const auto& b = run.samples[k + 1];
        twice += a.slidingSpeed * b.frictionCoefficient() - b.slidingSpeed * a.frictionCoefficient();
    }
    return 0.5 * twice;
}

/// Lowest and highest contact temperature (K above ambient) from `fromSeconds` on.
struct TemperatureRange
{
    double low = 1e300, high = -1e300;
};
inline TemperatureRange temperatureRange(const physics::RigRun& run, double fromSeconds)
{
    TemperatureRange r;
    for (std::size_t k = sampleAt(run, fromSeconds); k < run.samples.size(); ++k)
    {
        r.low = std::min(r.low, run.samples[k].contactTemperature);
        r.high = std::max(r.high, run.samples[k].contactTemperature);
    }
    return r;
}

/// The largest v - v_rod of the run: > 0 is forward slipping, the oscillator overtaking the rod.
inline double largestForwardSlip(const physics::RigRun& run)
{
    double dv = 0.0;
    for (const physics::RigSample& s : run.samples)
        dv = std::max(dv, s.slidingSpeed);
    return dv;
}

} // namespace rosin::test::rig
