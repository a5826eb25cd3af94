#include "Calibration.h"

#include <algorithm>
#include <cstdio>
#include <numeric>

#include "ModelFit.h"

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
    for (std::size_t j = 0; j < ps.size(); ++j)
    {
        // The prior's ends: how much the data care about this one.
        std::vector<double> low = fit.best(), high = fit.best();
        low[j] = ps[j].prior.min, high[j] = ps[j].prior.max;
        const double here = fit.bestValue(), atLow = fit.objective(low), atHigh = fit.objective(high);
        r.swing.push_back(std::max({here, atLow, atHigh}) - std::min({here, atLow, atHigh}));
        // One the data do not constrain stays where it is (nominal, or a prior end that was better).
        if (r.swing.back() > kActiveSwing * here)
            fit.golden(j, 0.5 * fit.span(j), 3);
    }
    std::vector<std::size_t> order(ps.size());
    std::iota(order.begin(), order.end(), 0);
    std::sort(order.begin(), order.end(),
              [&r](std::size_t a, std::size_t b) { return r.swing[a] > r.swing[b]; });
    for (std::size_t j : order)
        if (r.active.size() < kMaxActive && r.swing[j] > kActiveSwing * fit.bestValue())
            r.active.push_back(j);
    std::vector<double> best = fit.best();
    for (std::size_t j = 0; j < ps.size(); ++j)
        if (best[j] != ps[j].nominal())
            best[j] = roundToThreeDigits(ps[j].prior, best[j]);
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
