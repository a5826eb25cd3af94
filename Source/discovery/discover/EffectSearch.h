#pragma once
// The effect search of rosin discover (issue 5): every effect of the EffectCatalog is fitted on a training
// half of the trials and scored on the other half; the best significant one is adopted, and the search
// repeats on what remains (at most three effects).
//   Split: a checkerboard over the grid, (beta + force + motion index) even -> training, odd -> held out
//          (repeats of a cell stay together), so both halves cover the whole scan.
//   Fit:   a grid over the catalog's fit range (7 points for one parameter, 5 x 5 for two; log-spaced where
//          the catalog says so; every choice), then a golden-section refinement of each continuous parameter
//          around the best point (5 evaluations each); the values are rounded to 3 significant digits. The
//          objective is the training trials' mean z^2 averaged over features (GapSummary::objective). Each
//          evaluation simulates the training trials.
//   Score: held-out gain = 1 - sum e_i(with effect) / sum e_i(current model) over the held-out trials,
//          e_i a trial's share of the objective (objectiveShares), so the gain is the held-out objective's
//          relative fall. Significant when the paired sign-flip test gives p < 0.01 / (effects
//          tried) (Bonferroni over the candidates) AND the gain is at least 20 %.
//   Stop:  after three effects, when no candidate is significant, or when the held-out gap of the model with
//          the adopted effects is 0 (within the measurement's scatter on every feature).
// JUCE-free.
#include <cstdint>
#include <ostream>
#include <string>
#include <vector>

#include "FeatureScatter.h"
#include "GapMeasure.h"
#include "TrialFeatures.h"
#include "discovery/Dataset.h"
#include "discovery/EffectCatalog.h"
#include "discovery/ScanGrid.h"
#include "discovery/SimulationModel.h"

namespace rosin::discovery
{

inline constexpr double kSignificanceLevel = 0.01;
inline constexpr double kMinRelativeGain = 0.2;
inline constexpr std::size_t kMaxEffects = 3;

struct SearchInputs
{
    const Dataset* dataset = nullptr;
    const ScanGrid* grid = nullptr;
    std::vector<std::size_t> training, heldOut; ///< dataset trial indices
    std::vector<TrialFeatures> measured;        ///< indexed like dataset.trials
    FeatureScatter scatter;
    std::vector<double> seconds; ///< each trial's length, s
    unsigned threads = 1;
    std::uint64_t seed = 0;
    std::ostream* log = nullptr; ///< progress lines, or nullptr
};

/// The checkerboard split of the valid trials (grid cells) into training and held-out halves.
void splitTrials(const ScanGrid& grid, std::vector<std::size_t>& training, std::vector<std::size_t>& heldOut);

struct EffectScore
{
    const Effect* effect = nullptr;
    std::vector<double> values;
    int evaluations = 0;
    double heldOutGain = 0.0;
    double pValue = 1.0;
    bool significant = false;
    GapSummary heldOutBefore, heldOutAfter;
};

struct SearchStep
{
    EffectScore chosen;
    std::vector<EffectScore> tried; ///< every candidate of the step, in catalog order
    double alpha = kSignificanceLevel;
    SimulationModel model; ///< the model after the step (the effect applied)
};

struct SearchResult
{
    std::vector<SearchStep> steps;      ///< adopted effects, in order
    std::vector<EffectScore> lastTried; ///< candidates of the step that adopted nothing (empty if none)
    double lastAlpha = kSignificanceLevel;
    SimulationModel model; ///< baseline + adopted effects
};

SearchResult searchEffects(const SearchInputs& inputs, const SimulationModel& baseline);

/// Why the evidence points to the effect, in words (held-out features that improved, the test).
std::string describeEvidence(const EffectScore& score, double alpha);

} // namespace rosin::discovery
