#pragma once
// The steady-state regime of a bowed string over an analysis window ([Notes §7.4]), judged from
// its slip onsets and, when given, the bridge force.
//
// The onsets are read as a repeating pattern: the smallest k (slips per cycle) for which (nearly) every
// interval recurs k intervals later decides the slips per cycle and the cycle length, the measured period
// P_m (median of the k-lag intervals). Then
//   P_m >= 1.1 P                                    -> ALF
//   P_m within +-10 % of P: k = 1                   -> Helmholtz (S-motion if the sawtoothness is off 1)
//                           k = 2                   -> double slipping;  k >= 3 -> multiple slipping
//   P_m a sub-multiple of P (P/2, P/3 ...)          -> double / multiple slipping by slips per period P
//   no repeating pattern (or a weak autocorrelation) -> raucous
//   (almost) no sticking                             -> constant slipping;  no slip at all -> no-slip.
// P (nominal period) and P_m are in samples. Offline analysis; no JUCE.
#include <cstddef>
#include <limits>
#include <vector>

#include "core/analysis/Regime.h"
#include "core/analysis/SlipOnsets.h"

namespace rosin::analysis
{

/// Thresholds, each marked with its origin. "Notes" = [Notes §7.4] (itself partly [A]).
namespace regime_thresholds
{
/// ALF: periodic with a period >= 1.1 P (notes).
inline constexpr double kAlfMinPeriodRatio = 1.1;
/// Helmholtz-family period band |P_m/P - 1| < 0.1 (ours). The notes ask +-3 % for Helmholtz, but a
/// stopped string on a body and the flattening near F_max shift the pitch by several %, which is reported
/// (RegimeAnalysis::withinReferencePitch, cents) rather than relabelled. Below 0.9 P a period must be a
/// sub-multiple of P within this tolerance.
inline constexpr double kPeriodTolerance = 0.10;
/// The notes' own pitch tolerance for Helmholtz (reported, not used to label).
inline constexpr double kReferencePeriodTolerance = 0.03;
/// S-motion: sawtoothness s = |F1|/(2|F2|) outside 0.7..1.3 (notes, "e.g.").
inline constexpr double kSawtoothMin = 0.7;
inline constexpr double kSawtoothMax = 1.3;
/// Periodic pattern: |Delta_{i+k} - Delta_i| below 3 % of the cycle (ours: sampling jitter of a simulation is
/// ~0.3 %, a noisy measured onset a few samples) for at least 90 % of the pairs (ours: one stray partial slip
/// in a steady window, as the simulation shows in triple slipping, must not turn it raucous).
inline constexpr double kPatternTolerance = 0.03;
inline constexpr double kMinPatternShare = 0.9;
/// Largest k (slips per cycle) tried (ours).
inline constexpr int kMaxSlipsPerCycle = 6;
/// At least this many whole cycles in the window to call it periodic (ours).
inline constexpr int kMinCycles = 3;
/// Normalised autocorrelation of the bridge force at lag P_m below this -> raucous (notes: "< 0.9").
inline constexpr double kMinAutocorrelation = 0.9;
/// Sliding for at least this share of the window -> constant slipping (ours; notes: "no sticking").
inline constexpr double kConstantSlippingFraction = 0.95;
/// Force alone, no onsets: a rise across the window above this many residual rms -> the string is dragged
/// with the bow (no-slip); otherwise it slides steadily (constant slipping) (ours).
inline constexpr double kDragTrendFactor = 5.0;
} // namespace regime_thresholds

/// [begin, end) in samples; end = 0 means to the end of the signal. [Notes §7.4] analyses the last >= 20
/// periods, after the transient.
struct AnalysisWindow
{
    std::size_t begin = 0;
    std::size_t end = 0;
};

struct RegimeAnalysis
{
    Regime regime = Regime::NoSlip;
    std::size_t onsetCount = 0;  ///< slip onsets in the window
    double slipsPerPeriod = 0.0; ///< onsets per nominal period P (from the onset span; 0 without 2 onsets)
    int slipsPerCycle = 0;       ///< k of the repeating pattern (0 if none)
    double measuredPeriod = 0.0; ///< P_m, samples (mean k-lag interval; 0 if no pattern)
    double pitchCents = 0.0;     ///< 1200 log2(P / P_m): deviation of the pattern's pitch from nominal
    bool withinReferencePitch = false; ///< |P_m/P - 1| < 3 % (the Helmholtz tolerance of [Notes §7.4])
    double intervalCv = 0.0;           ///< coefficient of variation of successive onset intervals
    double patternError = 0.0;         ///< rms (Delta_{i+k} - Delta_i) / P_m for the chosen k (k = 1 if none)
    double patternShare = 0.0;         ///< share of pairs with |Delta_{i+k} - Delta_i| < 3 % of P_m (same k)
    /// |F1|/(2|F2|) of the bridge force at P_m; NaN if not computed (no force, no pattern, < 2 cycles).
    double sawtoothness = std::numeric_limits<double>::quiet_NaN();
    /// Normalised autocorrelation of the bridge force at lag P_m; NaN if not computed.
    double autocorrelation = std::numeric_limits<double>::quiet_NaN();
    double slipFraction = std::numeric_limits<double>::quiet_NaN(); ///< sliding share (state); NaN from force
};

/// From the solver's sticking flag; bridgeForce (same length, or empty) adds sawtoothness and periodicity.
/// Every run of sliding counts as a slip, partial slips included (the string lagging the bow without
/// reversing, several per period with the reconstructed and thermal laws): prefer classifyFromVoice.
RegimeAnalysis classifyFromState(const std::vector<bool>& sticking, const std::vector<double>& bridgeForce,
                                 double periodSamples, AnalysisWindow window = {});

/// From a simulation's per-sample output, counting flybacks only (slipEpisodesFromVoice), with the bridge
/// force for sawtoothness and periodicity and the sticking flag for the slip fraction.
RegimeAnalysis classifyFromVoice(const std::vector<physics::VoiceSample>& samples, double periodSamples,
                                 AnalysisWindow window = {});

/// From episodes found some other way (e.g. flybacksOnly(...) of velocity-based episodes), with the window's
/// slip fraction (0..1) and the total signal length in samples.
RegimeAnalysis classifyFromEpisodes(const std::vector<SlipEpisode>& episodes, double slipFraction,
                                    std::size_t signalLength, const std::vector<double>& bridgeForce,
                                    double periodSamples, AnalysisWindow window = {});

/// From the bridge force alone (a measurement): onsets by slipOnsetsFromBridgeForce over the whole signal,
/// then the window. Without sticking information, no onsets mean constant slipping unless the force rises
/// steadily across the window (the string dragged with the bow: no-slip). Reliable for Helmholtz motion
/// (the flyback is the largest fall); at light force, where the body's Schelleng ripples are as large as the
/// falls of the slips (the simulated cello D below ~0.2 N at 0.05 m/s), it cannot count slips per period and
/// says raucous where the state sees double or multiple slipping.
RegimeAnalysis classifyFromBridgeForce(const std::vector<double>& bridgeForce, double periodSamples,
                                       AnalysisWindow window = {}, const ForceOnsetOptions& options = {});
/// The same from the onsets slipOnsetsFromBridgeForce found over the whole signal (for a caller that also
/// needs them for the transient: the onset search is the analysis' costliest step).
RegimeAnalysis classifyFromForceOnsets(const std::vector<std::size_t>& onsets,
                                       const std::vector<double>& bridgeForce, double periodSamples,
                                       AnalysisWindow window = {});

/// Sawtoothness s = |F1| / (2 |F2|) of x over [begin, end) at period periodSamples (Hann-windowed
/// projection on whole cycles, mean removed): 1 for an ideal sawtooth. NaN if fewer than 2 cycles fit.
double sawtoothness(const std::vector<double>& x, std::size_t begin, std::size_t end, double periodSamples);

/// Normalised autocorrelation of x (mean removed) over [begin, end) at lag round(lagSamples); NaN if the lag
/// does not fit.
double autocorrelationAt(const std::vector<double>& x, std::size_t begin, std::size_t end, double lagSamples);

} // namespace rosin::analysis
