#pragma once
// Calibration before attribution (issue 16 item 1): the nuisance parameters (NuisanceParameters.h) fitted to
// the training trials within their priors, before any effect is tried, so each candidate effect competes
// against a baseline that is as right as the lab's tolerances allow, not against one that is off for
// reasons that have nothing to do with it.
//   Search: coordinate descent from nominal. Each parameter in turn: its prior's two ends, then, if the
//           data care (below), a golden-section search (3 points) around the best of the three (the active
//           ones are refined again with each candidate effect). 15-36 simulations of the training half.
//   Active: the parameters the data constrain: the training objective moved by more than 2 % of its value
//           there (as calibrated so far) across the prior, at most kMaxActive, largest first. Only these
//           are fitted again together with each candidate effect (EffectSearch), which keeps a search short.
// JUCE-free.
#include <cstddef>
#include <vector>

#include "SearchInputs.h"
#include "discovery/NuisanceParameters.h"
#include "discovery/SimulationModel.h"

namespace rosin::discovery
{

inline constexpr std::size_t kMaxActive = 3;
inline constexpr double kActiveSwing = 0.02;

struct CalibrationResult
{
    NuisanceValues values;           ///< the calibrated nuisance parameters
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
