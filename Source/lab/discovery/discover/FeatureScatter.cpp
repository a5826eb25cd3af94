#include "lab/discovery/discover/FeatureScatter.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <tuple>

namespace rosin::discovery
{

namespace
{
constexpr double kMadToSigma = 1.4826;

double median(std::vector<double> v)
{
    if (v.empty())
        return 0.0;
    std::sort(v.begin(), v.end());
    const std::size_t n = v.size();
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

double mad(const std::vector<double>& v)
{
    const double m = median(v);
    std::vector<double> dev;
    for (double x : v)
        dev.push_back(std::abs(x - m));
    return median(dev);
}

// Root mean square after dropping the largest 10 % in magnitude (a regime boundary crossing the grid).
double trimmedRms(std::vector<double> v)
{
    std::sort(v.begin(), v.end(), [](double a, double b) { return std::abs(a) < std::abs(b); });
    const std::size_t keep = v.size() - v.size() / 10;
    double sum = 0.0;
    for (std::size_t k = 0; k < keep; ++k)
        sum += v[k] * v[k];
    return keep > 0 ? std::sqrt(sum / static_cast<double>(keep)) : 0.0;
}

std::optional<double> pooledRepeats(const ScanGrid& grid, const std::vector<TrialFeatures>& measured,
                                    std::size_t f)
{
    double sum = 0.0;
    std::size_t dof = 0;
    for (const auto& cell : grid.cells)
    {
        std::vector<double> v;
        for (std::size_t t : cell.trials)
            if (measured[t][f])
                v.push_back(*measured[t][f]);
        if (v.size() < 2)
            continue;
        double mean = 0.0;
        for (double x : v)
            mean += x / static_cast<double>(v.size());
        for (double x : v)
            sum += (x - mean) * (x - mean);
        dof += v.size() - 1;
    }
    if (dof < 5)
        return std::nullopt;
    return std::sqrt(sum / static_cast<double>(dof));
}

std::vector<double> secondDifferences(const ScanGrid& grid, const std::vector<TrialFeatures>& measured,
                                      std::size_t f)
{
    // Cell means by (beta, force, motion) index.
    std::map<std::tuple<std::size_t, std::size_t, std::size_t>, double> value;
    for (const auto& cell : grid.cells)
    {
        double sum = 0.0;
        int n = 0;
        for (std::size_t t : cell.trials)
            if (measured[t][f])
            {
                sum += *measured[t][f];
                ++n;
            }
        if (n > 0)
            value[{cell.beta, cell.force, cell.motion}] = sum / n;
    }
    auto at = [&](std::size_t b, long i, long m) -> std::optional<double>
    {
        if (i < 0 || m < 0)
            return std::nullopt;
        auto it = value.find({b, static_cast<std::size_t>(i), static_cast<std::size_t>(m)});
        return it == value.end() ? std::nullopt : std::optional<double>(it->second);
    };
    std::vector<double> d2;
    for (const auto& [key, centre] : value)
    {
        const auto [b, i, m] = key;
        const long li = static_cast<long>(i), lm = static_cast<long>(m);
        if (auto lo = at(b, li - 1, lm), hi = at(b, li + 1, lm); lo && hi)
            d2.push_back(*lo - 2.0 * centre + *hi);
        if (auto lo = at(b, li, lm - 1), hi = at(b, li, lm + 1); lo && hi)
            d2.push_back(*lo - 2.0 * centre + *hi);
    }
    return d2;
}

// A category's scatter: the share of pairs that disagree, among repeats in one cell (at least 5 pairs) or
// else among cells adjacent along the force or motion axis (each cell by its first valid trial).
std::optional<std::pair<double, const char*>>
mismatchRate(const ScanGrid& grid, const std::vector<TrialFeatures>& measured, std::size_t f)
{
    std::size_t pairs = 0, differ = 0;
    std::map<std::tuple<std::size_t, std::size_t, std::size_t>, double> first;
    for (const auto& cell : grid.cells)
    {
        std::vector<double> v;
        for (std::size_t t : cell.trials)
            if (measured[t][f])
                v.push_back(*measured[t][f]);
        for (std::size_t a = 0; a < v.size(); ++a)
            for (std::size_t b = a + 1; b < v.size(); ++b)
                ++pairs, differ += v[a] != v[b] ? 1 : 0;
        if (!v.empty())
            first[{cell.beta, cell.force, cell.motion}] = v.front();
    }
    if (pairs >= 5)
        return std::pair{static_cast<double>(differ) / static_cast<double>(pairs), "repeats"};
    pairs = differ = 0;
    for (const auto& [key, value] : first)
    {
        const auto [b, i, m] = key;
        for (const auto& next : {std::tuple{b, i + 1, m}, std::tuple{b, i, m + 1}})
            if (auto it = first.find(next); it != first.end())
                ++pairs, differ += it->second != value ? 1 : 0;
    }
    if (pairs >= 5)
        return std::pair{static_cast<double>(differ) / static_cast<double>(pairs), "neighbours"};
    return std::nullopt;
}
} // namespace

FeatureScatter measureScatter(const ScanGrid& grid, const std::vector<TrialFeatures>& measured,
                              double sampleRate)
{
    FeatureScatter s;
    for (std::size_t f = 0; f < kFeatureCount; ++f)
    {
        double sigma = 0.0;
        if (isCategorical(f))
        {
            const auto rate = mismatchRate(grid, measured, f);
            s.sigma[f] = std::max(rate ? rate->first : 1.0, kMinMismatchRate);
            s.method[f] = !rate ? "none" : rate->first < kMinMismatchRate ? "resolution" : rate->second;
            continue;
        }
        if (auto r = pooledRepeats(grid, measured, f))
        {
            sigma = *r;
            s.method[f] = "repeats";
        }
        else if (auto d2 = secondDifferences(grid, measured, f); d2.size() >= 4)
        {
            sigma = std::max(kMadToSigma * mad(d2), trimmedRms(d2)) / std::sqrt(6.0);
            s.method[f] = "neighbours";
        }
        else
        {
            std::vector<double> all;
            for (const auto& t : measured)
                if (t[f])
                    all.push_back(*t[f]);
            sigma = kMadToSigma * mad(all);
            s.method[f] = "spread";
        }
        const double floor = featureResolution(f, sampleRate);
        if (!(sigma >= floor))
        {
            sigma = floor;
            s.method[f] = "resolution";
        }
        s.sigma[f] = sigma;
    }
    return s;
}

double FeatureScatter::trialSigma(std::size_t trial, std::size_t feature) const noexcept
{
    if (trial >= sensitivity.size())
        return sigma[feature];
    const double s = sensitivity[trial][feature];
    return std::sqrt(sigma[feature] * sigma[feature] + s * s);
}

} // namespace rosin::discovery
