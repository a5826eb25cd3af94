#pragma once
// Which regime a bowed string is in, judged cheaply on the audio thread from the voice's own output.
//
// A slip episode is a run of non-sticking samples. It is a flyback when, at some sample in it, the string
// moves backwards against the bow: |v - v_b| > |v_b| (v the bow-point velocity, v_b the bow's). Over an
// analysis window (about 80 ms, independent of the host's block size) the detector counts slips and flybacks
// per nominal period of the sounding note (f_open / finger ratio) and the regularity of the flyback
// intervals (their coefficient of variation), then classifies by the flybacks:
//   Helmholtz          one flyback per period (0.8..1.25), regular (CV < 0.2);
//   multiple slipping  1.6..4.5 flybacks per period (the string flies back more than once per period);
//   raucous            anything else that slips (fewer than 0.8 flybacks per period: aperiodic or
//                      subharmonic; irregular intervals; or between the two bands);
//   silent             the bow is lifted or still for most of the window, or nothing slips.
// Small secondary slips that do not move the string backwards (the ripple of the Helmholtz corner) count
// as slips, not flybacks: they are reported but do not change the regime.
// Per sample: a few comparisons and adds; no allocation, no lock.
#include "StringTelemetry.h"
#include "physics/voice/BowedStringVoice.h"

namespace rosin::plugin
{

class RegimeDetector
{
  public:
    static constexpr double kWindowSeconds = 0.08;

    void prepare(double sampleRate) noexcept;
    void reset() noexcept;

    /// Nominal frequency of the note now sounding on this string (Hz); set once per block.
    void setNominalFrequency(double hz) noexcept;
    /// One sample of this string's output and the bow force that produced it.
    void push(const physics::VoiceSample& s, double bowForce) noexcept;

    /// The last full window's verdict and rates (regime, flybacks, slips, irregularity, stick fraction,
    /// slip mu). Other StringReadout fields are left alone.
    void fillReadout(StringReadout& r) const noexcept;

  private:
    void finishWindow() noexcept;

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
    Regime regime_ = Regime::Silent;
    float flybacksPerPeriod_ = 0.0f;
    float slipsPerPeriod_ = 0.0f;
    float irregularity_ = 0.0f;
    float stickFraction_ = 1.0f;
    float muSlip_ = 0.0f;
};

} // namespace rosin::plugin
