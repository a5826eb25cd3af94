// A damaged project must neither silence nor crash the plugin: non-finite and
// out-of-range values restore as defaults, oversized or deeply nested states are refused before parsing,
// the engine plays again as soon as its inputs are sane, and every parameter the host sees is refreshed.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "instrument/plugin/PluginTestSupport.h"
#include "instrument/plugin/SavedState.h"

namespace rosin::test
{
namespace ROSIN_FILE_LOCAL
{

juce::MemoryBlock savedState(plugin::RosinProcessor& p)
{
    juce::MemoryBlock block;
    p.getStateInformation(block);
    return block;
}

/// The saved state of a fresh processor with PARAM `id` set to the text `value`.
juce::MemoryBlock damagedState(const char* id, const juce::String& value)
{
    plugin::RosinProcessor p;
    const juce::MemoryBlock good = savedState(p);
    auto xml = juce::AudioProcessor::getXmlFromBinary(good.getData(), static_cast<int>(good.getSize()));
    for (auto* param : xml->getChildWithTagNameIterator("PARAM"))
        if (param->getStringAttribute("id") == id)
            param->setAttribute("value", value);
    juce::MemoryBlock damaged;
    juce::AudioProcessor::copyXmlToBinary(*xml, damaged);
    return damaged;
}

/// RMS of one note (D3, velocity 80, 0.6 s) after the state is restored.
double noteRms(plugin::RosinProcessor& p)
{
    juce::MidiMessageSequence seq;
    seq.addEvent(juce::MidiMessage::noteOn(1, 50, static_cast<juce::uint8>(80)), 0.0);
    seq.addEvent(juce::MidiMessage::noteOff(1, 50), 0.6);
    engine::MidiRenderSettings settings;
    settings.tailSeconds = 0.0;
    const auto r = test::renderMidi(p, seq, settings);
    double sum = 0.0;
    for (float x : r.audio)
        sum += static_cast<double>(x) * x;
    EXPECT_TRUE(allFinite(r.audio));
    return r.audio.empty() ? 0.0 : std::sqrt(sum / static_cast<double>(r.audio.size()));
}

TEST(PluginStateSafety, NonFiniteAndOutOfRangeValuesRestoreAsDefaults)
{
    for (const char* id : {plugin::ids::bowForce, plugin::ids::attackAcceleration, plugin::ids::beta,
                           plugin::ids::outputLevel, plugin::ids::ambientTemperature})
        for (const char* bad : {"nan", "inf", "-inf", "1e30", "-5", "not a number"})
        {
            plugin::RosinProcessor p;
            auto* parameter = p.parameters().getParameter(id);
            const juce::MemoryBlock state = damagedState(id, bad);
            p.setStateInformation(state.getData(), static_cast<int>(state.getSize()));
            const float value = parameter->convertFrom0to1(parameter->getValue());
            const auto& range = parameter->getNormalisableRange();
            EXPECT_TRUE(std::isfinite(value)) << id << " = " << bad;
            if (std::string(bad) != "1e30" && std::string(bad) != "-5")
                EXPECT_NEAR(parameter->getValue(), parameter->getDefaultValue(), 1e-6) << id << " = " << bad;
            EXPECT_GE(value, range.start) << id << " = " << bad;
            EXPECT_LE(value, range.end) << id << " = " << bad;
        }
}

TEST(PluginStateSafety, ADamagedStateDoesNotSilenceTheEngine)
{
    plugin::RosinProcessor p;
    const double reference = noteRms(p);
    ASSERT_GT(reference, 1e-4);
    for (const char* id : {plugin::ids::bowForce, plugin::ids::outputLevel, plugin::ids::beta})
    {
        const juce::MemoryBlock nan = damagedState(id, "nan");
        p.setStateInformation(nan.getData(), static_cast<int>(nan.getSize()));
        EXPECT_GT(noteRms(p), 0.1 * reference) << id; // defaults play
        plugin::RosinProcessor fresh;
        const juce::MemoryBlock good = savedState(fresh);
        p.setStateInformation(good.getData(), static_cast<int>(good.getSize()));
        EXPECT_GT(noteRms(p), 0.1 * reference) << id; // and a good state afterwards too
    }
}

TEST(PluginStateSafety, OversizedAndDeeplyNestedStatesAreRefusedBeforeParsing)
{
    plugin::RosinProcessor p;
    setParameter(p, plugin::ids::bowForce, 2.0f);
    const float before = p.parameters().getParameter(plugin::ids::bowForce)->getValue();

    std::string deep = "<RosinState>";
    for (int i = 0; i < 30000; ++i)
        deep += "<a>";
    EXPECT_TRUE(plugin::unparseableState(deep.data(), static_cast<int>(deep.size())).has_value());
    const std::string shallow(3000, 'x');
    EXPECT_FALSE(plugin::unparseableState(shallow.data(), static_cast<int>(shallow.size())).has_value());

    juce::MemoryBlock nested;
    {
        juce::XmlElement root("RosinState");
        juce::XmlElement* e = &root;
        for (int i = 0; i < 100; ++i)
            e = e->createNewChildElement("a");
        juce::AudioProcessor::copyXmlToBinary(root, nested);
    }
    p.setStateInformation(nested.getData(), static_cast<int>(nested.getSize()));
    const std::string ampersands = "<RosinState a=\"" + std::string(1 << 20, '&') + "\"/>";
    p.setStateInformation(ampersands.data(), static_cast<int>(ampersands.size()));
    EXPECT_EQ(p.parameters().getParameter(plugin::ids::bowForce)->getValue(), before);

    const juce::MemoryBlock good = savedState(p);
    EXPECT_LT(static_cast<int>(good.getSize()), plugin::kMaxStateBytes / 8); // room for what states hold
    EXPECT_FALSE(plugin::unparseableState(good.getData(), static_cast<int>(good.getSize())).has_value());
}

TEST(PluginStateSafety, RestoringRefreshesEverySwitchAndChoiceTheHostHolds)
{
    // pluginval's state check: the host sets fractional values, restores a saved state, and reads every
    // parameter back. A switch at 0.59 reads as on; restoring "on" changes nothing inside, yet the host's
    // value must become 1.
    plugin::RosinProcessor p;
    const juce::MemoryBlock saved = savedState(p);
    std::vector<float> expected;
    for (auto* parameter : p.getParameters())
        expected.push_back(parameter->getValue());
    for (auto* parameter : p.getParameters())
        parameter->setValueNotifyingHost(parameter->getValue() > 0.5f ? 0.59f : 0.41f);
    p.setStateInformation(saved.getData(), static_cast<int>(saved.getSize()));
    for (std::size_t i = 0; i < expected.size(); ++i)
        EXPECT_NEAR(p.getParameters()[static_cast<int>(i)]->getValue(), expected[i], 1e-6)
            << p.getParameters()[static_cast<int>(i)]->getName(64);
}

} // namespace ROSIN_FILE_LOCAL
} // namespace rosin::test
