#pragma once
// Reproducible random numbers for the synthetic-data generator and, later, for the discovery workflow's
// splits. std::mt19937_64 is fully specified by the standard, but std::uniform_real_distribution and
// std::normal_distribution are not (libstdc++ and libc++ give different numbers for the same engine), so the
// distributions are written out here: a uniform double from the top 53 bits of one 64-bit draw, a normal
// from the Box-Muller transform (both of its values used), an integer below n by rejection.
//
// Every use draws from its own stream, seeded from (seed, stream, index): trial 17's jitter is the same
// whatever the number of trials, the threads or the order in which trials are computed, and the same for
// every hidden effect (a dataset with an effect and one without differ only by the effect).
#include <cstdint>
#include <random>

namespace rosin::discovery
{

/// The streams of rosin synth-data (values are part of the output: changing one changes every dataset).
enum class RandomStream : std::uint64_t
{
    EffectValues = 1, ///< index: the effect's place in the catalog
    Jitter = 2,       ///< index: the trial
    FaultChoice = 3,  ///< which trials fail (one stream for the dataset)
    FaultDetail = 4,  ///< index: the trial: kind and timing of its fault
    Noise = 5,        ///< index: the trial
};

/// SplitMix64's finaliser: a bijective mix of 64 bits ([SLF2014]).
std::uint64_t mix64(std::uint64_t x) noexcept;

class SeededRandom
{
  public:
    SeededRandom(std::uint64_t seed, RandomStream stream, std::uint64_t index = 0);

    std::uint64_t next() { return engine_(); }
    /// Uniform in [0, 1): the top 53 bits of one draw times 2^-53.
    double uniform();
    /// Uniform in [a, b).
    double uniform(double a, double b) { return a + (b - a) * uniform(); }
    /// Standard normal (Box-Muller; the second value of a pair is kept for the next call).
    double normal();
    /// Uniform integer in [0, n), n > 0, without modulo bias (rejection).
    std::uint64_t below(std::uint64_t n);

  private:
    std::mt19937_64 engine_;
    bool hasSpare_ = false;
    double spare_ = 0.0;
};

} // namespace rosin::discovery
