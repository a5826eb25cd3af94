#pragma once
// What the benchmarks share: STK's Bowed instrument as the peer, run in the same process (machines are noisy,
// so speed is reported as a ratio to it), a reporter that keeps each benchmark's time per iteration, and the
// summary every benchmark prints: time per sample and per 128-sample block, share of one core at 48 kHz and
// the ratio to STK; with --markdown=FILE also as the Markdown table the manual's benchmarks page shows
// (benchmarks/update_benchmark_tables.py puts it there, so its figures are printed, not typed).
#include <benchmark/benchmark.h>

#include <cstdio>
#include <cstring>
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

inline constexpr double kSummaryRate = 48000.0; ///< Hz: the rate the share of a core is given at
inline constexpr int kSummaryBlock = 128;       ///< samples per block, as a host would call

/// Removes --markdown=FILE from the arguments (Google Benchmark refuses flags it does not know) and returns
/// FILE, or "" when absent.
inline std::string takeMarkdownFlag(int& argc, char** argv)
{
    constexpr const char* flag = "--markdown=";
    std::string file;
    int kept = 1;
    for (int i = 1; i < argc; ++i)
        if (std::strncmp(argv[i], flag, std::strlen(flag)) == 0)
            file = argv[i] + std::strlen(flag);
        else
            argv[kept++] = argv[i];
    argc = kept;
    return file;
}

/// Prints each benchmark's time per sample (`samplesPerIteration` samples in one iteration), per 128-sample
/// block, its share of one core at 48 kHz and its ratio to STK run in the same process; the same rows go to
/// `markdownFile` as a Markdown table when it is not empty.
inline void printSummary(const IterationTimeReporter& reporter, int samplesPerIteration,
                         const std::string& markdownFile)
{
    const double stk = reporter.peer() / samplesPerIteration;
    std::FILE* md = markdownFile.empty() ? nullptr : std::fopen(markdownFile.c_str(), "w");
    if (!markdownFile.empty() && !md)
        std::fprintf(stderr, "cannot write %s\n", markdownFile.c_str());
    std::printf("\n%-40s %10s %10s %12s %8s\n", "benchmark", "ns/sample", "us/block", "% of a core",
                "vs STK");
    if (md)
        std::fprintf(md, "| benchmark | ns per sample | us per 128-sample block | %% of one core at 48 kHz | "
                         "x STK Bowed |\n| --- | ---: | ---: | ---: | ---: |\n");
    for (const auto& [name, perIteration] : reporter.nsPerIteration)
    {
        const double ns = perIteration / samplesPerIteration;
        const double block = ns * kSummaryBlock / 1e3, core = 100.0 * ns * kSummaryRate / 1e9;
        char ratio[32] = "n/a";
        if (stk > 0.0)
            std::snprintf(ratio, sizeof(ratio), "%.2f", ns / stk);
        std::printf("%-40s %10.1f %10.2f %11.2f%% %8s\n", name.c_str(), ns, block, core, ratio);
        if (md)
            std::fprintf(md, "| `%s` | %.1f | %.2f | %.2f | %s |\n", name.c_str(), ns, block, core, ratio);
    }
    if (md)
        std::fclose(md);
}

} // namespace rosin::bench
