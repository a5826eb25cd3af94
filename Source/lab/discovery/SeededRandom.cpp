#include "lab/discovery/SeededRandom.h"

#include <cmath>
#include <limits>
#include <numbers>

namespace rosin::discovery
{

std::uint64_t mix64(std::uint64_t x) noexcept
{
    x += 0x9E3779B97F4A7C15ull;
    x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ull;
    x = (x ^ (x >> 27)) * 0x94D049BB133111EBull;
    return x ^ (x >> 31);
}

SeededRandom::SeededRandom(std::uint64_t seed, RandomStream stream, std::uint64_t index)
    // Chained mixes, so (seed, stream, index) triples that differ anywhere start far apart.
    : engine_(mix64(mix64(mix64(seed) ^ static_cast<std::uint64_t>(stream)) ^ index))
{
}

double SeededRandom::uniform()
{
    return static_cast<double>(engine_() >> 11) * 0x1.0p-53;
}

double SeededRandom::normal()
{
    if (hasSpare_)
    {
        hasSpare_ = false;
        return spare_;
    }
    // 1 - u lies in (0, 1], so the logarithm is finite.
    const double r = std::sqrt(-2.0 * std::log(1.0 - uniform()));
    const double phi = 2.0 * std::numbers::pi * uniform();
    spare_ = r * std::sin(phi);
    hasSpare_ = true;
    return r * std::cos(phi);
}

std::uint64_t SeededRandom::below(std::uint64_t n)
{
    // Accept only draws below the largest multiple of n, so every residue is equally likely.
    const std::uint64_t max = std::numeric_limits<std::uint64_t>::max();
    const std::uint64_t limit = max - (max % n + 1) % n;
    std::uint64_t x = engine_();
    while (x > limit)
        x = engine_();
    return x % n;
}

} // namespace rosin::discovery
