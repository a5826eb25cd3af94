#include "lab/discovery/discover/Calibration.h"

#include <algorithm>
#include <cstdio>
#include <numeric>

#include "lab/discovery/discover/ModelFit.h"

namespace rosin::discovery
{

void setNuisance(SimulationModel& model, const std::vector<double>& values)
{
    const auto& ps = nuisanceParameters();
    for (std::size_t j = 0; j < ps.size() && j < values.size(); ++j)
        model.nuisance.*ps[j].value = values[j];
}

std::vector<double> nuisanceVector(const SimulationModel& model)
{
    std::vector<double> v;
    for (const auto& p : nuisanceParameters())
        v.push_back(model.nuisance.*p.value);
    return v;
}

namespace
{
// The objective's range over {here, prior min, prior max} of coordinate j, the others at `at`.
double swingAt(ModelFit& fit, std::vector<double> at, std::size_t j, double here)
{
    const auto& prior = nuisanceParameters()[j].prior;
    at[j] = prior.min;
    const double atLow = fit.objective(at);
    at[j] = prior.max;
    const double atHigh = fit.objective(at);
    return std::max({here, atLow, atHigh}) - std::min({here, atLow, atHigh});
}

// Indices 0..n-1 ordered by `key`, largest first (ties keep the catalog's order).
std::vector<std::size_t> largestFirst(const std::vector<double>& key)
{
    std::vector<std::size_t> order(key.size());
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(order.begin(), order.end(),
                     [&key](std::size_t a, std::size_t b) { return key[a] > key[b]; });
    return order;
}
} // namespace

CalibrationResult calibrate(const SearchInputs& in, const SimulationModel& model)
{
    const auto& ps = nuisanceParameters();
    std::vector<const EffectParameter*> coordinates;
    for (const auto& p : ps)
        coordinates.push_back(&p.prior);
    ModelFit fit(
        in, coordinates,
        [&model](const std::vector<double>& v)
        {
            SimulationModel m = model;
            setNuisance(m, v);
            return m;
        },
        nuisanceVector(model));
    CalibrationResult r;
    r.objectiveBefore = fit.bestValue();
    const std::vector<double> nominal = fit.best();
    for (std::size_t j = 0; j < ps.size(); ++j)
        r.screening.push_back(swingAt(fit, nominal, j, r.objectiveBefore));
    r.swing.assign(ps.size(), 0.0);
    for (std::size_t j : largestFirst(r.screening))
    {
        // The prior's ends from where the descent stands: how much the data care about this one there.
        r.swing[j] = swingAt(fit, fit.best(), j, fit.bestValue());
        // One the data do not constrain stays where it is (nominal, or a prior end that was better).
        if (r.swing[j] > kActiveSwing * fit.bestValue())
            fit.golden(j, 0.5 * fit.span(j), 4);
    }
    for (std::size_t j : largestFirst(r.swing))
        if (r.active.size() < kMaxActive && r.swing[j] > kActiveSwing * fit.bestValue())
            r.active.push_back(j);
    for (std::size_t j : r.active)
        fit.golden(j, 0.15 * fit.span(j), 3);
    std::vector<double> best = fit.best();
    for (std::size_t j = 0; j < ps.size(); ++j)
        if (best[j] != ps[j].nominal())
            best[j] = roundToResolution(ps[j].prior, best[j]);
    SimulationModel calibrated = model;
    setNuisance(calibrated, best);
    r.values = calibrated.nuisance;
    r.objectiveAfter = fit.bestValue();
    r.evaluations = fit.evaluations();
    if (in.log)
    {
        char line[160];
        std::snprintf(line, sizeof(line),
                      "calibration: training objective %.3g -> %.3g (%d fits): ", r.objectiveBefore,
                      r.objectiveAfter, r.evaluations);
        *in.log << line << describeNuisance(r.values) << "\n" << std::flush;
    }
    return r;
}

} // namespace rosin::discovery
