#include "core/analysis/LiveRegimeMeter.h"

#include <algorithm>
#include <cmath>

namespace rosin::analysis
{

namespace
{
constexpr double kMinBowSpeed = 1e-4; // m/s: below this the bow is taken as still
constexpr double kMinBowForce = 1e-3; // N: below this the bow is taken as lifted
} // namespace

void LiveRegimeMeter::prepare(double sampleRate) noexcept
{
    sampleRate_ = sampleRate > 0.0 ? sampleRate : 48000.0;
    windowLength_ = std::max(64L, static_cast<long>(std::lround(kWindowSeconds * sampleRate_)));
    reset();
}

void LiveRegimeMeter::reset() noexcept
{
    const double periodsPerSample = periodsPerSample_;
    const double sampleRate = sampleRate_;
    const long windowLength = windowLength_;
    *this = LiveRegimeMeter{};
    sampleRate_ = sampleRate;
    windowLength_ = windowLength;
    periodsPerSample_ = periodsPerSample;
}

void LiveRegimeMeter::setNominalFrequency(double hz) noexcept
{
    periodsPerSample_ = std::isfinite(hz) && hz > 0.0 ? hz / sampleRate_ : 0.0;
}

void LiveRegimeMeter::push(const physics::VoiceSample& s, double bowForce) noexcept
{
    const double vb = s.bowVelocity;
    const bool bowed = bowForce > kMinBowForce && std::abs(vb) > kMinBowSpeed;
    if (bowed)
    {
        ++bowedSamples_;
        periods_ += periodsPerSample_;
    }
    if (!s.sticking)
    {
        if (!inSlip_)
            inSlip_ = true, backwards_ = false;
        // Moving against the bow: v - v_b larger in size than v_b itself means v has the other sign.
        if (bowed && std::abs(s.bowPointVelocity - vb) > std::abs(vb))
            backwards_ = true;
        if (bowed)
        {
            slipMuSum_ += std::abs(s.frictionForce) / bowForce;
            ++slipMuSamples_;
        }
    }
    else
    {
        ++stickSamples_;
        if (bowed)
            ++bowedStickSamples_;
        if (inSlip_)
        {
            inSlip_ = false;
            if (bowed)
                ++slips_;
            if (bowed && backwards_)
            {
                ++flybacks_;
                if (lastFlyback_ >= 0)
                {
                    const double interval = static_cast<double>(t_ - lastFlyback_);
                    intervalSum_ += interval;
                    intervalSquares_ += interval * interval;
                    ++intervals_;
                }
                lastFlyback_ = t_;
            }
        }
    }
    ++t_;
    if (++windowSamples_ >= windowLength_)
        finishWindow();
}

void LiveRegimeMeter::finishWindow() noexcept
{
    const double n = static_cast<double>(windowSamples_);
    stickFraction_ = static_cast<float>(stickSamples_ / n);
    muSlip_ =
        slipMuSamples_ > 0 ? static_cast<float>(slipMuSum_ / static_cast<double>(slipMuSamples_)) : 0.0f;
    const double periods = periods_;
    flybacksPerPeriod_ = periods > 0.5 ? static_cast<float>(flybacks_ / periods) : 0.0f;
    slipsPerPeriod_ = periods > 0.5 ? static_cast<float>(slips_ / periods) : 0.0f;
    double cv = 1.0;
    if (intervals_ >= 2)
    {
        const double mean = intervalSum_ / static_cast<double>(intervals_);
        const double variance =
            std::max(0.0, intervalSquares_ / static_cast<double>(intervals_) - mean * mean);
        cv = mean > 0.0 ? std::sqrt(variance) / mean : 1.0;
    }
    else if (intervals_ == 1)
        cv = 0.0; // one interval at a low note in a short window: no evidence of irregularity
    irregularity_ = static_cast<float>(cv);

    bowing_ = bowedSamples_ * 2 > windowSamples_;
    regime_ = label(periods, cv);

    windowSamples_ = bowedSamples_ = bowedStickSamples_ = stickSamples_ = slips_ = flybacks_ = intervals_ =
        slipMuSamples_ = 0;
    intervalSum_ = intervalSquares_ = periods_ = slipMuSum_ = 0.0;
}

Regime LiveRegimeMeter::label(double periods, double cv) const noexcept
{
    const float fpp = flybacksPerPeriod_;
    const bool regular = cv < 0.2;
    if (!bowing_ || periods <= 0.5)
        return Regime::NoSlip;
    if (bowedStickSamples_ * 20 < bowedSamples_)
        return Regime::ConstantSlipping;
    if (slips_ == 0)
        return Regime::NoSlip;
    if (regular && fpp >= 0.8f && fpp <= 1.25f)
        return Regime::Helmholtz;
    if (regular && fpp >= 0.3f && fpp < 0.8f)
        return Regime::AnomalousLowFrequency;
    if (fpp >= 1.6f && fpp < 2.5f)
        return Regime::DoubleSlipping; // flybacks alternate short and long intervals: no CV test
    if (fpp >= 2.5f && fpp <= 4.5f)
        return Regime::MultipleSlipping;
    return Regime::Raucous;
}

} // namespace rosin::analysis
