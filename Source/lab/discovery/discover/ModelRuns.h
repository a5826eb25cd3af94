#pragma once
// The baseline model of a dataset and the simulation of its trials through the dataset's measurement chain.
// The baseline is the galluzzo-rig preset with the rig's string (dataset.json's rig.string), its body, the
// chosen friction law and the galluzzo contact; the rosin starts at the trial's ambient temperature (the
// thermal laws are calibrated at 20 C: ambientOffset = T - 20). A simulated trial runs with the nominal
// settings and the measured trial's length through TrialSimulator (as rosin synth-data does), then the
// sensor high-pass of SensorChain (no noise) and the calibrated chain (gain, low-pass, force channels' lag:
// the model's NuisanceValues), and is analysed by computeTrialFeatures like a measurement.
#include <cstddef>
#include <string>
#include <vector>

#include "lab/discovery/Dataset.h"
#include "lab/discovery/SimulationModel.h"
#include "lab/discovery/discover/TrialFeatures.h"

namespace rosin::discovery
{

/// The rig's calibration ambient of the thermal laws, deg C.
inline constexpr double kCalibrationAmbient = 20.0;

/// Throws DatasetError naming dataset.json's rig.body if the body is not "cello", "violin" or "rigid", and
/// std::invalid_argument if `friction` is not a friction law name.
SimulationModel baselineModel(const Dataset& dataset, const std::string& friction);

/// Factors on a trial's nominal settings (ModelSensitivity nudges them; 1 = as recorded).
struct SettingsNudge
{
    double bowForce = 1.0;
    double motion = 1.0; ///< the acceleration of a constant-acceleration gesture, the speed of a steady one
};

/// One simulated trial's recorded channels through the dataset's stated sensor, before the calibrated chain:
/// what a fit that changes only the chain (sensorGain, sensorBandwidth, sensorDelay) can reuse.
struct StringRun
{
    std::vector<Channel> layout;
    std::vector<std::vector<double>> channels;
    std::size_t bytes() const noexcept;
};
/// Indexed like dataset.trials; a run with no channels was not simulated.
using StringRuns = std::vector<StringRun>;

/// Features of the dataset's trials `trials` (indices into dataset.trials) simulated with `model`;
/// `seconds[i]` is trial i's length. Results are indexed like dataset.trials (others left empty). With
/// `runs`, a trial whose run is there is not simulated again, only sent through `model`'s chain, and a trial
/// simulated now leaves its run there: the caller vouches that `runs` came from a model with the same physics
/// (everything but the chain's three numbers), the same `seconds` and `nudge`. The features are the same
/// either way, bit for bit.
std::vector<TrialFeatures> simulateFeatures(const SimulationModel& model, const Dataset& dataset,
                                            const std::vector<std::size_t>& trials,
                                            const std::vector<double>& seconds, unsigned threads,
                                            SettingsNudge nudge = {}, StringRuns* runs = nullptr);

} // namespace rosin::discovery
