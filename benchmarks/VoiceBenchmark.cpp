// Cost of one voice per sample at 48 kHz for each friction law (cello D string with the cello body), and in
// the same run STK's Bowed instrument as the peer. Prints ns per sample, the real-time factor and the ratio
// to STK: machines are noisy, ratios within one process are what can be compared.
//   build/benchmarks/bench_voice [--benchmark_min_time=1] [--markdown=FILE]
#include <benchmark/benchmark.h>

#include <cstdio>
#include <map>
#include <string>

#include "PeerBenchmark.h"
#include "core/physics/instrument/BowedInstrument.h"
#include "core/physics/laws/FrictionLawFactory.h"
#include "core/physics/voice/BowedStringVoice.h"

namespace
{
constexpr double kSampleRate = 48000.0;
constexpr int kBlock = 4800; // samples per benchmark iteration (0.1 s)

void benchVoice(benchmark::State& state, rosin::physics::FrictionModel model,
                const rosin::physics::BowParameters& bow = {})
{
    using namespace rosin::physics;
    VoiceConfig cfg;
    cfg.string = stringFromCatalogue("cello-D3");
    cfg.body = celloBody();
    cfg.bow = bow;
    BowedStringVoice voice;
    voice.prepare(cfg, makeFrictionLaw(model, galluzzoContact()), kSampleRate);
    // Settle into steady bowing first, so the timing covers the sustained note a player hears.
    for (int k = 0; k < 24000; ++k)
        voice.step({1.0, std::min(0.1, k / kSampleRate), 0.0899, 1.0});
    double sink = 0.0;
    for (auto _ : state)
        for (int k = 0; k < kBlock; ++k)
            sink += voice.step({1.0, 0.1, 0.0899, 1.0}).bridgeForce;
    benchmark::DoNotOptimize(sink);
    state.SetItemsProcessed(state.iterations() * kBlock);
    state.counters["transverse"] = voice.transverseModeCount();
    state.counters["torsional"] = voice.torsionalModeCount();
    state.counters["body"] = voice.bodyModeCount();
}

/// The whole cello, four strings bowed at once on one body (the plugin's CPU figure), per sample of output.
void benchCello(benchmark::State& state)
{
    using namespace rosin::physics;
    BowedInstrument cello;
    cello.prepare(celloInstrument(), kSampleRate);
    std::vector<BowInput> in(4, BowInput{1.0, 0.0, 0.1, 1.0});
    std::vector<VoiceSample> out(4);
    for (int k = 0; k < 24000; ++k)
    {
        for (auto& b : in)
            b.bowVelocity = std::min(0.1, k / kSampleRate);
        cello.step(in.data(), out.data());
    }
    double sink = 0.0;
    for (auto _ : state)
        for (int k = 0; k < kBlock; ++k)
            sink += cello.step(in.data(), out.data());
    benchmark::DoNotOptimize(sink);
    state.SetItemsProcessed(state.iterations() * kBlock);
}

} // namespace

int main(int argc, char** argv)
{
    using rosin::physics::FrictionModel;
#ifdef ROSIN_HAVE_STK
    benchmark::RegisterBenchmark("STK_Bowed", [](benchmark::State& st)
                                 { rosin::bench::benchStkBowed(st, kSampleRate, kBlock); })
        ->Unit(benchmark::kMicrosecond);
#endif
    for (auto model : {FrictionModel::Classical, FrictionModel::Reconstructed, FrictionModel::Plastic,
                       FrictionModel::Viscous, FrictionModel::ModifiedBow, FrictionModel::ModifiedRod})
        benchmark::RegisterBenchmark((std::string("Rosin_cello_D_body/") + frictionModelName(model)).c_str(),
                                     [model](benchmark::State& s) { benchVoice(s, model); })
            ->Unit(benchmark::kMicrosecond);
    // The bow's width costs nothing per sample (it changes the modes' weights); the compliant hair one more
    // first-order state at the junction.
    benchmark::RegisterBenchmark(
        "Rosin_cello_D_body/plastic_horsehair_8mm", [](benchmark::State& s)
        { benchVoice(s, FrictionModel::Plastic, rosin::physics::horsehairBow(0.008)); })
        ->Unit(benchmark::kMicrosecond);
    // The slip noise: one Gaussian draw per sample while the string flies back.
    benchmark::RegisterBenchmark("Rosin_cello_D_body/plastic_slip_noise",
                                 [](benchmark::State& s)
                                 {
                                     rosin::physics::BowParameters bow;
                                     bow.slipNoise = rosin::physics::ribbonSlipNoise();
                                     benchVoice(s, FrictionModel::Plastic, bow);
                                 })
        ->Unit(benchmark::kMicrosecond);
    benchmark::RegisterBenchmark("Rosin_cello_4_strings/plastic", benchCello)->Unit(benchmark::kMicrosecond);
    const std::string markdown = rosin::bench::takeMarkdownFlag(argc, argv);
    benchmark::Initialize(&argc, argv);
    rosin::bench::IterationTimeReporter reporter;
    benchmark::RunSpecifiedBenchmarks(&reporter);
    rosin::bench::printSummary(reporter, kBlock, markdown);
    benchmark::Shutdown();
    return 0;
}
