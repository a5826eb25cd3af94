// The effect catalog of the discrepancy workflow: its names, parameters and ranges, and that applying each
// effect changes the model as EffectCatalog.h documents, checked on the voice and friction law the model
// builds (what a simulation actually runs), not only on the model's fields.
#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <tuple>

#include "core/config/VoiceSetup.h"
#include "core/physics/voice/BowedStringVoice.h"
#include "lab/discovery/EffectCatalog.h"
#include "lab/discovery/SimulationModel.h"

using namespace rosin::discovery;

namespace ROSIN_FILE_LOCAL
{
constexpr double kFs = 44100.0;

SimulationModel withEffect(const std::string& name, const std::vector<double>& values)
{
    SimulationModel model;
    const Effect* effect = findEffect(name);
    EXPECT_NE(effect, nullptr) << name;
    applyEffect(*effect, values, model);
    return model;
}

TEST(EffectCatalog, NamesTheSevenEffectsInTheirOrder)
{
    EXPECT_EQ(effectNames(), (std::vector<std::string>{"junction-growth", "breakaway-jump", "hertz-contact",
                                                       "sticking-creep", "extra-string-damping",
                                                       "ambient-temperature", "friction-law"}));
    for (const auto& e : effectCatalog())
    {
        EXPECT_EQ(findEffect(e.name), &e);
        EXPECT_EQ(&effectCatalog()[effectIndex(e)], &e);
        EXPECT_FALSE(e.summary.empty()) << e.name;
        EXPECT_FALSE(e.source.empty()) << e.name;
    }
    EXPECT_EQ(findEffect("none"), nullptr);
    EXPECT_EQ(findEffect("junction"), nullptr);
}

TEST(EffectCatalog, ParametersHaveNamesUnitsAndRanges)
{
    const std::map<std::string, std::vector<std::string>> expected{
        {"junction-growth", {"growth", "onsetTime", "ageingForm"}},
        {"breakaway-jump", {"jumpCurve", "firstSlipMargin"}},
        {"hertz-contact", {}},
        {"sticking-creep", {"creepResistance"}},
        {"extra-string-damping", {"lossScale", "lossTerms"}},
        {"ambient-temperature", {"ambientOffset"}},
        {"friction-law", {"replacementLaw"}}};
    std::set<std::string> all;
    for (const auto& e : effectCatalog())
    {
        std::vector<std::string> names;
        for (const auto& p : e.parameters)
        {
            names.push_back(p.name);
            EXPECT_TRUE(all.insert(p.name).second) << p.name << " is used twice";
            // Long enough that a search of binary trial files for it cannot hit by chance.
            EXPECT_GE(p.name.size(), 6u) << p.name;
            EXPECT_LT(p.min, p.max) << p.name;
            EXPECT_FALSE(p.meaning.empty()) << p.name;
            // Whatever synth-data draws, a fit can reach.
            const double lo = p.signedDraw ? -p.drawMax : p.drawMin;
            EXPECT_LE(p.min, lo) << p.name;
            EXPECT_LE(p.drawMax, p.max) << p.name;
            EXPECT_LE(p.drawMin, p.drawMax) << p.name;
            if (p.logarithmic)
                EXPECT_GT(p.min, 0.0) << p.name;
        }
        EXPECT_EQ(names, expected.at(e.name)) << e.name;
    }
    const auto& jump = findEffect("breakaway-jump")->parameters.front();
    EXPECT_EQ(jump.choices, (std::vector<std::string>{"rod", "bow", "none"}));
    EXPECT_EQ(jump.drawMax, 1.0); // synth-data hides [Woodhouse-thermal]'s law, rod or bow, as it always did
    EXPECT_EQ(findEffect("junction-growth")->parameters[1].unit, "s");
    EXPECT_EQ(findEffect("sticking-creep")->parameters[0].unit, "N s/m");
    EXPECT_EQ(findEffect("ambient-temperature")->parameters[0].unit, "K");
}

TEST(EffectCatalog, JunctionGrowthAgesTheVoicesStaticLimit)
{
    const SimulationModel model = withEffect("junction-growth", {0.2, 0.005, 0.0});
    EXPECT_DOUBLE_EQ(model.frictionEffects.junctionGrowth, 0.2);
    EXPECT_DOUBLE_EQ(model.frictionEffects.junctionGrowthTime, 0.005);
    auto law = frictionLaw(model);
    law->prepare(kFs);
    auto plain = frictionLaw(SimulationModel{});
    plain->prepare(kFs);
    const double fresh = law->staticCoefficient(1.0);
    EXPECT_NEAR(fresh, plain->staticCoefficient(1.0), 1e-12);
    // Held 20 ms (a sticking contact: no sliding speed, no force), the limit has grown as the law says.
    for (int k = 0; k < 882; ++k)
        ASSERT_TRUE(law->solve({0.0, 1.0, 1.0}).sticking);
    const double aged = law->staticCoefficient(1.0);
    EXPECT_GT(aged, 1.1 * fresh);
    for (int k = 0; k < 882; ++k)
        law->solve({0.0, 1.0, 1.0});
    EXPECT_GT(law->staticCoefficient(1.0), aged); // and keeps growing with hold time
}

// Each choice builds that law of the source texts on the voice; synth-data hides one of the three that are
// not the default baseline, and the law a model already has is the candidate's null.
TEST(EffectCatalog, FrictionLawPutsAnotherLawOfTheSourcesInTheBaselinesPlace)
{
    const Effect& swap = *findEffect("friction-law");
    const auto& choice = swap.parameters.front();
    EXPECT_EQ(choice.choices, (std::vector<std::string>{"plastic", "viscous", "classical", "reconstructed"}));
    EXPECT_EQ(choice.drawMin, 1.0);
    EXPECT_EQ(choice.drawMax, 3.0);
    for (std::size_t k = 0; k < choice.choices.size(); ++k)
    {
        const SimulationModel model = withEffect("friction-law", {static_cast<double>(k)});
        EXPECT_EQ(model.preset.friction, choice.choices[k]);
        EXPECT_EQ(frictionLaw(model)->name(), choice.choices[k]);
    }
    EXPECT_TRUE(isNull(swap, {0}));
    EXPECT_FALSE(isNull(swap, {1}));
    SimulationModel classical;
    classical.preset.friction = "classical";
    EXPECT_TRUE(isNull(swap, {2}, classical));
    EXPECT_FALSE(isNull(swap, {0}, classical));
}

TEST(EffectCatalog, BreakawayJumpSwitchesToTheModifiedThermalLaw)
{
    SimulationModel rod = withEffect("breakaway-jump", {0, 0.0});
    EXPECT_EQ(rod.preset.friction, "modified-rod");
    EXPECT_STREQ(frictionLaw(rod)->name(), "modified-rod");
    EXPECT_STREQ(frictionLaw(withEffect("breakaway-jump", {1, 0.0}))->name(), "modified-bow");
    EXPECT_STREQ(frictionLaw(SimulationModel{})->name(), "plastic");
}

// The family's curve-free member: the baseline's law, with a margin on its static limit until the first slip.
TEST(EffectCatalog, BreakawayWithoutACurveRaisesOnlyTheRestingLimit)
{
    EXPECT_EQ(withEffect("breakaway-jump", {2, 0.3}).preset.friction, SimulationModel{}.preset.friction);
    SimulationModel classical; // a law without a temperature, so the slip leaves the limit as it was
    classical.preset.friction = "classical";
    SimulationModel model = classical;
    applyEffect(*findEffect("breakaway-jump"), {2, 0.3}, model);
    EXPECT_EQ(model.preset.friction, "classical");
    auto law = frictionLaw(model);
    law->prepare(kFs);
    auto plain = frictionLaw(classical);
    plain->prepare(kFs);
    EXPECT_NEAR(law->staticCoefficient(1.0), 1.3 * plain->staticCoefficient(1.0), 1e-9);
    law->solve({-10.0, 1.0, 1.0}); // far beyond any limit: the first slip
    plain->solve({-10.0, 1.0, 1.0});
    EXPECT_NEAR(law->staticCoefficient(1.0), plain->staticCoefficient(1.0), 1e-9);
}

TEST(EffectCatalog, HertzContactChangesTheContactScaling)
{
    const SimulationModel model = withEffect("hertz-contact", {});
    EXPECT_EQ(rosin::config::buildVoiceSetup(model.preset).contact.rig.scaling,
              rosin::physics::ContactScaling::Hertz);
    EXPECT_EQ(rosin::config::buildVoiceSetup(SimulationModel{}.preset).contact.rig.scaling,
              rosin::physics::ContactScaling::Coulomb);
    // Below the reference force a Hertz contact is larger than a Coulomb one: mu_s rises.
    auto hertz = frictionLaw(model);
    auto coulomb = frictionLaw(SimulationModel{});
    hertz->prepare(kFs);
    coulomb->prepare(kFs);
    EXPECT_GT(hertz->staticCoefficient(0.5), coulomb->staticCoefficient(0.5));
}

TEST(EffectCatalog, StickingCreepPutsADashpotInTheStuckContact)
{
    const double eta = 60.0;
    const SimulationModel model = withEffect("sticking-creep", {eta});
    EXPECT_DOUBLE_EQ(model.frictionEffects.creepResistance, eta);
    auto law = frictionLaw(model);
    law->prepare(kFs);
    const double slope = 1.1, dvh = -0.01;
    const auto s = law->solve({dvh, slope, 1.0});
    // The rigid-sticking force times eta / (2Z + eta), the string creeping behind the bow.
    EXPECT_NEAR(s.frictionForce, slope * -dvh * eta / (slope + eta), 1e-12);
    EXPECT_LT(s.dv, 0.0);
}

TEST(EffectCatalog, ExtraStringDampingScalesTheLoss)
{
    SimulationModel model = withEffect("extra-string-damping", {3.0, 0.0});
    EXPECT_DOUBLE_EQ(voiceConfig(model).lossScale, 3.0);
    EXPECT_DOUBLE_EQ(voiceConfig(SimulationModel{}).lossScale, 1.0);
    applyEffect(*findEffect("extra-string-damping"), {2.0, 0.0}, model);
    EXPECT_DOUBLE_EQ(voiceConfig(model).lossScale, 6.0); // on top of what the model had
    // One term only: the internal friction (every partial alike) or the bending term (the high ones).
    const auto nominal = SimulationModel{}.preset.string;
    const auto internal = withEffect("extra-string-damping", {3.0, 1.0}).preset.string;
    const auto bending = withEffect("extra-string-damping", {3.0, 2.0}).preset.string;
    EXPECT_DOUBLE_EQ(internal.lossF, 3.0 * nominal.lossF);
    EXPECT_DOUBLE_EQ(internal.lossB, nominal.lossB);
    EXPECT_DOUBLE_EQ(bending.lossB, 3.0 * nominal.lossB);
    EXPECT_DOUBLE_EQ(bending.lossF, nominal.lossF);
    const double L = nominal.length;
    EXPECT_LT(bending.lossFactor(2, L, false) / nominal.lossFactor(2, L, false),
              bending.lossFactor(40, L, false) / nominal.lossFactor(40, L, false));
}

TEST(EffectCatalog, AmbientTemperatureOffsetsTheRosin)
{
    const SimulationModel model = withEffect("ambient-temperature", {-12.0});
    EXPECT_DOUBLE_EQ(model.preset.ambientOffset, -12.0);
    EXPECT_DOUBLE_EQ(rosin::config::buildVoiceSetup(model.preset).contact.ambientOffset, -12.0);
    // A warmer rosin is softer: lower static friction at rest.
    auto warm = frictionLaw(withEffect("ambient-temperature", {12.0}));
    auto nominal = frictionLaw(SimulationModel{});
    warm->prepare(kFs);
    nominal->prepare(kFs);
    EXPECT_LT(warm->staticCoefficient(1.0), nominal->staticCoefficient(1.0));
}

/// The bridge force of 0.3 s bowed from rest (0.8 N, 0.1 m/s reached over 50 ms, beta 0.1) on the model.
std::vector<double> bowedFromRest(const SimulationModel& model)
{
    rosin::physics::BowedStringVoice voice;
    voice.prepare(voiceConfig(model), frictionLaw(model), kFs);
    std::vector<double> force;
    for (int k = 0; k < static_cast<int>(0.3 * kFs); ++k)
        force.push_back(voice.step({0.8, 0.1 * std::min(1.0, k / (0.05 * kFs)), 0.1, 1.0}).bridgeForce);
    return force;
}

double relativeRmsDifference(const std::vector<double>& a, const std::vector<double>& b)
{
    double d = 0.0, e = 0.0;
    for (std::size_t k = 0; k < a.size(); ++k)
    {
        d += (a[k] - b[k]) * (a[k] - b[k]);
        e += b[k] * b[k];
    }
    return std::sqrt(d / e);
}

// A fit that ends at an effect's null explains nothing of its own (discover says so): at the null the
// simulation is the baseline's, and a step off it is not the null.
TEST(EffectCatalog, AnEffectAtItsNullBowsAsTheBaselineDoes)
{
    const auto baseline = bowedFromRest(SimulationModel{});
    const std::vector<std::tuple<std::string, std::vector<double>, std::vector<double>>> cases = {
        {"junction-growth", {0.0, 0.005, 0.0}, {0.01, 0.005, 0.0}},
        {"breakaway-jump", {2, 0.0}, {2, 0.01}},
        {"extra-string-damping", {1.0, 0.0}, {1.05, 0.0}},
        {"ambient-temperature", {0.0}, {0.5}},
        {"friction-law", {0}, {1}},
    };
    for (const auto& [name, null, off] : cases)
    {
        const Effect& effect = *findEffect(name);
        EXPECT_TRUE(isNull(effect, null)) << name;
        EXPECT_FALSE(isNull(effect, off)) << name;
        EXPECT_EQ(bowedFromRest(withEffect(name, null)), baseline) << name; // bit for bit
        EXPECT_NE(bowedFromRest(withEffect(name, off)), baseline)
            << name; // and a small step off it bows otherwise
    }
    EXPECT_FALSE(isNull(*findEffect("hertz-contact"), {})); // a switch: no null to stay at
    // The weakest dashpot of the fit's range (0.9995 x the rigid contact on this string) still moves the
    // bowed transient by a tenth: creep has no null inside its range.
    EXPECT_FALSE(isNull(*findEffect("sticking-creep"), {2000.0}));
    EXPECT_GT(relativeRmsDifference(bowedFromRest(withEffect("sticking-creep", {2000.0})), baseline), 0.01);
    EXPECT_FALSE(isNull(*findEffect("breakaway-jump"), {0, 0.0})); // the modified law, without a margin
}

TEST(EffectCatalog, OutOfRangeValuesAreRefusedByName)
{
    SimulationModel model;
    const Effect& growth = *findEffect("junction-growth");
    try
    {
        applyEffect(growth, {0.2, 2.0, 0.0}, model);
        FAIL() << "no error";
    }
    catch (const std::invalid_argument& e)
    {
        EXPECT_NE(std::string(e.what()).find("junction-growth: parameter onsetTime: expected 5e-04..0.05 s"),
                  std::string::npos)
            << e.what();
    }
    EXPECT_THROW(applyEffect(growth, {0.2}, model), std::invalid_argument);
    EXPECT_THROW(applyEffect(*findEffect("breakaway-jump"), {0.5}, model), std::invalid_argument);
    EXPECT_THROW(applyEffect(*findEffect("sticking-creep"), {NAN}, model), std::invalid_argument);
    EXPECT_DOUBLE_EQ(model.frictionEffects.junctionGrowth, 0.0); // nothing applied
}

TEST(EffectCatalog, DescribesValuesWithUnitsAndChoices)
{
    EXPECT_EQ(describeEffect(*findEffect("junction-growth"), {0.2, 0.005, 1.0}),
              "junction-growth: growth = 0.2, onsetTime = 0.005 s, ageingForm = saturating");
    EXPECT_EQ(describeEffect(*findEffect("breakaway-jump"), {1, 0}),
              "breakaway-jump: jumpCurve = bow, firstSlipMargin = 0");
    EXPECT_EQ(describeEffect(*findEffect("hertz-contact"), {}), "hertz-contact");
}

// Junction growth is fitted as (gain after a 50 ms hold, onset, form): each point maps to the growth whose
// ageing law gives that gain at 50 ms, in both forms; every other effect is fitted in its own parameters.
TEST(EffectCatalog, JunctionGrowthIsFittedAlongTheGainAtAFirstHold)
{
    const Effect& growth = *findEffect("junction-growth");
    ASSERT_EQ(fitCoordinates(growth).size(), growth.parameters.size());
    for (std::size_t j = 0; j < growth.parameters.size(); ++j)
        EXPECT_EQ(fitCoordinates(growth)[j].choices, growth.parameters[j].choices);
    const auto log = parameterValues(growth, {0.86, 0.003, 0.0});
    EXPECT_NEAR(log[0] * std::log(1.0 + 0.05 / 0.003), 0.86, 1e-12);
    EXPECT_DOUBLE_EQ(log[1], 0.003);
    const auto saturating = parameterValues(growth, {0.4, 0.02, 1.0});
    EXPECT_NEAR(saturating[0] * (1.0 - std::exp(-0.05 / 0.02)), 0.4, 1e-12);
    EXPECT_DOUBLE_EQ(parameterValues(growth, {2.0, 0.05, 0.0})[0], 1.0); // held within the catalog's range
    for (const auto& e : effectCatalog())
        if (&e != &growth)
        {
            EXPECT_EQ(&fitCoordinates(e), &e.parameters) << e.name;
            const std::vector<double> v(e.parameters.size(), 0.0);
            EXPECT_EQ(parameterValues(e, v), v) << e.name;
        }
}

} // namespace ROSIN_FILE_LOCAL
