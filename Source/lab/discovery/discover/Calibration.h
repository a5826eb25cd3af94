#pragma once
// Calibration before attribution: the nuisance parameters (NuisanceParameters.h) fitted to
// the training trials within their priors, before any effect is tried, so each candidate effect competes
// against a baseline that is as right as the lab's tolerances allow, not against one that is off for
// reasons that have nothing to do with it.
//   Search: coordinate descent from nominal, largest effect first. A screening pass first simulates each
//           parameter's prior ends with the others nominal; the parameters are then fitted in the order of
//           that screening swing, because an early, weakly constrained one can otherwise mimic a strongly
//           constrained one and trap the descent (a smaller contact flattens the Helmholtz pitch a little, as
//           a lower tension does: fitted first, it held at its stated tension a foreign string whose pitch
//           lay 9-10 cents sharp of the model). Each parameter in turn: its prior's two ends from the current
//           point, then, if the data care (below), a golden-section search (4 points) around the best of the
//           three. Last, the active ones are polished once more (3 points over +-15 % of their prior) now
//           that all are in place.
//           53-70 simulations of the training half in the datasets tried.
//   Active: the parameters the data constrain: the training objective moved by more than 2 % of its value
//           there (as calibrated so far) across the prior, at most kMaxActive, largest first. Only these
//           are fitted again together with each candidate effect (EffectSearch), which keeps a search short.
// JUCE-free.
#include <cstddef>
#include <vector>

#include "lab/discovery/NuisanceParameters.h"
#include "lab/discovery/SimulationModel.h"
#include "lab/discovery/discover/SearchInputs.h"

namespace rosin::discovery
{

inline constexpr std::size_t kMaxActive = 3;
inline constexpr double kActiveSwing = 0.02;

struct CalibrationResult
{
    NuisanceValues values;           ///< the calibrated nuisance parameters
    std::vector<double> screening;   ///< per nuisance parameter: the objective's range over it at nominal
    std::vector<double> swing;       ///< per nuisance parameter: the training objective's range over it
    std::vector<std::size_t> active; ///< indices into nuisanceParameters(), largest swing first
    double objectiveBefore = 0.0;    ///< training objective at nominal
    double objectiveAfter = 0.0;     ///< and calibrated
    int evaluations = 0;
};

/// Calibrates `model`'s nuisance values on inputs.training (the model's other parts stay as they are).
CalibrationResult calibrate(const SearchInputs& inputs, const SimulationModel& model);

/// The nuisance values of `values` (in nuisanceParameters() order) written into `model`.
void setNuisance(SimulationModel& model, const std::vector<double>& values);
/// The model's nuisance values in nuisanceParameters() order.
std::vector<double> nuisanceVector(const SimulationModel& model);

} // namespace rosin::discovery
