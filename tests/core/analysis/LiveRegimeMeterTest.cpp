// The live regime meter (the plugin's readout) on canonical bow-point motions, and on a simulated string
// against the offline classifier: the same labels from the same physics.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <memory>

#include "core/analysis/LiveRegimeMeter.h"
#include "core/analysis/RegimeClassifier.h"
#include "core/physics/friction/CurveFrictionLaw.h"
#include "support/Runs.h"

using namespace rosin;
using namespace rosin::analysis;

namespace ROSIN_FILE_LOCAL
{
constexpr double kFs = 48000.0, kF0 = 146.83, kVb = 0.1, kBeta = 0.1;
const double kPeriod = kFs / kF0;

// Feeds 0.2 s in which sample k slips (flying back at -v_b (1 - beta) / beta) when slipAt(k) is true.
Regime meter(const std::function<bool(long)>& slipAt, double bowForce = 0.5, double bowVelocity = kVb)
{
    LiveRegimeMeter m;
    m.prepare(kFs);
    m.setNominalFrequency(kF0);
    for (long k = 0; k < static_cast<long>(0.2 * kFs); ++k)
    {
        physics::VoiceSample s;
        s.bowVelocity = bowVelocity;
        s.sticking = !slipAt(k);
        s.bowPointVelocity = s.sticking ? bowVelocity : -bowVelocity * (1.0 - kBeta) / kBeta;
        s.frictionForce = 0.3 * bowForce;
        m.push(s, bowForce);
    }
    return m.regime();
}

bool slipsWithin(long k, double cycle, double share, double offset = 0.0)
{
    return std::fmod(static_cast<double>(k) + offset, cycle) < share * cycle;
}

TEST(LiveRegimeMeter, CanonicalMotionsGetTheOfflineLabels)
{
    EXPECT_EQ(meter([](long k) { return slipsWithin(k, kPeriod, kBeta); }), Regime::Helmholtz);
    EXPECT_EQ(meter([](long k) { return slipsWithin(k, kPeriod / 2.0, 2.0 * kBeta); }),
              Regime::DoubleSlipping);
    EXPECT_EQ(meter([](long k) { return slipsWithin(k, kPeriod / 3.0, 3.0 * kBeta); }),
              Regime::MultipleSlipping);
    EXPECT_EQ(meter([](long k) { return slipsWithin(k, 2.0 * kPeriod, 0.5 * kBeta); }),
              Regime::AnomalousLowFrequency);
    // Irregular: slips at intervals drawn between 0.3 P and 1.7 P.
    std::vector<bool> irregular(static_cast<std::size_t>(0.2 * kFs), false);
    unsigned state = 12345u;
    for (double t = 0.0; t < static_cast<double>(irregular.size());)
    {
        for (long j = 0; j < 20 && t + j < static_cast<double>(irregular.size()); ++j)
            irregular[static_cast<std::size_t>(t) + static_cast<std::size_t>(j)] = true;
        state = state * 1664525u + 1013904223u;
        t += kPeriod * (0.3 + 1.4 * static_cast<double>(state >> 8) / static_cast<double>(1u << 24));
    }
    EXPECT_EQ(meter([&](long k) { return static_cast<bool>(irregular[static_cast<std::size_t>(k)]); }),
              Regime::Raucous);
    EXPECT_EQ(meter([](long) { return true; }), Regime::ConstantSlipping);
    EXPECT_EQ(meter([](long) { return false; }), Regime::NoSlip);
}

TEST(LiveRegimeMeter, NoBowIsNotBowing)
{
    LiveRegimeMeter m;
    m.prepare(kFs);
    m.setNominalFrequency(kF0);
    for (int k = 0; k < 8000; ++k)
        m.push(physics::VoiceSample{}, 0.0);
    EXPECT_FALSE(m.bowing());
    EXPECT_EQ(m.regime(), Regime::NoSlip);
}

TEST(LiveRegimeMeter, AgreesWithTheOfflineClassifierOnASimulatedString)
{
    physics::VoiceConfig cfg;
    cfg.string = physics::stringFromCatalogue("cello-D3");
    cfg.body = physics::celloBody();
    auto law = std::make_unique<physics::ClassicalFrictionLaw>(physics::ClassicalCurve{}, "classical");
    const double N = 0.3;
    const auto trace = rosin::test::bowSteady(cfg, std::move(law), kFs, N, 0.05, 0.1, 1.0);
    LiveRegimeMeter m;
    m.prepare(kFs);
    m.setNominalFrequency(cfg.string.fundamental());
    for (const auto& s : trace.samples)
        m.push(s, N);
    const double P = kFs / cfg.string.fundamental();
    const auto offline = classifyFromVoice(trace.samples, P, AnalysisWindow{trace.samples.size() - 9600, 0});
    EXPECT_EQ(offline.regime, Regime::Helmholtz);
    EXPECT_EQ(m.regime(), offline.regime);
    EXPECT_NEAR(m.flybacksPerPeriod(), 1.0, 0.15);
}

} // namespace ROSIN_FILE_LOCAL
