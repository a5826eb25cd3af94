#include "lab/discovery/discover/ModelFit.h"

#include <algorithm>
#include <cmath>

#include "lab/discovery/discover/GapMeasure.h"
#include "lab/discovery/discover/ModelRuns.h"

namespace rosin::discovery
{

ModelFit::ModelFit(const SearchInputs& inputs, std::vector<const EffectParameter*> coordinates,
                   ModelBuilder build, const std::vector<double>& start)
    : in_(inputs), coordinates_(std::move(coordinates)), build_(std::move(build))
{
    for (const EffectParameter* c : coordinates_)
        chain_.push_back(isMeasurementChain(*c));
    reusesRuns_ = std::find(chain_.begin(), chain_.end(), true) != chain_.end();
    bestValue_ = 1e300;
    objective(start);
}

double ModelFit::objective(const std::vector<double>& values)
{
    if (auto it = memo_.find(values); it != memo_.end())
        return it->second;
    const auto sim = simulateFeatures(build_(values), *in_.dataset, in_.training, in_.seconds, in_.threads,
                                      {}, reusesRuns_ ? &runsFor(values) : nullptr);
    ++evaluations_;
    const double o = fitGap(in_.training, in_.measured, sim, in_.scatter, in_.reference).objective;
    if (o < bestValue_)
    {
        bestValue_ = o;
        best_ = values;
    }
    return memo_[values] = o;
}

StringRuns& ModelFit::runsFor(const std::vector<double>& values)
{
    std::vector<double> physics;
    for (std::size_t j = 0; j < values.size(); ++j)
        if (!chain_[j])
            physics.push_back(values[j]);
    auto it =
        std::find_if(runs_.begin(), runs_.end(), [&physics](const auto& r) { return r.first == physics; });
    if (it != runs_.end())
        runs_.splice(runs_.begin(), runs_, it);
    else
        runs_.emplace_front(std::move(physics), StringRuns{});
    // The runs of the points used longest ago go first; the newest always stays (it is about to be filled).
    std::size_t bytes = 0;
    for (auto r = runs_.begin(); r != runs_.end(); ++r)
    {
        for (const auto& run : r->second)
            bytes += run.bytes();
        if (bytes > kRunBudgetBytes && r != runs_.begin())
        {
            runs_.erase(r, runs_.end());
            break;
        }
    }
    return runs_.front().second;
}

// To 3 significant digits of the value or of a linear prior's width (ModelFit.h).
double roundToResolution(const EffectParameter& p, double v)
{
    if (!p.choices.empty() || v == 0.0)
        return v;
    // 10^k with k the exponent of x's third significant digit, as a power of ten to multiply by (exact for
    // the decimal digits that matter, unlike a step of 1e-4).
    auto perThirdDigit = [](double x) { return std::pow(10.0, 2.0 - std::floor(std::log10(std::abs(x)))); };
    double scale = perThirdDigit(v);
    if (!p.logarithmic && p.max > p.min)
        scale = std::max(scale, perThirdDigit(p.max - p.min));
    return std::clamp(std::round(v * scale) / scale, p.min, p.max);
}

double ModelFit::toSearch(std::size_t j, double v) const
{
    return coordinates_[j]->logarithmic ? std::log(v) : v;
}

double ModelFit::fromSearch(std::size_t j, double x) const
{
    const auto& p = *coordinates_[j];
    return std::clamp(p.logarithmic ? std::exp(x) : x, p.min, p.max);
}

double ModelFit::span(std::size_t j) const
{
    return toSearch(j, coordinates_[j]->max) - toSearch(j, coordinates_[j]->min);
}

void ModelFit::grid(const std::vector<std::size_t>& axes, int points)
{
    std::vector<std::vector<double>> values;
    for (std::size_t j : axes)
    {
        const auto& p = *coordinates_[j];
        std::vector<double> axis;
        if (!p.choices.empty())
            for (std::size_t c = 0; c < p.choices.size(); ++c)
                axis.push_back(static_cast<double>(c));
        else
            for (int k = 0; k < points; ++k)
                axis.push_back(fromSearch(j, toSearch(j, p.min) + span(j) * k / (points - 1)));
        values.push_back(axis);
    }
    const std::vector<double> centre = best_;
    std::vector<std::size_t> index(axes.size(), 0);
    for (;;)
    {
        std::vector<double> point = centre;
        for (std::size_t a = 0; a < axes.size(); ++a)
            point[axes[a]] = values[a][index[a]];
        objective(point);
        std::size_t a = 0;
        while (a < axes.size() && ++index[a] == values[a].size())
            index[a++] = 0;
        if (a == axes.size())
            break;
    }
}

void ModelFit::golden(std::size_t j, double halfWidth, int evaluations)
{
    golden(j, halfWidth, evaluations, std::vector<double>(best_));
}

std::vector<double> ModelFit::bestWith(std::size_t j, double value) const
{
    const std::vector<double>* found = nullptr;
    double lowest = 0.0;
    for (const auto& [point, objective] : memo_)
        if (point[j] == value && (!found || objective < lowest))
            found = &point, lowest = objective;
    return found ? *found : best_;
}

void ModelFit::golden(std::size_t j, double halfWidth, int evaluations, const std::vector<double>& centre)
{
    const auto& p = *coordinates_[j];
    const double x0 = toSearch(j, centre[j]);
    double a = std::max(toSearch(j, p.min), x0 - halfWidth), b = std::min(toSearch(j, p.max), x0 + halfWidth);
    auto at = [&](double x)
    {
        std::vector<double> v = centre;
        v[j] = fromSearch(j, x);
        return objective(v); // adopts the point if it is the best so far
    };
    const double r = 0.5 * (std::sqrt(5.0) - 1.0);
    double c = b - r * (b - a), d = a + r * (b - a);
    double fc = at(c), fd = at(d);
    for (int k = 0; k < evaluations - 2; ++k)
        if (fc < fd)
        {
            b = d, d = c, fd = fc;
            c = b - r * (b - a);
            fc = at(c);
        }
        else
        {
            a = c, c = d, fc = fd;
            d = a + r * (b - a);
            fd = at(d);
        }
}

} // namespace rosin::discovery
