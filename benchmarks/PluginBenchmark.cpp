// The plugin's CPU figure through the plugin itself: RosinProcessor::processBlock at 48 kHz in 128-sample
// blocks, the cello with body and plastic thermal friction, with everything the audio thread does (gesture,
// ears, regime readouts, output stage). Two loads: all four strings bowed (a held four-note chord, sustain
// pedal down; the worst case) and a solo line (one string bowed, three ringing with their bows lifted).
// Printed as % of one core and as a ratio to STK's Bowed run in the same process (the machines are noisy).
// The musical mapping's cost: the solo line with the default program (cello-solo: dynamics in the band,
// vibrato), and the player layer alone (MidiGestureController::next for the four strings, one bowed note
// with vibrato and tremolo against the lab mapping's same note), per 128-sample block.
#include <benchmark/benchmark.h>

#include <array>
#include <cstdio>
#include <map>
#include <string>
#include <utility>

#include <juce_events/juce_events.h>

#include "PeerBenchmark.h"
#include "instrument/player/MidiGestureController.h"
#include "instrument/plugin/RosinProcessor.h"

namespace
{

constexpr double kSampleRate = 48000.0;
constexpr int kBlock = 128;

/// The cello-plastic program at `quality`, prepared for 128-sample blocks at 48 kHz, with `play(seconds)` to
/// run it (the MIDI buffer is sent with the first block) and `time(state)` to measure one block per
/// iteration.
struct Session
{
    rosin::plugin::RosinProcessor processor;
    juce::AudioBuffer<float> buffer{1, kBlock};
    juce::MidiBuffer midi;

    explicit Session(rosin::engine::ModelQuality quality, const char* program = "cello-plastic")
    {
        processor.setProgramByName(program);
        auto* parameter = processor.parameters().getParameter(rosin::engine::ids::quality);
        parameter->setValueNotifyingHost(parameter->convertTo0to1(static_cast<float>(quality)));
        processor.setPlayConfigDetails(0, 1, kSampleRate, kBlock);
        processor.prepareToPlay(kSampleRate, kBlock);
    }
    void play(double seconds)
    {
        for (int k = 0; k < static_cast<int>(seconds * kSampleRate / kBlock); ++k)
        {
            processor.processBlock(buffer, midi);
            midi.clear();
        }
    }
    void time(benchmark::State& state)
    {
        for (auto _ : state)
        {
            processor.processBlock(buffer, midi);
            benchmark::DoNotOptimize(buffer.getReadPointer(0)[0]);
        }
        state.SetItemsProcessed(state.iterations() * kBlock);
    }
};

void benchCelloChord(benchmark::State& state, rosin::engine::ModelQuality quality)
{
    Session s(quality);
    s.midi.addEvent(juce::MidiMessage::controllerEvent(1, 64, 127), 0);
    // C2 G2 D3 A3: one note per string (the chord rule moves none of them).
    for (int note : {36, 43, 50, 57})
        s.midi.addEvent(juce::MidiMessage::noteOn(1, note, static_cast<juce::uint8>(90)), 0);
    s.play(0.5); // past the attacks
    s.time(state);
    state.counters["sounding strings"] = s.processor.activeEngine()->instrument.stringCount();
}

// A solo line as a cellist plays it: one string bowed (D3), the other three ringing after their notes
// ended (each was bowed for 0.3 s first, so its contact is warm and its modes are sounding).
void benchCelloSoloLine(benchmark::State& state, rosin::engine::ModelQuality quality, const char* program)
{
    Session s(quality, program);
    s.midi.addEvent(juce::MidiMessage::controllerEvent(1, 1, 80), 0); // the musical mapping's vibrato
    for (int note : {36, 43, 57})
        s.midi.addEvent(juce::MidiMessage::noteOn(1, note, static_cast<juce::uint8>(90)), 0);
    s.play(0.3);
    for (int note : {36, 43, 57})
        s.midi.addEvent(juce::MidiMessage::noteOff(1, note), 0);
    s.midi.addEvent(juce::MidiMessage::noteOn(1, 50, static_cast<juce::uint8>(90)), 0);
    s.play(0.5); // the three bows lifted, the D3 attack over
    s.time(state);
}

// The player layer alone: what it costs to turn MIDI into the four strings' bow inputs.
void benchPlayer(benchmark::State& state, rosin::player::Mapping mapping)
{
    rosin::player::MidiGestureController controller;
    const double open[] = {65.41, 98.0, 146.83, 220.0};
    controller.prepare(open, 4, kSampleRate);
    std::array<rosin::player::PlayableBand, 4> bands{};
    for (std::size_t i = 0; i < 4; ++i)
        bands[i] = {0.55, 0.015, 0.9, 0.2625, 1.0, 0.5, 0.55 / open[i]};
    controller.setBands(bands.data(), 4);
    rosin::player::GestureParameters p;
    p.mapping = mapping;
    controller.setParameters(p);
    using E = rosin::player::GestureEvent;
    controller.handleEvent(E::controller(1, 80));
    controller.handleEvent(E::controller(rosin::player::midimap::ccTremolo, 127));
    controller.handleEvent(E::noteOn(53, 90));
    std::array<rosin::physics::BowInput, 4> inputs{};
    for (int i = 0; i < 24000; ++i)
        controller.next(inputs.data());
    for (auto _ : state)
    {
        for (int i = 0; i < kBlock; ++i)
            controller.next(inputs.data());
        benchmark::DoNotOptimize(inputs[2].fingerRatio);
    }
    state.SetItemsProcessed(state.iterations() * kBlock);
}

} // namespace

int main(int argc, char** argv)
{
    juce::ScopedJuceInitialiser_GUI juce;
#ifdef ROSIN_HAVE_STK
    benchmark::RegisterBenchmark("STK_Bowed", [](benchmark::State& st)
                                 { rosin::bench::benchStkBowed(st, kSampleRate, kBlock); })
        ->Unit(benchmark::kMicrosecond);
#endif
    using rosin::engine::ModelQuality;
    for (const auto& [name, quality] :
         {std::pair{"full", ModelQuality::Full}, std::pair{"live", ModelQuality::Live}})
    {
        benchmark::RegisterBenchmark(("RosinProcessor_cello_4_strings/plastic/" + std::string(name)).c_str(),
                                     benchCelloChord, quality)
            ->Unit(benchmark::kMicrosecond);
        benchmark::RegisterBenchmark(("RosinProcessor_cello_solo_line/plastic/" + std::string(name)).c_str(),
                                     benchCelloSoloLine, quality, "cello-plastic")
            ->Unit(benchmark::kMicrosecond);
    }
    benchmark::RegisterBenchmark("RosinProcessor_cello_solo_line/musical/full", benchCelloSoloLine,
                                 ModelQuality::Full, "cello-solo")
        ->Unit(benchmark::kMicrosecond);
    benchmark::RegisterBenchmark("MidiGestureController_4_strings/lab", benchPlayer,
                                 rosin::player::Mapping::Lab)
        ->Unit(benchmark::kMicrosecond);
    benchmark::RegisterBenchmark("MidiGestureController_4_strings/musical", benchPlayer,
                                 rosin::player::Mapping::Musical)
        ->Unit(benchmark::kMicrosecond);
    const std::string markdown = rosin::bench::takeMarkdownFlag(argc, argv);
    benchmark::Initialize(&argc, argv);
    rosin::bench::IterationTimeReporter reporter;
    benchmark::RunSpecifiedBenchmarks(&reporter);
    rosin::bench::printSummary(reporter, kBlock, markdown);
    benchmark::Shutdown();
    return 0;
}
