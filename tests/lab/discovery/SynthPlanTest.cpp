// What rosin synth-data decides before simulating: nominal settings on the grid for dataset.json, jittered
// ones for the simulation, a few failed trials, the hidden effects' values, all from the seed; and a
// description the reader accepts that names nothing of the truth.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <regex>

#include "lab/discovery/DatasetReader.h"
#include "lab/discovery/DatasetWriter.h"
#include "lab/discovery/TrialSimulator.h"
#include "lab/discovery/synth/SynthPlan.h"
#include "lab/discovery/synth/SynthRun.h"
#include "lab/scan/Axis.h"

using namespace rosin::discovery;

namespace ROSIN_FILE_LOCAL
{
SynthSettings guettler(std::size_t forces, std::size_t accelerations, std::uint64_t seed = 1)
{
    SynthSettings s;
    s.scan = rosin::scan::defaultSpec(rosin::scan::ScanKind::Guettler);
    s.scan.betas = {0.0899, 0.1428};
    s.scan.forces = rosin::scan::linearAxis(0.4, 3.2, forces);
    s.scan.second = rosin::scan::linearAxis(0.08, 3.2, accelerations);
    s.scan.trialSeconds = 0.4;
    s.scan.sampleRate = 44100.0;
    s.seed = seed;
    return s;
}

EffectRequest request(const std::string& name, std::vector<std::optional<double>> fixed = {})
{
    const Effect* e = findEffect(name);
    fixed.resize(e->parameters.size());
    return {e, fixed};
}

double acceleration(const Gesture& g)
{
    return std::get<ConstantAcceleration>(g).acceleration;
}

TEST(SynthPlan, NominalSettingsLieOnTheGridAndTheSimulatedOnesScatter)
{
    const SynthSettings s = guettler(4, 5);
    const SynthPlan plan = planSynthData(s);
    ASSERT_EQ(plan.dataset.trials.size(), 40u);
    ASSERT_EQ(plan.actual.size(), 40u);
    double maxForce = 0.0, maxMotion = 0.0;
    for (std::size_t i = 0; i < 40; ++i)
    {
        const Trial& t = plan.dataset.trials[i];
        const auto cell = rosin::scan::cellSettings(s.scan, i);
        EXPECT_EQ(t.beta, cell.beta);
        EXPECT_EQ(t.bowForce, cell.force);
        EXPECT_EQ(acceleration(t.gesture), cell.second);
        const TrialSettings& a = plan.actual[i];
        EXPECT_EQ(a.beta, t.beta);
        const double df = a.bowForce / t.bowForce - 1.0, da = acceleration(a.gesture) / cell.second - 1.0;
        EXPECT_LE(std::abs(df), 3 * kForceJitter + 1e-12);
        EXPECT_LE(std::abs(da), 3 * kMotionJitter + 1e-12);
        EXPECT_NE(df, 0.0);
        maxForce = std::max(maxForce, std::abs(df));
        maxMotion = std::max(maxMotion, std::abs(da));
        EXPECT_EQ(a.seconds, 0.4);
    }
    EXPECT_GT(maxForce, kForceJitter); // a real scatter, not a rounding
    EXPECT_GT(maxMotion, kMotionJitter);
}

TEST(SynthPlan, TrialIdsNameBetaForceAndMotion)
{
    const SynthPlan plan = planSynthData(guettler(4, 12));
    EXPECT_EQ(plan.dataset.trials.front().id, "b0899-f00-a00");
    EXPECT_EQ(plan.dataset.trials[3 * 12 + 10].id, "b0899-f03-a10");
    EXPECT_EQ(plan.dataset.trials.back().id, "b1428-f03-a11");
    EXPECT_EQ(plan.dataset.trials.back().file, "trials/b1428-f03-a11.wav");
    auto s = guettler(3, 3);
    s.scan.kind = rosin::scan::ScanKind::Schelleng;
    s.scan.second = {0.05};
    s.scan.betas = {0.02, 0.020001};
    const auto ids = trialIds(s.scan);
    EXPECT_EQ(ids.front(), "b020000-f00-v00"); // too close for 4 digits: 6
    EXPECT_EQ(ids.back(), "b020001-f02-v00");
    const SynthPlan steady = planSynthData(s);
    EXPECT_TRUE(std::holds_alternative<Steady>(steady.dataset.trials.front().gesture));
}

TEST(SynthPlan, AFewTrialsFailFromTwentyOn)
{
    EXPECT_EQ(failedTrialCount(19), 0u);
    EXPECT_EQ(failedTrialCount(20), 1u);
    EXPECT_EQ(failedTrialCount(200), 5u);
    const SynthPlan plan = planSynthData(guettler(10, 10)); // 200 trials
    std::size_t invalid = 0;
    for (std::size_t i = 0; i < plan.dataset.trials.size(); ++i)
    {
        EXPECT_EQ(plan.dataset.trials[i].valid, !plan.faults[i].has_value());
        invalid += plan.dataset.trials[i].valid ? 0 : 1;
    }
    EXPECT_EQ(invalid, 5u);
    EXPECT_EQ(chooseFailedTrials(200, 1), chooseFailedTrials(200, 1));
    EXPECT_NE(chooseFailedTrials(200, 1), chooseFailedTrials(200, 2));
}

TEST(SynthPlan, FaultsCutShortOrDropOut)
{
    std::vector<std::vector<double>> cut{std::vector<double>(1000, 1.0)};
    applyTrialFault({TrialFault::Kind::CutShort, 0.25, 0.0}, 1000.0, cut);
    EXPECT_EQ(cut[0].size(), 250u);
    std::vector<std::vector<double>> drop{std::vector<double>(1000, 1.0), std::vector<double>(1000, 2.0)};
    applyTrialFault({TrialFault::Kind::Dropout, 0.5, 0.01}, 1000.0, drop);
    for (const auto& c : drop)
    {
        EXPECT_EQ(c.size(), 1000u);
        EXPECT_EQ(std::count(c.begin(), c.end(), 0.0), 10);
        EXPECT_EQ(c[500], 0.0);
    }
    EXPECT_EQ(describeTrialFault({TrialFault::Kind::Dropout, 0.5, 0.01}), "dropout 0.5-0.51 s");
}

TEST(SynthPlan, HiddenValuesAreDrawnFromTheSeedUnlessGiven)
{
    for (const auto& e : effectCatalog())
    {
        const auto values = drawEffectValues(request(e.name), 5);
        ASSERT_EQ(values.size(), e.parameters.size());
        for (std::size_t i = 0; i < values.size(); ++i)
        {
            const auto& p = e.parameters[i];
            const double magnitude = p.signedDraw ? std::abs(values[i]) : values[i];
            EXPECT_GE(magnitude, p.drawMin) << p.name;
            EXPECT_LE(magnitude, p.drawMax) << p.name;
        }
        EXPECT_EQ(values, drawEffectValues(request(e.name), 5));
    }
    const auto drawn = drawEffectValues(request("junction-growth"), 5);
    const auto fixed = drawEffectValues(request("junction-growth", {0.5}), 5);
    EXPECT_EQ(fixed[0], 0.5);
    EXPECT_EQ(fixed[1], drawn[1]); // fixing one value leaves the others
    EXPECT_NE(drawEffectValues(request("junction-growth"), 6), drawn);

    auto s = guettler(2, 2);
    s.effects = {request("junction-growth", {0.25, 0.004}), request("extra-string-damping", {3.0})};
    const SynthPlan plan = planSynthData(s);
    EXPECT_EQ(plan.model.frictionEffects.junctionGrowth, 0.25);
    EXPECT_EQ(plan.model.lossScale, 3.0);
    ASSERT_EQ(plan.effects.size(), 2u);
    s.effects = {request("sticking-creep", {1e6})};
    EXPECT_THROW(planSynthData(s), std::invalid_argument);
}

TEST(SynthPlan, DescriptionIsValidAndNamesNothingHidden)
{
    auto s = guettler(3, 3);
    for (const auto& e : effectCatalog())
        s.effects.push_back(request(e.name));
    const SynthPlan plan = planSynthData(s);
    const std::string text = datasetToJson(plan.dataset).dump();
    const Dataset back = parseDatasetDescription(nlohmann::json::parse(text), "dataset.json", ".");
    EXPECT_EQ(back.trials, plan.dataset.trials);
    EXPECT_TRUE(back.rig.defaultedStringFields.empty()); // every string field recorded
    EXPECT_EQ(back.rig.ambientTemperature, kRigAmbientCelsius);
    EXPECT_EQ(back.rig.body, "cello");
    EXPECT_EQ(back.sensor.highpassHz, kSensorHighpassHz);
    std::string lower = text;
    std::transform(lower.begin(), lower.end(), lower.begin(),
                   [](unsigned char c) { return std::tolower(c); });
    for (const auto& e : effectCatalog())
    {
        EXPECT_EQ(lower.find(e.name), std::string::npos) << e.name;
        for (const auto& p : e.parameters)
        {
            std::string name = p.name;
            std::transform(name.begin(), name.end(), name.begin(),
                           [](unsigned char c) { return std::tolower(c); });
            EXPECT_EQ(lower.find(name), std::string::npos) << p.name;
        }
    }
    EXPECT_EQ(lower.find("seed"), std::string::npos);
}

TEST(SynthPlan, PilotAndNoiseFloor)
{
    EXPECT_EQ(pilotTrials(3), (std::vector<std::size_t>{0, 1, 2}));
    EXPECT_EQ(pilotTrials(100), (std::vector<std::size_t>{6, 18, 31, 43, 56, 68, 81, 93}));
    EXPECT_DOUBLE_EQ(noiseFromPeaks({1.0, 2.0, 4.0}), 0.006);       // 0.3 % of the median
    EXPECT_DOUBLE_EQ(noiseFromPeaks({1.0, 2.2, 2.4, 9.0}), 0.0069); // 2 significant digits
}

TEST(SynthPlan, SimulatorFollowsTheGesture)
{
    TrialSimulator sim(SimulationModel{}, 44100.0);
    TrialSettings t;
    t.gesture = ConstantAcceleration{2.0};
    t.seconds = 0.05;
    const auto& samples = sim.run(t);
    ASSERT_EQ(samples.size(), 2205u);
    EXPECT_NEAR(samples.back().bowVelocity, 2.0 * 2204 / 44100.0, 1e-12);
    const auto first = channelSamples(samples, "bridgeForce");
    t.gesture = Steady{0.05};
    EXPECT_EQ(sim.run(t).front().bowVelocity, 0.05); // steady: the speed from t = 0
    t.gesture = ConstantAcceleration{2.0};
    EXPECT_EQ(channelSamples(sim.run(t), "bridgeForce"), first); // reset between trials
    EXPECT_THROW(channelSamples(samples, "contactTemperature"), std::invalid_argument);
}

} // namespace ROSIN_FILE_LOCAL
