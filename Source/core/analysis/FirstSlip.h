#pragma once
// The first slip of a constant-acceleration trial (bow speed v_b = a t from rest, constant force N, bow at
// beta) and what it says about the rosin ([Galluzzo2017] section 4.1, Figs. 15-16):
//   mu_s = F_br(just before the first slip) / ((1 - beta) N)     (force balance of the stuck string)
//   jump = (F_br before the fall - F_br right after it) / N
//
// Before the first slip the bridge force is a smooth, parabola-like rise (the string follows the bow
// quasi-statically: F_br ~ P_T a t^2 / (2 beta L)). The slip starts at the bow; the bridge hears of it a
// travel time tau = beta P / 2 later, and until then the bridge force goes on along the same parabola. So
// from the force alone: find the first abrupt fall, fit a quadratic to the rise that ends before the slip
// could have been heard, and read it at the slip instant (fall - tau) for mu_s and at the fall for the jump.
// A fit over hundreds of samples averages the sensor noise away. A first-order high-pass in the sensor
// (a piezo force gauge) is undone exactly before the fit: x = y + omega_c * integral(y) dt.
//
// Limits: a first slip with no abrupt fall ([Galluzzo2017]: the thermal law's rounded start, or a measured
// jump "vanishingly small") is not found from the force; pass the slip from the state when there is one.
#include <cstddef>
#include <optional>
#include <vector>

namespace rosin::analysis
{

struct FirstSlipOptions
{
    double sampleRate = 48000.0;   ///< Hz
    double beta = 0.0899;          ///< bow-bridge distance / length
    double bowForce = 1.0;         ///< N, N > 0
    double periodSeconds = 0.0;    ///< nominal P = 1/f0, s (> 0)
    double highPassCutoffHz = 0.0; ///< first-order high-pass of the sensor to undo, Hz (0 = none)
    /// Read the parabola at the fall minus beta P / 2 (the slip at the bow) rather than at the fall itself
    /// ([Galluzzo2017]'s measured "force before the slip", which at t1 = 37 ms is ~1.7 % higher).
    bool travelTimeCorrection = true;
    // Detection of the first fall from the force (ours):
    double fallOfLevel = 0.1;  ///< the fall must be this share of the force reached
    double noiseFactor = 8.0;  ///< ... and this many rms of the band-limited fall's noise (early samples)
    double spanSeconds = 1e-4; ///< half-length of the band-limiting difference
    /// The level after the fall: a line fitted over this many P after it, read back at the fall (ours: long
    /// enough to average the noise, short of the next flyback one period on).
    double afterWindowPeriods = 0.2;
};

struct FirstSlip
{
    bool found = false;
    double firstSlipTime = 0.0;   ///< s: the slip at the bow (state) or fall - tau (force)
    double fallTime = 0.0;        ///< s: centre of the first abrupt fall of the bridge force
    double forceAtSlip = 0.0;     ///< N: F_br just before the slip (the parabola at the slip instant)
    double forceBeforeFall = 0.0; ///< N: the parabola extended to the fall
    double forceAfterFall = 0.0;  ///< N: level right after the fall (line fit on the next 0.2 P, read back)
    double muStatic = 0.0;        ///< forceAtSlip / ((1 - beta) N)
    double jump = 0.0;            ///< (forceBeforeFall - forceAfterFall) / N
};

/// From the bridge force alone (a measurement: noise, and a high-pass if highPassCutoffHz > 0).
FirstSlip firstSlipFromBridgeForce(const std::vector<double>& bridgeForce, const FirstSlipOptions& options);

/// With the solver's sticking flag (a simulation): the first non-sticking sample is the slip, and
/// forceAtSlip is the bridge force of the sample before it (exact for a clean signal). The fall and the
/// jump are found in the force as above, within tau + P/4 after the slip.
FirstSlip firstSlipFromState(const std::vector<double>& bridgeForce, const std::vector<bool>& sticking,
                             const FirstSlipOptions& options);

/// Undoes a first-order high-pass y' = x' - omega_c y of cutoff fc (Hz): x = y + omega_c sum(y) / fs
/// (exact for the backward-Euler discretisation y[n] = a (y[n-1] + x[n] - x[n-1]), a = 1/(1 + omega_c/fs)).
std::vector<double> undoFirstOrderHighPass(const std::vector<double>& y, double cutoffHz, double sampleRate);

} // namespace rosin::analysis
