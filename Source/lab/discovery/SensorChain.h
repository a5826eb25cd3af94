#pragma once
// The measurement chain between the string and a dataset's trial files, as [Galluzzo2017] describes its rig:
// force gauges (piezo) behind a first-order high-pass (0.5 Hz there), and a noise floor on every channel.
// rosin synth-data passes its simulated trials through it; rosin discover passes its simulations through
// the response part (not the noise) so that measurement and model are compared like for like.
//
// The high-pass is the backward-Euler discretisation y[n] = a (y[n-1] + x[n] - x[n-1]), a = 1 / (1 + wc/fs),
// from rest, which analysis::undoFirstOrderHighPass undoes exactly (FirstSlip does that before fitting).
#include <string>
#include <vector>

#include "lab/discovery/Dataset.h"
#include "lab/discovery/SeededRandom.h"

namespace rosin::discovery
{

/// Channels that come from a force gauge (unit N) and so pass the sensor's high-pass; velocities (a
/// vibrometer, the bowing machine's encoder) do not.
bool passesSensorHighPass(const Channel& channel);

/// First-order high-pass of cutoff `cutoffHz` (> 0) in place, starting from rest.
void firstOrderHighPass(std::vector<double>& signal, double cutoffHz, double sampleRate);

/// Second-order Butterworth low-pass of corner `cornerHz` (< sampleRate / 2) in place, from rest.
void butterworthLowPass(std::vector<double>& signal, double cornerHz, double sampleRate);

/// What a dataset does not state about its force gauges (rosin discover calibrates it, NuisanceParameters.h):
/// the force channels x `gain`, then the low-pass (lowpassHz 0: none).
void applyGaugeCalibration(const std::vector<Channel>& layout, std::vector<std::vector<double>>& channels,
                           double gain, double lowpassHz, double sampleRate);

/// The sensor's response: the high-pass on the force channels, when sensor.highpassHz is given and > 0.
/// `channels[c]` holds the samples of dataset channel `layout[c]`.
void applySensorResponse(const std::vector<Channel>& layout, std::vector<std::vector<double>>& channels,
                         const Sensor& sensor, double sampleRate);

/// White Gaussian noise of sensor.noiseRms (in each channel's unit, as the spec defines it) on every channel,
/// from `random` channel after channel.
void addSensorNoise(std::vector<std::vector<double>>& channels, const Sensor& sensor, SeededRandom& random);

} // namespace rosin::discovery
