#include "lab/discovery/discover/ModelSensitivity.h"

#include <cmath>
#include <limits>

#include "lab/discovery/discover/ModelRuns.h"

namespace rosin::discovery
{

std::array<double, kFeatureCount> featureSensitivity(const TrialFeatures& nominal,
                                                     const std::vector<TrialFeatures>& nudged)
{
    std::array<double, kFeatureCount> s{};
    for (std::size_t f = 0; f < kFeatureCount; ++f)
        for (const auto& run : nudged)
        {
            if (run[f].has_value() != nominal[f].has_value())
            {
                s[f] = std::numeric_limits<double>::quiet_NaN();
                break;
            }
            if (run[f] && isCategorical(f) && *run[f] != *nominal[f])
            {
                s[f] = std::numeric_limits<double>::quiet_NaN(); // the category itself changes
                break;
            }
            if (run[f] && !isCategorical(f))
                s[f] = std::max(s[f], std::abs(*run[f] - *nominal[f]));
        }
    return s;
}

void addModelSensitivity(FeatureScatter& scatter, const SimulationModel& model, const Dataset& dataset,
                         const std::vector<std::size_t>& trials, const std::vector<TrialFeatures>& nominal,
                         const std::vector<double>& seconds, unsigned threads)
{
    const auto up = simulateFeatures(model, dataset, trials, seconds, threads,
                                     {1.0 + kSettingsNudge, 1.0 + kSettingsNudge});
    const auto down = simulateFeatures(model, dataset, trials, seconds, threads,
                                       {1.0 - kSettingsNudge, 1.0 - kSettingsNudge});
    scatter.sensitivity.assign(dataset.trials.size(), {});
    for (std::size_t t : trials)
        scatter.sensitivity[t] = featureSensitivity(nominal[t], {up[t], down[t]});
}

} // namespace rosin::discovery
