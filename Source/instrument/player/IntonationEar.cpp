#include "instrument/player/IntonationEar.h"

#include <algorithm>
#include <cmath>

namespace rosin::player
{

void IntonationEar::prepare(double openFrequencyHz, double sampleRate) noexcept
{
    openFrequency_ = openFrequencyHz > 0.0 ? openFrequencyHz : 100.0;
    sampleRate_ = sampleRate > 0.0 ? sampleRate : 48000.0;
    windowSamples_ = static_cast<std::int64_t>(std::llround(kWindowSeconds * sampleRate_));
    reset();
}

void IntonationEar::reset() noexcept
{
    correctionCents_ = 0.0;
    correctionFactor_ = 1.0;
    nominalFinger_ = 1.0;
    t_ = 0;
    inSlip_ = flewBack_ = false;
    slipOnset_ = 0;
    onsetCount_ = 0;
    restartWindow();
    windows_ = 0;
}

double IntonationEar::finger(double nominalFinger) noexcept
{
    nominalFinger_ = nominalFinger;
    if (!enabled_ || nominalFinger >= kOpenString)
        return nominalFinger;
    return std::clamp(nominalFinger * correctionFactor_, 0.1, 1.0);
}

void IntonationEar::listen(bool sticking, double stringVelocity, double bowVelocity) noexcept
{
    ++t_;
    if (sticking)
    {
        if (inSlip_ && flewBack_)
            flyback(slipOnset_);
        inSlip_ = false;
        return;
    }
    if (!inSlip_)
    {
        inSlip_ = true;
        flewBack_ = false;
        slipOnset_ = t_;
    }
    // A flyback moves the string backwards against the bow; Schelleng ripples and partial slips do not.
    if (std::abs(bowVelocity) > 1e-4 && std::abs(stringVelocity - bowVelocity) > std::abs(bowVelocity))
        flewBack_ = true;
}

void IntonationEar::restartWindow() noexcept
{
    windowStart_ = -1;
    periodSum_ = 0.0;
    periods_ = 0;
    windowFinger_ = nominalFinger_;
}

std::int64_t IntonationEar::partnerOf(std::int64_t onset, double nominalPeriod) const noexcept
{
    std::int64_t best = -1;
    double bestDistance = 1e9;
    for (int i = 0; i < std::min(onsetCount_, kHistory); ++i)
    {
        const double ratio = static_cast<double>(onset - onsets_[i]) / nominalPeriod;
        if (ratio >= kShortestPeriod && ratio <= kLongestPeriod && std::abs(ratio - 1.0) < bestDistance)
        {
            bestDistance = std::abs(ratio - 1.0);
            best = onsets_[i];
        }
    }
    return best;
}

void IntonationEar::flyback(std::int64_t onset) noexcept
{
    const double nominalPeriod = sampleRate_ * nominalFinger_ / openFrequency_;
    const std::int64_t partner = partnerOf(onset, nominalPeriod);
    onsets_[onsetCount_++ % kHistory] = onset;
    if (nominalFinger_ >= kOpenString || std::abs(nominalFinger_ / windowFinger_ - 1.0) > kSteadyFinger ||
        partner < 0)
    {
        restartWindow(); // open string, a glide, or no periodic motion to hear
        return;
    }
    if (windowStart_ < 0)
        windowStart_ = partner;
    periodSum_ += static_cast<double>(onset - partner);
    ++periods_;
    if (onset - windowStart_ < windowSamples_ || periods_ < kMinPeriods)
        return;
    const double measuredPeriod = periodSum_ / periods_;
    const double errorCents = 1200.0 * std::log2(nominalPeriod / measuredPeriod); // > 0: sharp
    ++windows_;
    if (enabled_)
    {
        // A small step per window, as a hand adjusts: one window caught in an attack transient (prolonged
        // periods) cannot throw the finger far.
        const double step = std::clamp(-kGain * errorCents, -kMaxStepCents, kMaxStepCents);
        correctionCents_ = std::clamp(correctionCents_ + step, -kMaxCents, kMaxCents);
        correctionFactor_ = std::exp2(-correctionCents_ / 1200.0);
    }
    restartWindow();
}

} // namespace rosin::player
