// The engine's parameter table is the one vocabulary of the host parameters: its order is the IDs' order and
// the snapshot's index, the JUCE parameters made from it carry its ranges and defaults, and the snapshot a
// block plays with reads damaged values (NaN from a host) as defaults and maps the string choice as players
// number strings.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "instrument/engine/EngineParameters.h"
#include "instrument/engine/OfflineInstrument.h"
#include "instrument/engine/ParameterSet.h"

namespace rosin::engine
{
namespace ROSIN_FILE_LOCAL
{

TEST(EngineParameters, TableOrderIsTheIdsOrderAndTheSnapshotIndex)
{
    const auto& specs = parameterSpecs();
    ASSERT_EQ(specs.size(), static_cast<std::size_t>(kParameterCount));
    for (int i = 0; i < kParameterCount; ++i)
    {
        const char* id = allParameterIds()[static_cast<std::size_t>(i)];
        EXPECT_STREQ(specs[static_cast<std::size_t>(i)].id, id);
        EXPECT_EQ(parameterIndex(id), i);
        EXPECT_EQ(findParameterSpec(id), &specs[static_cast<std::size_t>(i)]);
    }
    EXPECT_EQ(parameterIndex(ids::bypass), static_cast<int>(ParameterIndex::bypass));
    EXPECT_EQ(parameterIndex("bowForse"), -1);
    EXPECT_EQ(findParameterSpec("bowForse"), nullptr);
}

TEST(EngineParameters, JuceParametersCarryTheTablesRangesAndDefaults)
{
    const auto parameters = makeParameters();
    ASSERT_EQ(parameters.size(), parameterSpecs().size());
    for (std::size_t i = 0; i < parameters.size(); ++i)
    {
        const ParameterSpec& spec = parameterSpecs()[i];
        const juce::RangedAudioParameter& p = *parameters[i];
        EXPECT_EQ(p.getParameterID(), juce::String(spec.id));
        EXPECT_FLOAT_EQ(p.getNormalisableRange().start, static_cast<float>(spec.min)) << spec.id;
        EXPECT_FLOAT_EQ(p.getNormalisableRange().end, static_cast<float>(spec.max)) << spec.id;
        EXPECT_NEAR(p.convertFrom0to1(p.getDefaultValue()), spec.defaultValue,
                    1e-6f * (1.0f + std::abs(spec.defaultValue)))
            << spec.id;
        if (spec.skewCentre > 0.0f) // the taper puts the centre at mid-travel
            EXPECT_NEAR(p.convertFrom0to1(0.5f), spec.skewCentre, 1e-4f * spec.skewCentre) << spec.id;
        if (spec.kind == ParameterSpec::Kind::Choice)
            EXPECT_EQ(static_cast<std::size_t>(p.getNumSteps()), spec.choices.size()) << spec.id;
    }
}

TEST(EngineParameters, DefaultsGiveTheDefaultSnapshot)
{
    const ParameterSet set;
    const ParameterSnapshot s = snapshotOf(set.raw(), 4);
    EXPECT_NEAR(s.gesture.bowForce, 1.0, 1e-6);
    EXPECT_NEAR(s.gesture.bowSpeed, 0.1, 1e-6);
    EXPECT_NEAR(s.gesture.beta, 0.0899, 1e-6);
    EXPECT_EQ(s.key.friction, physics::FrictionModel::Plastic);
    EXPECT_TRUE(s.key.body);
    EXPECT_EQ(s.gesture.stringOverride, -1);
    EXPECT_TRUE(s.intonationByEar);
    EXPECT_EQ(s.output.choice, OutputChoice::RadiatedSound);
    EXPECT_NEAR(20.0 * std::log10(s.output.gain), kDefaultOutputLevelDb, 1e-5);
}

TEST(EngineParameters, DamagedValuesReadAsDefaultsAndChoicesStayInRange)
{
    RawParameterValues raw = ParameterSet().raw();
    const float nan = std::numeric_limits<float>::quiet_NaN();
    raw[ParameterIndex::bowForce] = nan;
    raw[ParameterIndex::beta] = nan;
    raw[ParameterIndex::ambientTemperature] = nan;
    raw[ParameterIndex::friction] = 1e9f;
    raw[ParameterIndex::instrument] = -3.0f;
    raw[ParameterIndex::output] = nan;
    const ParameterSnapshot s = snapshotOf(raw, 4);
    EXPECT_EQ(s.gesture.bowForce, 1.0);
    EXPECT_NEAR(s.gesture.beta, 0.0899, 1e-6);
    EXPECT_EQ(s.key.ambientCelsius, 20.0);
    EXPECT_EQ(static_cast<int>(s.key.friction), physics::kFrictionModelCount - 1);
    EXPECT_EQ(s.key.instrument, 0);
    EXPECT_EQ(s.output.choice, OutputChoice::RadiatedSound);
}

TEST(EngineParameters, StringChoiceCountsFromTheHighestString)
{
    ParameterSet set;
    for (int choice = 1; choice <= 4; ++choice)
    {
        set.set(ids::string, static_cast<float>(choice));
        // String I is the highest: index 3 of a four-string instrument counted from the lowest.
        EXPECT_EQ(snapshotOf(set.raw(), 4).gesture.stringOverride, 4 - choice);
    }
    set.set(ids::string, 0.0f);
    EXPECT_EQ(snapshotOf(set.raw(), 4).gesture.stringOverride, -1);
}

TEST(EngineParameters, SettingOnlyIfChangedReportsAChange)
{
    ParameterSet set;
    EXPECT_TRUE(set.set(ids::bowForce, 2.0f, true));
    EXPECT_FALSE(set.set(ids::bowForce, 2.0f, true));
    EXPECT_FALSE(set.set("noSuchParameter", 1.0f));
    EXPECT_NEAR(set.raw()[ParameterIndex::bowForce], 2.0f, 1e-5f);
}

// An offline render does not depend on how its blocks are cut (events at their sample, automation on the
// control grid).
TEST(OfflineInstrument, RenderDoesNotDependOnTheBlockSize)
{
    juce::MidiMessageSequence sequence;
    sequence.addEvent(juce::MidiMessage::noteOn(1, 50, static_cast<juce::uint8>(90)), 0.0);
    sequence.addEvent(juce::MidiMessage::noteOn(1, 57, static_cast<juce::uint8>(70)), 0.13);
    sequence.addEvent(juce::MidiMessage::noteOff(1, 50), 0.31);
    sequence.addEvent(juce::MidiMessage::noteOff(1, 57), 0.42);
    const AutomationLanes lanes = parseAutomation(
        {{"format", "rosin-automation/1"},
         {"lanes",
          {{"bowForce", {{0, 0.8}, {0.4, 1.6}}}, {"friction", {{0, "plastic"}, {0.2, "classical"}}}}}},
        "lanes.json");
    std::vector<float> reference;
    for (int block : {512, 1, 77})
    {
        OfflineInstrument instrument;
        MidiRenderSettings settings;
        settings.blockSize = block;
        settings.tailSeconds = 0.1;
        const MidiRenderResult r = instrument.render(sequence, settings, &lanes);
        ASSERT_GT(r.peak, 0.001f);
        if (reference.empty())
            reference = r.audio;
        else
            EXPECT_EQ(r.audio, reference) << "block size " << block;
    }
}

} // namespace ROSIN_FILE_LOCAL
} // namespace rosin::engine
