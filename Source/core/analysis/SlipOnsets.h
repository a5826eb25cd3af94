#pragma once
// Where the string starts to slip, found two ways ([Notes §7.2]):
//  * from the simulation's own state: a slip episode is a maximal run of non-sticking samples (exact), a
//    flyback if the string moves backwards in it (partial slips, in which it only lags the bow, are not);
//  * from the bridge force alone, as a measurement gives it: the sharp falls of the sawtooth (the flyback
//    reaching the bridge), found on a band-limited derivative with a threshold relative to the largest falls
//    nearby and a refractory interval.
// Sample indices throughout; periods in samples. Offline analysis: allocation is fine, no JUCE.
#include <cstddef>
#include <vector>

#include "core/physics/voice/BowedStringVoice.h"

namespace rosin::analysis
{

/// One maximal run of sliding samples.
struct SlipEpisode
{
    std::size_t onset = 0;    ///< first sliding sample (stick -> slip)
    std::size_t duration = 0; ///< sliding samples in the run
    /// The string moved backwards, |v - v_b| > |v_b| (the flyback of Helmholtz motion). Known only when the
    /// episodes come from velocities; episodes from the sticking flag alone are taken as flybacks.
    bool flyback = true;
    /// Largest |v - v_b| in the episode and |v_b| at its onset, m/s (known only from velocities; 0 else).
    double peakSlipSpeed = 0.0;
    double bowSpeedAtOnset = 0.0;
};

/// Episodes from the solver's sticking flag. A run already under way at sample 0 is not an onset (its start
/// is unseen) and is left out.
std::vector<SlipEpisode> slipEpisodesFromState(const std::vector<bool>& sticking);

/// Episodes from a simulation's per-sample output: the runs of the solver's sticking flag, each marked a
/// flyback if somewhere in it |v - v_b| > |v_b| (v the bow-point velocity), as HelmholtzMotionTest and the
/// plugin's live meter (LiveRegimeMeter) count them.
std::vector<SlipEpisode> slipEpisodesFromVoice(const std::vector<physics::VoiceSample>& samples);

/// The bridge force and the sticking flag of a simulation's samples, as the force- and state-based
/// analyses take them.
struct ForceAndState
{
    std::vector<double> bridgeForce;
    std::vector<bool> sticking;
};
ForceAndState forceAndState(const std::vector<physics::VoiceSample>& samples);

/// Episodes from the relative velocity dv = v - v_b at the bow (m/s): sliding where |dv| > threshold (m/s).
/// With bowVelocity (same length, or empty) each episode also records whether it was a flyback.
/// [Notes §7.2] suggests threshold = 1 % of v_b to ignore numerical chatter.
std::vector<SlipEpisode> slipEpisodesFromRelativeVelocity(const std::vector<double>& relativeVelocity,
                                                          double threshold,
                                                          const std::vector<double>& bowVelocity = {});

/// Only the flybacks: partial slips, in which the string lags the bow without reversing (the ripple of a
/// rounded Helmholtz corner), are dropped.
std::vector<SlipEpisode> flybacksOnly(const std::vector<SlipEpisode>& episodes);

/// The flybacks that carry the string back at least `share` of the ideal Helmholtz flyback speed v_b / beta
/// (relative to the bow, at the onset's bow speed). A flyback of Helmholtz motion, even with rounded corners,
/// reaches most of it; the short secondary reversals of a thermal law at a slow bow (a few % of it) do not,
/// and neither they nor the ripple are a period's slip. Episodes without velocities pass.
std::vector<SlipEpisode> fullFlybacksOnly(const std::vector<SlipEpisode>& episodes, double beta,
                                          double share);

/// Onset sample indices of the episodes.
std::vector<std::size_t> onsetsOf(const std::vector<SlipEpisode>& episodes);

/// Share of sliding samples in [begin, end) of the sticking flag (end clamped to its size); 0 if empty.
double slipFraction(const std::vector<bool>& sticking, std::size_t begin, std::size_t end);

/// Settings of the bridge-force onset detector. Defaults: [Notes §7.2] where it gives a value, else ours.
struct ForceOnsetOptions
{
    double relativeThreshold = 0.3; ///< of the largest fall in the local window ([Notes §7.2])
    /// No two onsets closer than this many P (ours). The ~0.3 P of [Notes §7.2] would hide multiple slipping:
    /// the simulated cello D at 0.05 N slips three times a period, 0.26 P apart at the closest.
    double refractoryPeriods = 0.15;
    double localWindowPeriods = 2.0; ///< the "window" of the relative threshold is +-this many P (ours)
    /// A fall over the derivative span must also be this share of the local peak-to-peak force (ours): a
    /// slip is abrupt, a smooth oscillation (a sine: ~3 % of its range over 0.01 P) is not a slip.
    double minFallOfRange = 0.1;
    double spanPeriods = 0.01; ///< half-length of the band-limiting difference, in P (ours; >= 1 sample)
    /// Sensor noise, N rms (0 = unknown). When known, falls must exceed noiseFactor times the noise of the
    /// band-limited difference, so that a quiet signal has no slips. When unknown every signal has slips:
    /// pure noise gives random onsets (which the classifier calls raucous).
    double noiseRms = 0.0;
    double noiseFactor = 8.0;
};

/// The band-limited fall of x at each sample: mean of the `span` samples before k minus the mean of the
/// `span` samples from k on (0 where the window does not fit). A step down between k-1 and k peaks at k.
std::vector<double> bandLimitedFall(const std::vector<double>& x, std::size_t span);

/// Slip onsets (samples where the bridge force falls fastest) in a bridge-force signal with nominal period
/// `periodSamples` > 0. The constant offset between the slip at the bow and the fall at the bridge (about
/// beta P / 2) is not removed: intervals, not absolute times, are what the classifier uses.
std::vector<std::size_t> slipOnsetsFromBridgeForce(const std::vector<double>& bridgeForce,
                                                   double periodSamples,
                                                   const ForceOnsetOptions& options = {});

} // namespace rosin::analysis
