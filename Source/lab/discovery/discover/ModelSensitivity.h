#pragma once
// How far each simulated feature moves when a trial's settings move within a bowing machine's accuracy.
// A bowed attack near a regime boundary is chaotic: 2 % more force can turn a 5-period transient into a
// 14-period one, or give Helmholtz motion where there was none. Neither the measurement nor the model can
// then be compared trial by trial, and the measurement's scatter between neighbouring cells (FeatureScatter)
// does not see it. So the baseline is simulated twice more with the nominal force and acceleration (or
// speed) both scaled by 1 + kSettingsNudge and by 1 - kSettingsNudge; per trial and feature the larger of
// the two departures from the nominal run is the model's sensitivity, added in quadrature to the scatter,
// and a feature that appears or vanishes under the nudge (or a category, the regime, that changes) is not
// compared in that trial at all.
// The 2 % is an assumption about the rigs, not a fit: bowing machines hold force and speed to about 1-3 %.
// JUCE-free.
#include <cstddef>
#include <vector>

#include "lab/discovery/Dataset.h"
#include "lab/discovery/SimulationModel.h"
#include "lab/discovery/discover/FeatureScatter.h"
#include "lab/discovery/discover/TrialFeatures.h"

namespace rosin::discovery
{

inline constexpr double kSettingsNudge = 0.02;

/// Fills scatter.sensitivity for the trials `trials` from the model's features at the nominal settings
/// (`nominal`, indexed like dataset.trials) and two nudged runs of `model`.
void addModelSensitivity(FeatureScatter& scatter, const SimulationModel& model, const Dataset& dataset,
                         const std::vector<std::size_t>& trials, const std::vector<TrialFeatures>& nominal,
                         const std::vector<double>& seconds, unsigned threads);

/// Per feature: the largest departure of `nudged` runs from `nominal`, or NaN if the feature is present in
/// some and absent in others or is a category that changes (0 when absent in all, or a category that holds).
std::array<double, kFeatureCount> featureSensitivity(const TrialFeatures& nominal,
                                                     const std::vector<TrialFeatures>& nudged);

} // namespace rosin::discovery
