#include "core/analysis/SlipOnsets.h"

#include <algorithm>
#include <cmath>
#include <set>

namespace rosin::analysis
{

namespace
{
// Largest (or, with less = greater, smallest) value of x within +-radius of each sample: a monotonic queue
// of indices (each enters and leaves once, O(n)), kept in a plain array: with std::deque this search was 7 %
// of a rosin discover run's profile.
template <typename Better>
std::vector<double> slidingExtreme(const std::vector<double>& x, std::size_t radius, Better better)
{
    const std::size_t n = x.size();
    std::vector<double> out(n);
    std::vector<std::size_t> q(n); // q[head, tail): indices whose values are in `better` order
    std::size_t head = 0, tail = 0;
    std::size_t next = 0; // next index to enter the window
    for (std::size_t k = 0; k < n; ++k)
    {
        const std::size_t hi = std::min(n - 1, k + radius);
        for (; next <= hi; ++next)
        {
            while (tail > head && !better(x[q[tail - 1]], x[next]))
                --tail;
            q[tail++] = next;
        }
        const std::size_t lo = k > radius ? k - radius : 0;
        while (q[head] < lo)
            ++head;
        out[k] = x[q[head]];
    }
    return out;
}
} // namespace

std::vector<SlipEpisode> slipEpisodesFromState(const std::vector<bool>& sticking)
{
    std::vector<SlipEpisode> episodes;
    for (std::size_t k = 1; k < sticking.size(); ++k)
    {
        if (sticking[k])
            continue;
        if (sticking[k - 1])
            episodes.push_back({k, 0, true});
        if (!episodes.empty())
            ++episodes.back().duration;
    }
    return episodes;
}

std::vector<SlipEpisode> slipEpisodesFromVoice(const std::vector<physics::VoiceSample>& samples)
{
    std::vector<SlipEpisode> episodes;
    for (std::size_t k = 1; k < samples.size(); ++k)
    {
        const auto& s = samples[k];
        if (s.sticking)
            continue;
        if (samples[k - 1].sticking)
            episodes.push_back({k, 0, false, 0.0, std::abs(s.bowVelocity)});
        if (episodes.empty())
            continue; // a run under way at sample 0
        auto& e = episodes.back();
        ++e.duration;
        const double slip = std::abs(s.bowPointVelocity - s.bowVelocity);
        e.peakSlipSpeed = std::max(e.peakSlipSpeed, slip);
        if (slip > std::abs(s.bowVelocity))
            e.flyback = true;
    }
    return episodes;
}

ForceAndState forceAndState(const std::vector<physics::VoiceSample>& samples)
{
    ForceAndState out;
    out.bridgeForce.resize(samples.size());
    out.sticking.resize(samples.size());
    for (std::size_t k = 0; k < samples.size(); ++k)
    {
        out.bridgeForce[k] = samples[k].bridgeForce;
        out.sticking[k] = samples[k].sticking;
    }
    return out;
}

std::vector<SlipEpisode> slipEpisodesFromRelativeVelocity(const std::vector<double>& relativeVelocity,
                                                          double threshold,
                                                          const std::vector<double>& bowVelocity)
{
    const bool knowBow = bowVelocity.size() == relativeVelocity.size();
    std::vector<SlipEpisode> episodes;
    bool wasSliding = relativeVelocity.empty() ? false : std::abs(relativeVelocity[0]) > threshold;
    bool inRun = false; // inside a run whose onset was seen
    for (std::size_t k = 1; k < relativeVelocity.size(); ++k)
    {
        const bool sliding = std::abs(relativeVelocity[k]) > threshold;
        if (sliding && !wasSliding)
        {
            episodes.push_back({k, 0, !knowBow, 0.0, knowBow ? std::abs(bowVelocity[k]) : 0.0});
            inRun = true;
        }
        if (!sliding)
            inRun = false;
        if (sliding && inRun)
        {
            auto& e = episodes.back();
            ++e.duration;
            e.peakSlipSpeed = std::max(e.peakSlipSpeed, std::abs(relativeVelocity[k]));
            if (knowBow && std::abs(relativeVelocity[k]) > std::abs(bowVelocity[k]))
                e.flyback = true;
        }
        wasSliding = sliding;
    }
    return episodes;
}

std::vector<SlipEpisode> flybacksOnly(const std::vector<SlipEpisode>& episodes)
{
    std::vector<SlipEpisode> out;
    std::copy_if(episodes.begin(), episodes.end(), std::back_inserter(out),
                 [](const SlipEpisode& e) { return e.flyback; });
    return out;
}

std::vector<SlipEpisode> fullFlybacksOnly(const std::vector<SlipEpisode>& episodes, double beta, double share)
{
    std::vector<SlipEpisode> out;
    std::copy_if(episodes.begin(), episodes.end(), std::back_inserter(out),
                 [=](const SlipEpisode& e)
                 {
                     const bool measured = e.peakSlipSpeed > 0.0 || e.bowSpeedAtOnset > 0.0;
                     return e.flyback && (!measured || e.peakSlipSpeed >= share * e.bowSpeedAtOnset / beta);
                 });
    return out;
}

std::vector<std::size_t> onsetsOf(const std::vector<SlipEpisode>& episodes)
{
    std::vector<std::size_t> out;
    out.reserve(episodes.size());
    for (const auto& e : episodes)
        out.push_back(e.onset);
    return out;
}

double slipFraction(const std::vector<bool>& sticking, std::size_t begin, std::size_t end)
{
    end = std::min(end, sticking.size());
    if (begin >= end)
        return 0.0;
    const auto sliding = std::count(sticking.begin() + static_cast<std::ptrdiff_t>(begin),
                                    sticking.begin() + static_cast<std::ptrdiff_t>(end), false);
    return static_cast<double>(sliding) / static_cast<double>(end - begin);
}

std::vector<double> bandLimitedFall(const std::vector<double>& x, std::size_t span)
{
    span = std::max<std::size_t>(1, span);
    const std::size_t n = x.size();
    std::vector<double> fall(n, 0.0);
    if (n < 2 * span)
        return fall;
    // Prefix sums make each difference of means O(1).
    std::vector<double> prefix(n + 1, 0.0);
    for (std::size_t k = 0; k < n; ++k)
        prefix[k + 1] = prefix[k] + x[k];
    const double inv = 1.0 / static_cast<double>(span);
    for (std::size_t k = span; k + span <= n; ++k)
        fall[k] = ((prefix[k] - prefix[k - span]) - (prefix[k + span] - prefix[k])) * inv;
    return fall;
}

std::vector<std::size_t> slipOnsetsFromBridgeForce(const std::vector<double>& bridgeForce,
                                                   double periodSamples, const ForceOnsetOptions& o)
{
    std::vector<std::size_t> onsets;
    const std::size_t n = bridgeForce.size();
    if (!(periodSamples > 0.0) || n < 4)
        return onsets;
    const auto span = static_cast<std::size_t>(std::max(1.0, std::round(o.spanPeriods * periodSamples)));
    const auto radius =
        static_cast<std::size_t>(std::max(1.0, std::round(o.localWindowPeriods * periodSamples)));
    const auto fall = bandLimitedFall(bridgeForce, span);
    const auto largestFall = slidingExtreme(fall, radius, [](double a, double b) { return a > b; });
    const auto highest = slidingExtreme(bridgeForce, radius, [](double a, double b) { return a > b; });
    const auto lowest = slidingExtreme(bridgeForce, radius, [](double a, double b) { return a < b; });
    // White noise of rms s gives a difference of two span-means with rms s sqrt(2/span).
    const double noiseFloor = o.noiseFactor * o.noiseRms * std::sqrt(2.0 / static_cast<double>(span));

    struct Candidate
    {
        std::size_t k;
        double fall;
    };
    std::vector<Candidate> candidates;
    for (std::size_t k = 1; k + 1 < n; ++k)
    {
        const double f = fall[k];
        if (!(f > 0.0) || f < fall[k - 1] || f <= fall[k + 1])
            continue; // not a local peak of the fall
        const double threshold = std::max(
            {o.relativeThreshold * largestFall[k], o.minFallOfRange * (highest[k] - lowest[k]), noiseFloor});
        if (f >= threshold)
            candidates.push_back({k, f});
    }
    // Largest falls first; a smaller one within the refractory interval of an accepted one is its ripple.
    std::stable_sort(candidates.begin(), candidates.end(),
                     [](const Candidate& a, const Candidate& b) { return a.fall > b.fall; });
    const double refractory = o.refractoryPeriods * periodSamples;
    std::set<std::size_t> accepted;
    for (const auto& c : candidates)
    {
        const auto after = accepted.lower_bound(c.k);
        if (after != accepted.end() && static_cast<double>(*after - c.k) < refractory)
            continue;
        if (after != accepted.begin() && static_cast<double>(c.k - *std::prev(after)) < refractory)
            continue;
        accepted.insert(c.k);
    }
    onsets.assign(accepted.begin(), accepted.end());
    return onsets;
}

} // namespace rosin::analysis
