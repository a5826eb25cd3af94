#pragma once
// Fitting numbers of a model to the training trials, shared by the effect fit (EffectSearch) and the
// calibration of the nuisance parameters (Calibration): the objective (GapSummary::objective over the
// training trials), memoised so no point is simulated twice; a grid over full ranges; a golden-section
// refinement of one coordinate around the best point. Points that differ only in the measurement chain's
// numbers (sensorGain, sensorBandwidth, sensorDelay) share the string's simulation (ModelRuns.h StringRuns).
// Coordinates are searched on a log scale where their EffectParameter says so; a choice is searched by the
// grid only. JUCE-free.
#include <cstddef>
#include <functional>
#include <list>
#include <map>
#include <vector>

#include "lab/discovery/EffectCatalog.h"
#include "lab/discovery/SimulationModel.h"
#include "lab/discovery/discover/ModelRuns.h"
#include "lab/discovery/discover/SearchInputs.h"

namespace rosin::discovery
{

/// Fitted values are reported (and adopted) to 3 significant digits, of the value or, on a linear scale, of
/// its range's width where that is finer (tension within 0.98-1.02: steps of 1e-4, 0.09 cents, not of 0.01,
/// 8.6 cents): no fit here is finer than that. A choice is returned as it is.
double roundToResolution(const EffectParameter& parameter, double value);

/// The model at a point: `values` in the order of the fit's coordinates.
using ModelBuilder = std::function<SimulationModel(const std::vector<double>& values)>;

class ModelFit
{
  public:
    /// `coordinates` give each value's range; `start` is the first best point (evaluated at once).
    ModelFit(const SearchInputs& inputs, std::vector<const EffectParameter*> coordinates, ModelBuilder build,
             const std::vector<double>& start);

    /// The training objective at `values` (simulated once per distinct point).
    double objective(const std::vector<double>& values);
    /// Every combination of `points` values per axis over the whole range of each coordinate in `axes` (all
    /// choices of a choice), the others at the best point; keeps the best.
    void grid(const std::vector<std::size_t>& axes, int points);
    /// Golden-section search of coordinate j over best +- halfWidth (search scale, within its range) with
    /// `evaluations` points; adopts the minimum when it beats the best point.
    void golden(std::size_t j, double halfWidth, int evaluations);
    /// The same around `centre` instead of the best point (still adopting only what beats the best point).
    void golden(std::size_t j, double halfWidth, int evaluations, const std::vector<double>& centre);
    /// The best point evaluated so far whose coordinate j equals `value` (a choice); best() if there is none.
    std::vector<double> bestWith(std::size_t j, double value) const;
    /// The width of coordinate j's range on its search scale.
    double span(std::size_t j) const;

    const std::vector<double>& best() const noexcept { return best_; }
    double bestValue() const noexcept { return bestValue_; }
    int evaluations() const noexcept { return evaluations_; }

  private:
    /// The string's simulations for `values`' physics (the values of the coordinates outside the chain):
    /// kept for the most recently used points, within kRunBudgetBytes.
    StringRuns& runsFor(const std::vector<double>& values);
    double toSearch(std::size_t j, double v) const;
    double fromSearch(std::size_t j, double x) const;

    const SearchInputs& in_;
    std::vector<const EffectParameter*> coordinates_;
    ModelBuilder build_;
    std::vector<double> best_;
    double bestValue_ = 0.0;
    int evaluations_ = 0;
    std::map<std::vector<double>, double> memo_;
    std::vector<bool> chain_; ///< coordinate j is one of the measurement chain's
    bool reusesRuns_ = false; ///< some coordinate is: points can share a simulation
    std::list<std::pair<std::vector<double>, StringRuns>> runs_; ///< most recently used first
    static constexpr std::size_t kRunBudgetBytes = std::size_t{128} << 20;
};

} // namespace rosin::discovery
