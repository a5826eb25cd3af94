#pragma once
// One trial of a dataset simulated with a SimulationModel: the bow gesture of rosin scan's TrialProtocol
// (Guettler: v = a t from rest; steady: v from t = 0, as the measured-data format defines "steady", so no
// ramp), on one voice prepared once and reset between trials. Preparing a thermal law calibrates it (~25 ms,
// longer than a short trial), so a worker thread keeps one TrialSimulator for all of its trials; reset()
// returns the voice to rest, so a trial's samples do not depend on the trials run before it.
#include <string>
#include <vector>

#include "core/physics/voice/BowedStringVoice.h"
#include "lab/discovery/Dataset.h"
#include "lab/discovery/SimulationModel.h"

namespace rosin::discovery
{

/// What one trial does, in the units of the dataset.
struct TrialSettings
{
    double beta = 0.0899;
    double bowForce = 1.0; ///< N
    /// ConstantAcceleration or Steady (a Recorded gesture is not simulated here).
    Gesture gesture = ConstantAcceleration{1.0};
    double seconds = 0.4; ///< length of the trial
};

class TrialSimulator
{
  public:
    /// Prepares the voice. Throws config::ConfigError for an unknown name in the model's preset.
    TrialSimulator(const SimulationModel& model, double sampleRate);
    TrialSimulator(const TrialSimulator&) = delete;
    TrialSimulator& operator=(const TrialSimulator&) = delete;

    /// The voice's output for every sample of the trial (valid until the next run). Throws
    /// std::invalid_argument for a recorded gesture.
    const std::vector<physics::VoiceSample>& run(const TrialSettings& settings);

    double sampleRate() const noexcept { return sampleRate_; }
    /// Nominal period 1/f0 of the open string, s.
    double periodSeconds() const noexcept { return period_; }

  private:
    physics::BowedStringVoice voice_;
    std::vector<physics::VoiceSample> samples_;
    double sampleRate_;
    double period_;
};

/// One dataset channel's values from the voice's samples: bridgeForce, frictionForce, bowPointVelocity or
/// bowVelocity (the simulation has no bowForceMeasured). Throws std::invalid_argument for another name.
std::vector<double> channelSamples(const std::vector<physics::VoiceSample>& samples, const std::string& name);

} // namespace rosin::discovery
