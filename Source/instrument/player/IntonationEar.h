#pragma once
// The player's ear: a cellist does not play in tune by finger geometry alone. Helmholtz motion sounds flat
// of f_open / finger ratio as the bow force rises (the corner rounding of [Galluzzo2017] section 4.2), and a
// short stopped length of a stiff string sounds sharp of it; players hear the difference and move the finger.
// This class does the same, one string at a time (JUCE-free, allocation-free, per sample):
//   - it listens to the string's own flybacks (slip episodes in which the string moves backwards against the
//     bow, |v - v_b| > |v_b|), as analysis::LiveRegimeMeter does;
//   - each flyback looks back for the flyback one period earlier (within -15 %..+18 % of the nominal
//     period): in Helmholtz motion the one before it, in double or multiple slipping the one in the same
//     phase of the previous period, since those motions are periodic too and their pitch is heard as well;
//   - over a window (the nominal finger steady within 0.2 %, at least kMinPeriods period samples and
//     kWindowSeconds long) it averages those periods, hence the pitch error in cents against the note;
//   - it moves the finger a fraction (kGain) of the way to cancel the error, at most kMaxStepCents per
//     window and kMaxCents in all.
// When the motion is not periodic (raucous, a flyback with no partner a period back), while sticking, during
// glides and vibrato, it only keeps the correction it has: the hand holds its position. Open strings play
// open: there is no finger to move (their pitch is the tuning's business). The correction is kept from note
// to note on a string (neighbouring notes need nearly the same) and cleared by reset().
#include <cstdint>

namespace rosin::player
{

class IntonationEar
{
  public:
    static constexpr double kWindowSeconds = 0.06;
    static constexpr int kMinPeriods = 4;
    static constexpr double kGain = 0.6;
    static constexpr double kMaxCents = 80.0;
    static constexpr double kMaxStepCents = 3.0;    ///< largest correction per window
    static constexpr double kShortestPeriod = 0.85; ///< of the nominal period
    static constexpr double kLongestPeriod = 1.18;
    static constexpr double kOpenString = 0.999;   ///< nominal finger ratio of an open string
    static constexpr double kSteadyFinger = 0.002; ///< relative change of the nominal finger that restarts

    void prepare(double openFrequencyHz, double sampleRate) noexcept;
    void reset() noexcept;
    void setEnabled(bool enabled) noexcept { enabled_ = enabled; }
    bool enabled() const noexcept { return enabled_; }

    /// The finger ratio to play for the nominal one (f_open / f_note, with bends): the nominal ratio moved
    /// by the learnt correction. Call once per sample before the string steps.
    double finger(double nominalFinger) noexcept;
    /// The string's response to that sample: its sticking state, the bow-point velocity v of the string
    /// and the bow velocity v_b.
    void listen(bool sticking, double stringVelocity, double bowVelocity) noexcept;

    /// Pitch correction applied (cents, positive = finger moved towards the bridge: the string sharpened).
    double correctionCents() const noexcept { return correctionCents_; }
    /// Windows measured so far (tests).
    int windowsMeasured() const noexcept { return windows_; }

  private:
    void flyback(std::int64_t onset) noexcept;
    void restartWindow() noexcept;
    /// The flyback about one nominal period before `onset` (-1: none).
    std::int64_t partnerOf(std::int64_t onset, double nominalPeriod) const noexcept;

    double openFrequency_ = 100.0;
    double sampleRate_ = 48000.0;
    std::int64_t windowSamples_ = 2880;
    bool enabled_ = true;

    double correctionCents_ = 0.0;
    double correctionFactor_ = 1.0; // 2^(-correction / 1200)
    double nominalFinger_ = 1.0;

    std::int64_t t_ = 0;
    bool inSlip_ = false;
    bool flewBack_ = false;
    std::int64_t slipOnset_ = 0;

    static constexpr int kHistory = 8; // flybacks remembered (up to 7 per period)
    std::int64_t onsets_[kHistory] = {};
    int onsetCount_ = 0;

    std::int64_t windowStart_ = -1; // first flyback of the window; -1: none yet
    double periodSum_ = 0.0;
    int periods_ = 0;
    double windowFinger_ = 1.0; // nominal finger when the window started
    int windows_ = 0;
};

} // namespace rosin::player
