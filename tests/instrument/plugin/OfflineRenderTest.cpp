// One engine for every front end: `rosin render --midi` plays through engine::OfflineInstrument,
// not through the plugin's processor. What it writes must still be exactly what the plugin plays: for every
// factory program, with automation that rebuilds the instrument, with a measured body response, at another
// sample rate and block size, the offline render and the processor driven as a host drives it agree sample
// for sample. And the offline parameters hold the values a host's value tree state holds.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include <juce_audio_formats/juce_audio_formats.h>

#include "instrument/engine/FactoryPrograms.h"
#include "instrument/engine/OfflineInstrument.h"
#include "instrument/plugin/PluginTestSupport.h"

namespace rosin::test
{
namespace ROSIN_FILE_LOCAL
{

const engine::FactoryProgram& program(const std::string& name)
{
    static const std::vector<engine::FactoryProgram> programs = engine::loadFactoryPrograms();
    for (const auto& p : programs)
        if (p.name == name)
            return p;
    throw std::runtime_error("no factory program " + name);
}

// An event plays in the sample whose period holds its time, as a host counting in samples places it: tick t
// of a 960-per-quarter file at 60 bpm lies at t * fs / 960 samples exactly, and the sample is that number's
// integer part (computed here in integers, away from the doubles the render uses).
TEST(OfflineRender, AnEventPlaysInTheSampleThatHoldsItsTime)
{
    for (const int fs : {44100, 48000, 96000})
        for (int tick = 0; tick < 9600; ++tick)
        {
            const double seconds = tick / 960.0;
            ASSERT_EQ(engine::eventSample(seconds, fs), static_cast<std::int64_t>(tick) * fs / 960)
                << "tick " << tick << " at " << fs << " Hz";
        }
    EXPECT_EQ(engine::eventSample(-0.5, 48000.0), 0);
}

std::size_t differingSamples(const std::vector<float>& a, const std::vector<float>& b)
{
    if (a.size() != b.size())
        return std::max(a.size(), b.size());
    std::size_t n = 0;
    for (std::size_t i = 0; i < a.size(); ++i)
        n += a[i] != b[i];
    return n;
}

engine::MidiRenderSettings settingsOf(double sampleRate, int blockSize, double tail)
{
    engine::MidiRenderSettings s;
    s.sampleRate = sampleRate;
    s.blockSize = blockSize;
    s.tailSeconds = tail;
    return s;
}

// Lanes over most parameters, including the ones that rebuild the instrument (law, body, ambient,
// instrument).
engine::AutomationLanes busyLanes()
{
    const nlohmann::json lanes = {{"bowForce", {{0, 1.0}, {2.5, 2.0}, {4.0, 0.4}}},
                                  {"bowSpeed", {{0, 0.1}, {3, 0.3}}},
                                  {"friction", {{0, "plastic"}, {4, "classical"}}},
                                  {"body", {{0, true}, {1, false}, {2.2, true}}},
                                  {"beta", {{0, 0.1}, {5, 0.05}}},
                                  {"outputLevel", {{0, -12}, {3, -6}}},
                                  {"instrument", {{0, "cello"}, {6, "violin"}}},
                                  {"ambientTemperature", {{0, 20}, {3.5, 30}}},
                                  {"string", {{0, "auto"}, {1.5, "II"}}},
                                  {"intonation", {{0, true}, {2, false}}},
                                  {"attackAcceleration", {{0, 2.0}, {1, 5.0}}}};
    return engine::parseAutomation({{"format", "rosin-automation/1"}, {"lanes", lanes}}, "busy.json");
}

// Two damped resonances, written as a 32-bit WAV: a measured response without third-party data.
juce::File writeResponse(const juce::File& file)
{
    constexpr double fs = 48000.0;
    std::vector<float> h(6000);
    for (std::size_t k = 0; k < h.size(); ++k)
    {
        const double t = static_cast<double>(k) / fs;
        h[k] = static_cast<float>(0.02 * std::exp(-t / 0.03) * std::sin(2.0 * std::numbers::pi * 300.0 * t));
    }
    file.deleteFile();
    juce::WavAudioFormat wav;
    std::unique_ptr<juce::AudioFormatWriter> writer(
        wav.createWriterFor(new juce::FileOutputStream(file), fs, 1, 32, {}, 0));
    const float* channel = h.data();
    writer->writeFromFloatArrays(&channel, 1, static_cast<int>(h.size()));
    return file;
}

TEST(OfflineRender, EveryProgramPlaysWhatTheProcessorPlays)
{
    const auto settings = settingsOf(48000.0, 512, 0.3);
    for (const engine::FactoryProgram& p : engine::loadFactoryPrograms())
    {
        plugin::RosinProcessor processor;
        ASSERT_TRUE(processor.setProgramByName(p.name));
        const auto host = renderMidi(processor, demoPhrase(), settings);
        engine::OfflineInstrument offline;
        offline.setProgram(p);
        const auto own = offline.render(demoPhrase(), settings);
        ASSERT_GT(host.peak, 0.01f) << p.name;
        EXPECT_EQ(differingSamples(own.audio, host.audio), 0u) << p.name;
        EXPECT_EQ(own.peak, host.peak) << p.name;
    }
}

TEST(OfflineRender, AutomationThatRebuildsTheInstrumentPlaysWhatTheProcessorPlays)
{
    const engine::AutomationLanes lanes = busyLanes();
    for (int block : {97}) // 512 is every program's case above
    {
        const auto settings = settingsOf(48000.0, block, 0.5);
        plugin::RosinProcessor processor;
        processor.setProgramByName("cello-plastic");
        const auto host = renderMidi(processor, demoPhrase(), settings, &lanes);
        engine::OfflineInstrument offline;
        offline.setProgram(program("cello-plastic"));
        const auto own = offline.render(demoPhrase(), settings, &lanes);
        ASSERT_GT(host.peak, 0.01f);
        EXPECT_EQ(differingSamples(own.audio, host.audio), 0u) << "block size " << block;
    }
}

TEST(OfflineRender, OutputChoicesSampleRateAndMeasuredResponsePlayWhatTheProcessorPlays)
{
    juce::TemporaryFile temp(".wav");
    const juce::File response = writeResponse(temp.getFile());
    struct Case
    {
        float output;
        bool dcBlocker, measured;
        double sampleRate;
        int block;
    };
    for (const Case c : {Case{1.0f, false, false, 44100.0, 33}, Case{2.0f, true, false, 48000.0, 256},
                         Case{0.0f, true, true, 48000.0, 256}})
    {
        const auto settings = settingsOf(c.sampleRate, c.block, 0.3);
        plugin::RosinProcessor processor;
        processor.setProgramByName("cello-classical");
        if (c.measured)
            ASSERT_TRUE(processor.bodyResponse().load(response));
        setParameter(processor, plugin::ids::output, c.output);
        setParameter(processor, plugin::ids::dcBlocker, c.dcBlocker ? 1.0f : 0.0f);
        const auto host = renderMidi(processor, demoPhrase(), settings);

        engine::OfflineInstrument offline;
        offline.setProgram(program("cello-classical"));
        if (c.measured)
            offline.useBodyResponse(engine::readBodyResponse(response));
        offline.parameters().set(engine::ids::output, c.output);
        offline.parameters().set(engine::ids::dcBlocker, c.dcBlocker ? 1.0f : 0.0f);
        const auto own = offline.render(demoPhrase(), settings);
        ASSERT_GT(host.peak, 0.001f);
        EXPECT_EQ(differingSamples(own.audio, host.audio), 0u)
            << "output " << c.output << ", measured " << c.measured << ", " << c.sampleRate << " Hz";
    }
}

// The offline ParameterSet stores what juce::AudioProcessorValueTreeState stores for the same plain values,
// to the bit (the skewed ranges round through their normalised value twice).
TEST(OfflineRender, ParameterSetHoldsTheValuesAHostsValueTreeStateHolds)
{
    plugin::RosinProcessor processor;
    engine::ParameterSet offline;
    std::mt19937 random(21);
    for (int round = 0; round < 200; ++round)
        for (const engine::ParameterSpec& spec : engine::parameterSpecs())
        {
            std::uniform_real_distribution<double> value(spec.min, spec.max);
            const float plain = static_cast<float>(value(random));
            setParameter(processor, spec.id, plain);
            offline.set(spec.id, plain);
            const float host = *processor.parameters().getRawParameterValue(spec.id);
            const float own =
                offline.raw()[static_cast<engine::ParameterIndex>(engine::parameterIndex(spec.id))];
            ASSERT_EQ(own, host) << spec.id << " = " << plain;
        }
}

} // namespace ROSIN_FILE_LOCAL
} // namespace rosin::test
