// The measured body response, with a synthetic response (no third-party data): what the
// host hears is the bridge force convolved with it (checked against a direct time-domain convolution of the
// plugin's own bridge-force output), loading while playing allocates nothing on the audio thread, the state
// keeps the file's path and content hash, and a missing or broken file says what is wrong and keeps the modal
// body.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include <juce_audio_formats/juce_audio_formats.h>

#include "instrument/engine/SoftClip.h"
#include "instrument/plugin/PluginTestSupport.h"
#include "instrument/plugin/ThreadAllocationCounter.h"

namespace rosin::test
{
namespace ROSIN_FILE_LOCAL
{

constexpr double kFs = 48000.0;

/// A body-like response: two damped resonances (300 Hz and 1.1 kHz), 0.25 s long, Pa per N per sample.
std::vector<float> syntheticResponse()
{
    std::vector<float> h(static_cast<std::size_t>(0.25 * kFs));
    for (std::size_t k = 0; k < h.size(); ++k)
    {
        const double t = static_cast<double>(k) / kFs;
        h[k] = static_cast<float>(0.02 * std::exp(-t / 0.03) * std::sin(2.0 * std::numbers::pi * 300.0 * t) +
                                  0.01 * std::exp(-t / 0.01) * std::sin(2.0 * std::numbers::pi * 1100.0 * t));
    }
    return h;
}

juce::File writeWav(const juce::File& file, const std::vector<float>& x)
{
    file.deleteFile();
    juce::WavAudioFormat wav;
    std::unique_ptr<juce::AudioFormatWriter> writer(
        wav.createWriterFor(new juce::FileOutputStream(file), kFs, 1, 32, {}, 0));
    const float* channel = x.data();
    writer->writeFromFloatArrays(&channel, 1, static_cast<int>(x.size()));
    return file;
}

std::vector<float> renderNote(plugin::RosinProcessor& p, engine::OutputChoice output)
{
    setParameter(p, plugin::ids::output, static_cast<float>(output));
    setParameter(p, plugin::ids::dcBlocker, 0.0f);
    setParameter(p, plugin::ids::outputLevel, -12.0f);
    return renderHeldNote(p, 50, 0.6, 0.2);
}

// With the response loaded before playback (as a project or `rosin render --midi --body-response` does) the
// output is the bridge force convolved with it from the first sample: the plugin's own force output (same
// gain, below the soft clip) convolved in the time domain here matches within 1e-4 of the peak.
TEST(BodyResponse, HostHearsTheBridgeForceThroughTheResponse)
{
    TempFolder temp;
    const std::vector<float> h = syntheticResponse();
    const juce::File file = writeWav(temp.folder().getChildFile("response.wav"), h);

    plugin::RosinProcessor withResponse;
    ASSERT_TRUE(withResponse.bodyResponse().load(file)) << withResponse.bodyResponse().status();
    const std::vector<float> heard = renderNote(withResponse, engine::OutputChoice::RadiatedSound);
    plugin::RosinProcessor plain;
    const std::vector<float> force = renderNote(plain, engine::OutputChoice::BridgeForce);
    ASSERT_EQ(heard.size(), force.size());

    double peak = 0.0, worst = 0.0, forcePeak = 0.0;
    for (std::size_t n = 0; n < heard.size(); ++n)
    {
        double expected = 0.0;
        for (std::size_t k = 0; k < h.size() && k <= n; ++k)
            expected += static_cast<double>(h[k]) * force[n - k];
        peak = std::max(peak, std::abs(expected));
        forcePeak = std::max(forcePeak, static_cast<double>(std::abs(force[n])));
        worst = std::max(worst, std::abs(expected - heard[n]));
    }
    ASSERT_LT(forcePeak, engine::kSoftClipKnee); // both outputs are linear in their samples
    ASSERT_LT(peak, engine::kSoftClipKnee);
    ASSERT_GT(peak, 1e-3);
    std::printf("[ figures  ] measured-response output vs direct convolution: worst %.2e of the peak %.3f\n",
                worst / peak, peak);
    EXPECT_LT(worst, 1e-4 * peak);
    EXPECT_EQ(withResponse.getLatencySamples(), 0); // zero-latency partitions: nothing to report to the host
}

// Without a response every render is the same to the bit whatever the host's block size (DeterminismTest);
// with one, renders at different block sizes agree within 1e-5 of the peak, not to the bit: the
// zero-latency partitioned convolution rounds differently when the host cuts the blocks differently.
TEST(BodyResponse, BlockSizesAgreeWithinTheConvolutionsRounding)
{
    TempFolder temp;
    const juce::File file = writeWav(temp.folder().getChildFile("response.wav"), syntheticResponse());
    std::vector<std::vector<float>> renders;
    for (int block : {64, 512, 997})
    {
        plugin::RosinProcessor p;
        ASSERT_TRUE(p.bodyResponse().load(file));
        juce::MidiMessageSequence seq;
        seq.addEvent(juce::MidiMessage::noteOn(1, 50, juce::uint8(80)), 0.0);
        seq.addEvent(juce::MidiMessage::noteOff(1, 50), 0.6);
        engine::MidiRenderSettings settings;
        settings.sampleRate = kFs;
        settings.blockSize = block;
        settings.tailSeconds = 0.2;
        renders.push_back(test::renderMidi(p, seq, settings).audio);
    }
    double peak = 0.0, worst = 0.0;
    for (std::size_t n = 0; n < renders[0].size(); ++n)
    {
        peak = std::max(peak, static_cast<double>(std::abs(renders[0][n])));
        for (std::size_t r = 1; r < renders.size(); ++r)
            worst = std::max(worst, static_cast<double>(std::abs(renders[r][n] - renders[0][n])));
    }
    std::printf("[ figures  ] block sizes 64/512/997 with a response: worst difference %.2e of the peak\n",
                worst / peak);
    EXPECT_LT(worst, 1e-5 * peak);
}

// Loaded while the audio runs, the response reaches the audio thread through the handoff: no heap allocation
// in any processBlock, and after JUCE's engine swap and the crossfade the output is no longer the modal one.
TEST(BodyResponse, LoadingWhilePlayingAllocatesNothingOnTheAudioThread)
{
    TempFolder temp;
    const juce::File file = writeWav(temp.folder().getChildFile("response.wav"), syntheticResponse());
    constexpr int kBlock = 256;
    plugin::RosinProcessor a, b; // b stays modal
    for (auto* p : {&a, &b})
    {
        p->setPlayConfigDetails(0, 2, kFs, kBlock);
        p->prepareToPlay(kFs, kBlock);
    }
    juce::AudioBuffer<float> bufferA(2, kBlock), bufferB(2, kBlock);
    juce::MidiBuffer noteOn, none;
    noteOn.addEvent(juce::MidiMessage::noteOn(1, 50, 0.7f), 0);
    long allocations = 0;
    double difference = 0.0;
    for (int block = 0; block < static_cast<int>(1.0 * kFs / kBlock); ++block)
    {
        if (block == 40)
            ASSERT_TRUE(a.bodyResponse().load(file));
        if (block > 40)
            juce::Thread::sleep(1); // let JUCE's background thread build the engine, as real time would
        {
            ThreadAllocationCounter counter;
            a.processBlock(bufferA, block == 0 ? noteOn : none);
            allocations += counter.count();
        }
        b.processBlock(bufferB, block == 0 ? noteOn : none);
        for (int i = 0; i < kBlock; ++i)
        {
            ASSERT_TRUE(std::isfinite(bufferA.getSample(0, i)));
            if (block < 40)
                ASSERT_EQ(bufferA.getSample(0, i), bufferB.getSample(0, i));
            else
                difference =
                    std::max(difference, std::abs(double(bufferA.getSample(0, i) - bufferB.getSample(0, i))));
        }
    }
    EXPECT_EQ(allocations, 0);
    EXPECT_GT(difference, 1e-3);
}

// The state keeps the file's path and SHA-256; a restored project loads it again. A missing file keeps the
// modal body and says so, naming the file.
TEST(BodyResponse, StateKeepsTheFileAndAMissingFileIsNamed)
{
    TempFolder temp;
    const juce::File file = writeWav(temp.folder().getChildFile("response.wav"), syntheticResponse());
    juce::MemoryBlock saved;
    {
        plugin::RosinProcessor p;
        ASSERT_TRUE(p.bodyResponse().load(file));
        p.getStateInformation(saved);
    }
    const juce::String xml =
        plugin::RosinProcessor::getXmlFromBinary(saved.getData(), int(saved.getSize()))->toString();
    EXPECT_TRUE(xml.contains(file.getFullPathName()));
    EXPECT_TRUE(xml.contains(engine::fileSha256(file)));
    {
        plugin::RosinProcessor p;
        p.setStateInformation(saved.getData(), static_cast<int>(saved.getSize()));
        EXPECT_EQ(p.bodyResponse().path(), file.getFullPathName());
        EXPECT_TRUE(p.bodyResponse().status().contains("response.wav")) << p.bodyResponse().status();
    }
    file.deleteFile();
    {
        plugin::RosinProcessor p;
        p.setStateInformation(saved.getData(), static_cast<int>(saved.getSize()));
        EXPECT_TRUE(p.bodyResponse().path().isEmpty());
        EXPECT_TRUE(p.bodyResponse().status().contains("missing")) << p.bodyResponse().status();
        EXPECT_TRUE(p.bodyResponse().status().contains(file.getFullPathName()));
    }
}

// Broken files: each message names the file and what was expected; the response in use stays.
TEST(BodyResponse, BrokenFilesAreRefusedWithTheReason)
{
    TempFolder temp;
    const juce::File good = writeWav(temp.folder().getChildFile("good.wav"), syntheticResponse());
    const juce::File text = temp.folder().getChildFile("notes.wav");
    text.replaceWithText("not audio");
    const juce::File silent =
        writeWav(temp.folder().getChildFile("silent.wav"), std::vector<float>(4800, 0.0f));
    const juce::File tiny = writeWav(temp.folder().getChildFile("tiny.wav"), std::vector<float>(10, 0.5f));
    plugin::RosinProcessor p;
    ASSERT_TRUE(p.bodyResponse().load(good));
    const std::pair<juce::File, const char*> cases[] = {{text, "could not be read"},
                                                        {silent, "every sample is zero"},
                                                        {tiny, "at least 64 samples"},
                                                        {temp.folder().getChildFile("none.wav"), "missing"}};
    for (const auto& [file, reason] : cases)
    {
        EXPECT_FALSE(p.bodyResponse().load(file));
        EXPECT_TRUE(p.bodyResponse().status().contains(file.getFullPathName())) << p.bodyResponse().status();
        EXPECT_TRUE(p.bodyResponse().status().contains(reason)) << p.bodyResponse().status();
        EXPECT_EQ(p.bodyResponse().path(), good.getFullPathName()); // still in use
    }
}

} // namespace ROSIN_FILE_LOCAL
} // namespace rosin::test
