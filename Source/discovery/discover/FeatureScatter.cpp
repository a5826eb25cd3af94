#include "FeatureScatter.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <optional>
#include <tuple>

namespace rosin::discovery
{

namespace
{
constexpr double kMadToSigma = 1.4826;
constexpr std::size_t kMinLocalDifferences = 8; ///< second differences a row's own scatter needs

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

struct SecondDifference
{
    std::size_t motion; ///< the centre cell's motion index
    double value;
};

std::vector<SecondDifference> secondDifferences(const ScanGrid& grid,
                                                const std::vector<TrialFeatures>& measured, std::size_t f)
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
    std::vector<SecondDifference> d2;
    for (const auto& [key, centre] : value)
    {
        const auto [b, i, m] = key;
        const long li = static_cast<long>(i), lm = static_cast<long>(m);
        if (auto lo = at(b, li - 1, lm), hi = at(b, li + 1, lm); lo && hi)
            d2.push_back({m, *lo - 2.0 * centre + *hi});
        if (auto lo = at(b, li, lm - 1), hi = at(b, li, lm + 1); lo && hi)
            d2.push_back({m, *lo - 2.0 * centre + *hi});
    }
    return d2;
}

double sigmaFromSecondDifferences(const std::vector<double>& d2)
{
    return std::max(kMadToSigma * mad(d2), trimmedRms(d2)) / std::sqrt(6.0);
}

// Per motion index: the scatter of the second differences centred on that row and its two neighbours, where
// there are at least kMinLocalDifferences of them; NaN elsewhere.
std::vector<double> rowSigmas(const std::vector<SecondDifference>& d2, std::size_t rows)
{
    std::vector<double> out(rows, std::numeric_limits<double>::quiet_NaN());
    for (std::size_t m = 0; m < rows; ++m)
    {
        std::vector<double> near;
        for (const auto& d : d2)
            if (d.motion + 1 >= m && d.motion <= m + 1)
                near.push_back(d.value);
        if (near.size() >= kMinLocalDifferences)
            out[m] = sigmaFromSecondDifferences(near);
    }
    return out;
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

// Where a row of the grid scatters more than the whole (a feature whose noise grows as its trials shorten),
// its trials get that row's scatter.
void addRowScatter(FeatureScatter& s, const ScanGrid& grid, std::size_t f, const std::vector<double>& rows,
                   double global)
{
    for (const auto& cell : grid.cells)
        for (std::size_t t : cell.trials)
        {
            const double local = cell.motion < rows.size() ? rows[cell.motion] : global;
            if (!(local > global))
                continue;
            if (s.local.size() <= t)
                s.local.resize(t + 1);
            s.local[t][f] = local;
        }
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
            std::vector<double> values;
            for (const auto& d : d2)
                values.push_back(d.value);
            sigma = sigmaFromSecondDifferences(values);
            s.method[f] = "neighbours";
            addRowScatter(s, grid, f, rowSigmas(d2, std::max<std::size_t>(1, grid.motion.size())), sigma);
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
    const double own = trial < local.size() && local[trial][feature] > sigma[feature] ? local[trial][feature]
                                                                                      : sigma[feature];
    if (trial >= sensitivity.size())
        return own;
    const double s = sensitivity[trial][feature];
    return std::sqrt(own * own + s * s);
}

} // namespace rosin::discovery
