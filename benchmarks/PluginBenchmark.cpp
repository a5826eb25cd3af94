// Issue 3's CPU figure through the plugin itself: RosinProcessor::processBlock at 48 kHz in 128-sample
// blocks, the cello with all four strings bowed (a held four-note chord, sustain pedal down), body and
// plastic thermal friction, with everything the audio thread does (gesture, ears, regime readouts, output
// stage). Printed as % of one core and as a ratio to STK's Bowed run in the same process (the machines are
// noisy).
#include <benchmark/benchmark.h>

#include <cstdio>
#include <map>
#include <string>

#include <juce_events/juce_events.h>

#include "plugin/RosinProcessor.h"

#ifdef ROSIN_HAVE_STK
#include <stk/Bowed.h>
#endif

namespace
{

constexpr double kSampleRate = 48000.0;
constexpr int kBlock = 128;

void benchCelloChord(benchmark::State& state)
{
    rosin::plugin::RosinProcessor processor;
    processor.setProgramByName("cello-plastic");
    processor.setPlayConfigDetails(0, 1, kSampleRate, kBlock);
    processor.prepareToPlay(kSampleRate, kBlock);
    juce::AudioBuffer<float> buffer(1, kBlock);
    juce::MidiBuffer midi;
    midi.addEvent(juce::MidiMessage::controllerEvent(1, 64, 127), 0);
    // C2 G2 D3 A3: one note per string (the chord rule moves none of them).
    for (int note : {36, 43, 50, 57})
        midi.addEvent(juce::MidiMessage::noteOn(1, note, static_cast<juce::uint8>(90)), 0);
    processor.processBlock(buffer, midi);
    midi.clear();
    for (int k = 0; k < static_cast<int>(0.5 * kSampleRate / kBlock); ++k) // past the attacks
        processor.processBlock(buffer, midi);
    for (auto _ : state)
    {
        processor.processBlock(buffer, midi);
        benchmark::DoNotOptimize(buffer.getReadPointer(0)[0]);
    }
    state.SetItemsProcessed(state.iterations() * kBlock);
    state.counters["sounding strings"] = processor.activeEngine()->instrument.stringCount();
}

#ifdef ROSIN_HAVE_STK
void benchStkBowed(benchmark::State& state)
{
    stk::Stk::setSampleRate(kSampleRate);
    stk::Bowed bowed(20.0);
    bowed.noteOn(146.8, 0.8);
    double sink = 0.0;
    for (auto _ : state)
        for (int k = 0; k < kBlock; ++k)
            sink += bowed.tick();
    benchmark::DoNotOptimize(sink);
    state.SetItemsProcessed(state.iterations() * kBlock);
}
#endif

class BlockReporter : public benchmark::ConsoleReporter
{
  public:
    std::map<std::string, double> nsPerBlock;
    void ReportRuns(const std::vector<Run>& runs) override
    {
        ConsoleReporter::ReportRuns(runs);
        for (const auto& r : runs)
            if (r.run_type == Run::RT_Iteration && r.iterations > 0)
                nsPerBlock[r.benchmark_name()] =
                    r.GetAdjustedRealTime() * (r.time_unit == benchmark::kMicrosecond ? 1e3 : 1.0);
    }
};

} // namespace

int main(int argc, char** argv)
{
    juce::ScopedJuceInitialiser_GUI juce;
#ifdef ROSIN_HAVE_STK
    benchmark::RegisterBenchmark("STK_Bowed", benchStkBowed)->Unit(benchmark::kMicrosecond);
#endif
    benchmark::RegisterBenchmark("RosinProcessor_cello_4_strings/plastic", benchCelloChord)
        ->Unit(benchmark::kMicrosecond);
    benchmark::Initialize(&argc, argv);
    BlockReporter reporter;
    benchmark::RunSpecifiedBenchmarks(&reporter);
    const double blockSeconds = kBlock / kSampleRate;
    const double stk = reporter.nsPerBlock.count("STK_Bowed") ? reporter.nsPerBlock["STK_Bowed"] : 0.0;
    std::printf("\n%-44s %14s %12s %10s\n", "128-sample block at 48 kHz", "us/block", "% of a core",
                "vs STK");
    for (const auto& [name, ns] : reporter.nsPerBlock)
        std::printf("%-44s %14.1f %11.2f%% %10s\n", name.c_str(), ns / 1e3, 100.0 * ns * 1e-9 / blockSeconds,
                    stk > 0 ? (std::to_string(ns / stk).substr(0, 5) + "x").c_str() : "n/a");
    benchmark::Shutdown();
    return 0;
}
