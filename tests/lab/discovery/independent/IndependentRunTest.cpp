// The generator's contract (that of runSynthData) and its measurement chain: determinism for a seed whatever
// the threads, the pilot's noise floor, trial order, the plan's faults, and the anti-aliasing filter's and
// high-pass's responses at their corners (analytic: -3.01 dB).
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <numbers>

#include "lab/discovery/independent/IndependentRun.h"

namespace rosin::discovery
{
namespace ROSIN_FILE_LOCAL
{

SynthPlan smallPlan(std::uint64_t seed, const std::vector<std::string>& effects = {})
{
    SynthSettings s;
    s.scan.kind = scan::ScanKind::Guettler;
    s.scan.sampleRate = 44100.0;
    s.scan.trialSeconds = 0.12;
    s.scan.betas = {0.0899, 0.1428};
    s.scan.forces = {0.8, 1.6};
    s.scan.second = {1.0, 3.0, 5.0, 8.0, 12.0}; // 20 trials: one of them fails (TrialFault.h)
    s.seed = seed;
    s.allChannels = true;
    for (const auto& name : effects)
        s.effects.push_back({findEffect(name), {}});
    return planSynthData(s);
}

std::vector<std::vector<std::vector<double>>> run(SynthPlan& plan, unsigned threads)
{
    std::vector<std::vector<std::vector<double>>> out;
    runIndependentSynthData(plan, threads,
                            [&](std::size_t i, const std::vector<std::vector<double>>& channels)
                            {
                                EXPECT_EQ(i, out.size()); // trial order
                                EXPECT_TRUE(plan.dataset.sensor.noiseRms.has_value());
                                out.push_back(channels);
                            });
    return out;
}

TEST(IndependentRun, SameSeedSameDataWhateverTheThreads)
{
    SynthPlan a = smallPlan(7, {"junction-growth"}), b = smallPlan(7, {"junction-growth"}), c = smallPlan(8);
    const auto one = run(a, 1), two = run(b, 2), other = run(c, 1);
    ASSERT_EQ(one.size(), a.dataset.trials.size());
    EXPECT_EQ(one, two);
    EXPECT_EQ(*a.dataset.sensor.noiseRms, *b.dataset.sensor.noiseRms);
    EXPECT_NE(one[3], other[3]);
    const auto samples = static_cast<std::size_t>(std::llround(0.12 * 44100.0));
    std::size_t shortOnes = 0;
    for (std::size_t i = 0; i < one.size(); ++i)
    {
        EXPECT_EQ(one[i].size(), a.dataset.channels.size());
        shortOnes += one[i][0].size() < samples ? 1 : 0;
        if (a.dataset.trials[i].valid)
        {
            EXPECT_EQ(one[i][0].size(), samples);
        }
    }
    EXPECT_LE(shortOnes, 1u);
}

TEST(IndependentRun, TruthRecordsTheDrawsWithinTheirRanges)
{
    const SynthPlan plan = smallPlan(11, {"hertz-contact"});
    const IndependentTruth t = independentTruth(plan);
    EXPECT_NEAR(t.nuisance.contactRadius, 1.0, 0.15);
    EXPECT_NEAR(t.nuisance.tension, 1.0, 0.02);
    EXPECT_NEAR(t.nuisance.massPerLength, 1.0, 0.01);
    EXPECT_GE(t.chain.cornerHz, 8000.0);
    EXPECT_LE(t.chain.cornerHz, 16000.0);
    for (double g : t.chain.gains)
        EXPECT_NEAR(g, 1.0, 0.03);
    for (double d : t.startDelays)
        EXPECT_LE(d, 1e-3);
    EXPECT_TRUE(t.effects.hertz);
    EXPECT_GE(t.effects.hertzExponent, 0.62);
    EXPECT_LE(t.effects.hertzExponent, 0.72);
    const auto j = t.toJson();
    EXPECT_EQ(j["generator"], kIndependentGenerator);
    EXPECT_TRUE(j["effects"].contains("hertz-contact.exponent"));
    EXPECT_EQ(t.startDelays.size(), plan.dataset.trials.size());
}

using Filter = std::function<void(std::vector<double>&, double, double)>;

double gainAt(const Filter& filter, double corner, double f, double rate)
{
    std::vector<double> x(static_cast<std::size_t>(rate * 20.0 / std::min(f, 50.0)) + 40000);
    for (std::size_t i = 0; i < x.size(); ++i)
        x[i] = std::sin(2.0 * std::numbers::pi * f * static_cast<double>(i) / rate);
    filter(x, corner, rate);
    double peak = 0.0;
    for (std::size_t i = x.size() / 2; i < x.size(); ++i)
        peak = std::max(peak, std::abs(x[i]));
    return 20.0 * std::log10(peak);
}

Filter butterworth(int order)
{
    return [order](std::vector<double>& x, double corner, double rate)
    { antiAliasLowPass(x, corner, rate, order); };
}

TEST(IndependentRun, ChainFiltersHaveTheirAnalyticCorners)
{
    const double rate = 88200.0;
    EXPECT_NEAR(gainAt(butterworth(4), 12000.0, 12000.0, rate), -3.01, 0.05);
    // 4th order: -24 dB per octave well above the corner (bilinear: a little more).
    EXPECT_LT(gainAt(butterworth(4), 8000.0, 32000.0, rate), -48.0);
    EXPECT_NEAR(gainAt(butterworth(4), 12000.0, 1000.0, rate), 0.0, 0.01);
    EXPECT_NEAR(gainAt(firstOrderHighPassBilinear, 0.5, 0.5, 4410.0), -3.01, 0.05);
}

// The family's other orders: -3 dB at the corner, and two octaves above it at least 6 dB per octave and
// order (|H|^2 = 1 / (1 + (f / fc)^(2 N)) of the analog prototype: -24.1 dB for N = 2, -72.2 for N = 6).
TEST(IndependentRun, ButterworthOfEveryFamilyOrderHasItsAnalyticCornerAndSlope)
{
    const double rate = 132300.0;
    for (int order : {2, 6})
    {
        SCOPED_TRACE(order);
        EXPECT_NEAR(gainAt(butterworth(order), 10000.0, 10000.0, rate), -3.01, 0.05);
        const double analog = -10.0 * std::log10(1.0 + std::pow(4.0, 2.0 * order));
        EXPECT_LT(gainAt(butterworth(order), 8000.0, 32000.0, rate), analog + 0.5);
        EXPECT_NEAR(gainAt(butterworth(order), 10000.0, 500.0, rate), 0.0, 0.01);
    }
}

} // namespace ROSIN_FILE_LOCAL
} // namespace rosin::discovery
