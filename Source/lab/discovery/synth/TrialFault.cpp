#include "lab/discovery/synth/TrialFault.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "core/gesture/GestureLimits.h"

namespace rosin::discovery
{

std::size_t failedTrialCount(std::size_t trials)
{
    if (trials < kTrialsForOneFailure)
        return 0;
    return std::max<std::size_t>(1, static_cast<std::size_t>(std::llround(kFailedShare * trials)));
}

std::vector<std::size_t> chooseFailedTrials(std::size_t trials, std::uint64_t seed)
{
    const std::size_t count = failedTrialCount(trials);
    std::vector<std::size_t> order(trials);
    std::iota(order.begin(), order.end(), std::size_t{0});
    // The first `count` steps of a Fisher-Yates shuffle pick `count` distinct trials uniformly.
    SeededRandom random(seed, RandomStream::FaultChoice);
    for (std::size_t i = 0; i < count; ++i)
        std::swap(order[i], order[i + random.below(trials - i)]);
    order.resize(count);
    std::sort(order.begin(), order.end());
    return order;
}

TrialFault drawTrialFault(std::uint64_t seed, std::size_t trial, double seconds)
{
    SeededRandom random(seed, RandomStream::FaultDetail, trial);
    TrialFault f;
    f.kind = random.below(2) == 0 ? TrialFault::Kind::CutShort : TrialFault::Kind::Dropout;
    if (f.kind == TrialFault::Kind::CutShort)
    {
        f.start = seconds * random.uniform(0.15, 0.6);
        return f;
    }
    f.start = seconds * random.uniform(0.1, 0.8);
    f.length = random.uniform(0.005, 0.03);
    return f;
}

void applyTrialFault(const TrialFault& fault, double sampleRate, std::vector<std::vector<double>>& channels)
{
    for (auto& channel : channels)
    {
        const std::size_t n = channel.size();
        // At least one frame stays: a file without samples is not a WAV file the spec allows.
        const auto first =
            std::clamp<std::size_t>(static_cast<std::size_t>(std::llround(fault.start * sampleRate)), 1, n);
        if (fault.kind == TrialFault::Kind::CutShort)
        {
            channel.resize(first);
            continue;
        }
        const auto last =
            std::min(n, first + static_cast<std::size_t>(std::llround(fault.length * sampleRate)));
        std::fill(channel.begin() + static_cast<std::ptrdiff_t>(first),
                  channel.begin() + static_cast<std::ptrdiff_t>(last), 0.0);
    }
}

std::string describeTrialFault(const TrialFault& fault)
{
    if (fault.kind == TrialFault::Kind::CutShort)
        return "cut short at " + physics::formatNumber(std::round(fault.start * 1e4) / 1e4) + " s";
    return "dropout " + physics::formatNumber(std::round(fault.start * 1e4) / 1e4) + "-" +
           physics::formatNumber(std::round((fault.start + fault.length) * 1e4) / 1e4) + " s";
}

} // namespace rosin::discovery
