// The waveguide string against the string's own physics, not against Rosin: a free string rings at
// c / (2L) (rigid ends, stiffness off: [Notes §4.2] with B = 0) and its fundamental decays at
// sigma = pi eta(f0) f0 with eta from the loss law, [Notes] eq. (4.1).
#include <gtest/gtest.h>

#include <cmath>

#include "lab/discovery/independent/IndependentFixtures.h"
#include "lab/discovery/independent/WaveguideString.h"

namespace rosin::discovery
{
namespace ROSIN_FILE_LOCAL
{

struct Ringing
{
    std::vector<double> bridgeForce;
    double f0 = 0.0;
};

// A 1-sample force pulse at the bow point, then free vibration for `seconds`.
Ringing ring(double extraEta, double seconds, bool stiff = false)
{
    const auto s = physics::stringFromCatalogue("cello-D3");
    WaveguideSettings w;
    w.tension = s.tension;
    w.massPerLength = s.massPerLength;
    w.length = s.length;
    w.beta = 0.0899;
    w.transverseLoss = stringLossLaw(s.tension, s.massPerLength, s.bendingStiffness, s.etaF(false), s.etaB(),
                                     s.etaA(), extraEta);
    w.bendingStiffness = stiff ? s.bendingStiffness : 0.0;
    w.torsion = false;
    w.sampleRate = test::kRate;
    WaveguideString string(w);
    Ringing r;
    r.f0 = s.waveSpeed() / (2.0 * s.length);
    const auto n = static_cast<std::size_t>(seconds * test::kRate);
    for (std::size_t k = 0; k < n; ++k)
    {
        string.beginStep(k);
        string.finishStep(k, k == 0 ? 1.0 : 0.0);
        r.bridgeForce.push_back(string.bridgeForce());
    }
    return r;
}

double decayRate(const Ringing& r, double f)
{
    const auto i = [](double t) { return static_cast<std::size_t>(t * test::kRate); };
    const double a1 = test::amplitudeAt(r.bridgeForce, i(0.1), i(0.6), f, test::kRate);
    const double a2 = test::amplitudeAt(r.bridgeForce, i(1.6), i(2.1), f, test::kRate);
    return std::log(a1 / a2) / 1.5;
}

TEST(WaveguideString, FreeStringRingsAtHalfTheWaveSpeedOverLength)
{
    const Ringing r = ring(0.0, 2.2);
    const double f =
        test::peakFrequency(r.bridgeForce, 0, r.bridgeForce.size(), 0.97 * r.f0, 1.03 * r.f0, test::kRate);
    const double cents = 1200.0 * std::log2(f / r.f0);
    RecordProperty("cents", std::to_string(cents));
    std::printf("free decay: f = %.4f Hz, c/2L = %.4f Hz, %.3f cents\n", f, r.f0, cents);
    EXPECT_LT(std::abs(cents), 2.0);
}

TEST(WaveguideString, FundamentalDecaysAtTheLossLawRate)
{
    const Ringing r = ring(0.0, 2.2);
    const auto s = physics::stringFromCatalogue("cello-D3");
    const double expected = std::numbers::pi * test::referenceLoss(s, r.f0) * r.f0; // 1/s
    const double measured = decayRate(r, r.f0);
    std::printf("free decay: sigma = %.4f 1/s, loss law %.4f 1/s (Q %.0f)\n", measured, expected,
                std::numbers::pi * r.f0 / expected);
    EXPECT_NEAR(measured / expected, 1.0, 0.08);
}

TEST(WaveguideString, ConstantExtraLossAddsItsDecayRate)
{
    const double extra = 8e-4; // the extra-string-damping effect's constant 1/Q form
    const Ringing r = ring(extra, 2.2);
    const auto s = physics::stringFromCatalogue("cello-D3");
    const double expected = std::numbers::pi * (test::referenceLoss(s, r.f0) + extra) * r.f0;
    const double measured = decayRate(r, r.f0);
    std::printf("extra damping: sigma = %.4f 1/s, expected %.4f 1/s\n", measured, expected);
    EXPECT_NEAR(measured / expected, 1.0, 0.08);
}

TEST(WaveguideString, StiffStringPartialsAreSharpByTheInharmonicity)
{
    // [Notes] eq. (4.2): f_n = n f0 sqrt(1 + B n^2), B = pi^2 EI / (P L^2) = 5.6e-5 for the cello D. Up
    // through harmonic 60 (9.7 kHz, 50 cents sharp of harmonic): the band of analysis::HarmonicTilt, where
    // the corner's rounding by dispersion shows.
    const Ringing r = ring(0.0, 1.2, true);
    const auto s = physics::stringFromCatalogue("cello-D3");
    const double B =
        std::numbers::pi * std::numbers::pi * s.bendingStiffness / (s.tension * s.length * s.length);
    for (int n : {5, 12, 20, 35, 45, 60})
    {
        const double expected = n * r.f0 * std::sqrt(1.0 + B * n * n);
        const double f = test::peakFrequency(r.bridgeForce, 0, r.bridgeForce.size(), expected * 0.995,
                                             expected * 1.005, test::kRate);
        const double cents = 1200.0 * std::log2(f / expected);
        std::printf("stiff string: partial %d at %.3f Hz, eq. 4.2 %.3f Hz (%.2f cents; harmonic %.1f cents "
                    "below)\n",
                    n, f, expected, cents, 1200.0 * std::log2(expected / (n * r.f0)));
        EXPECT_LT(std::abs(cents), 3.0);
    }
}

TEST(WaveguideString, OnePoleMatchesTheLossTargetAtBothFitPoints)
{
    const auto s = physics::stringFromCatalogue("cello-D3");
    const LossLaw eta =
        stringLossLaw(s.tension, s.massPerLength, s.bendingStiffness, s.etaF(false), s.etaB(), s.etaA());
    const double tau = 2.0 * s.length / s.waveSpeed();
    const double f0 = 1.0 / tau;
    const OnePoleLoss loss(eta, tau, f0, 6.0 * f0, test::kRate);
    for (double f : {f0, 6.0 * f0})
        EXPECT_NEAR(loss.magnitude(f), std::exp(-std::numbers::pi * eta(f) * f * tau), 1e-9);
    // A string under a static load loses nothing: unity at DC (else a held string creeps under the bow).
    EXPECT_NEAR(loss.magnitude(0.0), 1.0, 1e-12);
}

} // namespace ROSIN_FILE_LOCAL
} // namespace rosin::discovery
