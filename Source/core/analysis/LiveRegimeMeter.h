#pragma once
// The regime of a bowed string, judged as it plays, sample by sample with no allocation and no lock: the
// live counterpart of RegimeClassifier (same analysis::Regime labels), for the plugin's readout.
//
// A slip episode is a run of non-sticking samples; it is a flyback when, somewhere in it, the string moves
// backwards against the bow: |v - v_b| > |v_b| (SlipOnsets.h counts flybacks the same way). Over a window
// of about 80 ms (independent of the host's block size) the meter counts slips and flybacks per nominal
// period of the sounding note and the regularity of the flyback intervals (coefficient of variation CV),
// then labels the window like RegimeClassifier labels an onset pattern:
//   no bow for most of the window, or no slip            -> no-slip (bowing() tells the two apart)
//   sticking for less than 5 % of the bowed time          -> constant slipping
//   1 flyback per period (0.8..1.25), regular (CV < 0.2)  -> Helmholtz
//   0.3..0.8 flybacks per period, regular                 -> anomalous low frequency (a longer period)
//   1.6..2.5 flybacks per period                          -> double slipping
//   2.5..4.5 flybacks per period                          -> multiple slipping
//   anything else that slips                              -> raucous
// Small secondary slips that do not move the string backwards (the ripple of a rounded Helmholtz corner)
// count as slips, not flybacks. S-motion needs the bridge force's shape and is left to the offline
// classifier. JUCE-free.
#include "core/analysis/Regime.h"
#include "core/physics/voice/BowedStringVoice.h"

namespace rosin::analysis
{

class LiveRegimeMeter
{
  public:
    static constexpr double kWindowSeconds = 0.08;

    void prepare(double sampleRate) noexcept;
    void reset() noexcept;

    /// Nominal frequency of the note now sounding on this string (Hz); set once per block.
    void setNominalFrequency(double hz) noexcept;
    /// One sample of this string's output and the bow force that produced it.
    void push(const physics::VoiceSample& s, double bowForce) noexcept;

    // The last full window's verdict and rates.
    Regime regime() const noexcept { return regime_; }
    bool bowing() const noexcept { return bowing_; } ///< bowed (force on, bow moving) for most of it
    float flybacksPerPeriod() const noexcept { return flybacksPerPeriod_; }
    float slipsPerPeriod() const noexcept { return slipsPerPeriod_; }
    float irregularity() const noexcept { return irregularity_; } ///< CV of the flyback intervals
    float stickFraction() const noexcept { return stickFraction_; }
    float muSlip() const noexcept { return muSlip_; } ///< mean |f| / F_b while slipping

  private:
    void finishWindow() noexcept;
    Regime label(double periods, double cv) const noexcept;

    double sampleRate_ = 48000.0;
    long windowLength_ = 3840;
    double periodsPerSample_ = 0.0;

    // Running state.
    long t_ = 0; // samples since reset
    bool inSlip_ = false;
    bool backwards_ = false;
    long lastFlyback_ = -1;

    // Window accumulators.
    long windowSamples_ = 0;
    long bowedSamples_ = 0;
    long bowedStickSamples_ = 0;
    long stickSamples_ = 0;
    long slips_ = 0;
    long flybacks_ = 0;
    long intervals_ = 0;
    double intervalSum_ = 0.0;
    double intervalSquares_ = 0.0;
    double periods_ = 0.0;
    double slipMuSum_ = 0.0;
    long slipMuSamples_ = 0;

    // The last verdict.
    Regime regime_ = Regime::NoSlip;
    bool bowing_ = false;
    float flybacksPerPeriod_ = 0.0f;
    float slipsPerPeriod_ = 0.0f;
    float irregularity_ = 0.0f;
    float stickFraction_ = 1.0f;
    float muSlip_ = 0.0f;
};

} // namespace rosin::analysis
