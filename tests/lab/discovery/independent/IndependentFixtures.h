#pragma once
// Shared set-up of the independent generator's tests: the nominal Galluzzo rig (cello D3, [Galluzzo2017]
// Tables 1 and 2) without nuisance, and small measurements on traces (slip onsets, the fundamental's
// amplitude).
#include <cmath>
#include <complex>
#include <numbers>
#include <vector>

#include "core/physics/thermal/ContactParameters.h"
#include "lab/discovery/independent/IndependentTrial.h"

namespace rosin::discovery::test
{

inline constexpr double kRate = 88200.0; // 2 x 44.1 kHz, the generator's internal rate

inline IndependentRig nominalRig(const OwnEffects& effects = {}, bool celloBody = true)
{
    IndependentRig rig;
    rig.string = physics::stringFromCatalogue("cello-D3");
    rig.body = celloBody ? physics::bodyByName("cello") : physics::rigidBody();
    const auto contact = physics::galluzzoContact();
    rig.contactRadius = contact.rig.radius;
    rig.referenceForce = contact.rig.referenceForce;
    rig.layerThickness = contact.rig.layerThickness;
    rig.calibration = {contact.calibration.radius, contact.calibration.referenceForce,
                       contact.calibration.layerThickness};
    rig.materials = {contact.materials.layer, contact.materials.stationary, contact.materials.moving};
    rig.effects = effects;
    return rig;
}

inline TrialSettings guettler(double beta, double force, double acceleration, double seconds)
{
    return {beta, force, ConstantAcceleration{acceleration}, seconds};
}

/// Index of the first stick -> slip transition, or the trace's length.
inline std::size_t firstSlip(const TrialTrace& t)
{
    for (std::size_t i = 1; i < t.sticking.size(); ++i)
        if (t.sticking[i - 1] && !t.sticking[i])
            return i;
    return t.sticking.size();
}

/// Largest |friction| up to sample `end`.
inline double peakFriction(const TrialTrace& t, std::size_t end)
{
    double peak = 0.0;
    for (std::size_t i = 0; i < end && i < t.frictionForce.size(); ++i)
        peak = std::max(peak, std::abs(t.frictionForce[i]));
    return peak;
}

/// Amplitude of the component at f (Hz) of x[begin, end), Hann-windowed.
inline double amplitudeAt(const std::vector<double>& x, std::size_t begin, std::size_t end, double f,
                          double rate)
{
    std::complex<double> sum = 0.0;
    double weight = 0.0;
    const double n = static_cast<double>(end - begin);
    for (std::size_t i = begin; i < end; ++i)
    {
        const double k = static_cast<double>(i - begin);
        const double w = 0.5 - 0.5 * std::cos(2.0 * std::numbers::pi * k / n);
        sum += w * x[i] * std::polar(1.0, -2.0 * std::numbers::pi * f * static_cast<double>(i) / rate);
        weight += w;
    }
    return 2.0 * std::abs(sum) / weight;
}

/// The frequency of the largest Hann-windowed component of x[begin, end) in [lo, hi] (golden section).
inline double peakFrequency(const std::vector<double>& x, std::size_t begin, std::size_t end, double lo,
                            double hi, double rate)
{
    const double g = (std::sqrt(5.0) - 1.0) / 2.0;
    double a = lo, b = hi;
    for (int i = 0; i < 60; ++i)
    {
        const double c = b - g * (b - a), d = a + g * (b - a);
        if (amplitudeAt(x, begin, end, c, rate) > amplitudeAt(x, begin, end, d, rate))
            b = d;
        else
            a = c;
    }
    return 0.5 * (a + b);
}

/// Loss factor of [Notes] eq. (4.1) at a harmonic frequency (the test's own evaluation).
inline double referenceLoss(const physics::StringParameters& s, double f)
{
    const double w = 2.0 * std::numbers::pi * f;
    const double k = w / s.waveSpeed(); // stiffness changes k by < 0.01 % at f0
    const double bend = s.bendingStiffness * k * k;
    return (s.tension * (s.etaF(false) + s.etaA() / w) + bend * s.etaB()) / (s.tension + bend);
}

} // namespace rosin::discovery::test
