#pragma once
// What the benchmarks share: STK's Bowed instrument as the peer, run in the same process (machines are noisy,
// so speed is reported as a ratio to it), and a reporter that keeps each benchmark's time per iteration.
#include <benchmark/benchmark.h>

#include <map>
#include <string>
#include <vector>

#ifdef ROSIN_HAVE_STK
#include <stk/Bowed.h>

namespace rosin::bench
{

/// STK's Bowed at 146.8 Hz, `samples` ticks per iteration.
inline void benchStkBowed(benchmark::State& state, double sampleRate, int samples)
{
    stk::Stk::setSampleRate(sampleRate);
    stk::Bowed bowed(20.0);
    bowed.noteOn(146.8, 0.8);
    double sink = 0.0;
    for (auto _ : state)
        for (int k = 0; k < samples; ++k)
            sink += bowed.tick();
    benchmark::DoNotOptimize(sink);
    state.SetItemsProcessed(state.iterations() * samples);
}

} // namespace rosin::bench
#endif

namespace rosin::bench
{

/// Prints as the console reporter does and keeps ns per iteration for each benchmark by name.
class IterationTimeReporter : public benchmark::ConsoleReporter
{
  public:
    std::map<std::string, double> nsPerIteration;
    void ReportRuns(const std::vector<Run>& runs) override
    {
        ConsoleReporter::ReportRuns(runs);
        for (const auto& r : runs)
            if (r.run_type == Run::RT_Iteration && r.iterations > 0)
                nsPerIteration[r.benchmark_name()] =
                    r.GetAdjustedRealTime() * (r.time_unit == benchmark::kMicrosecond ? 1e3 : 1.0);
    }
    /// The peer's time per iteration, or 0 when STK was not built in.
    double peer() const
    {
        const auto it = nsPerIteration.find("STK_Bowed");
        return it == nsPerIteration.end() ? 0.0 : it->second;
    }
};

} // namespace rosin::bench
