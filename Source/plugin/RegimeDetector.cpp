#include "RegimeDetector.h"

#include <algorithm>
#include <cmath>

namespace rosin::plugin
{

namespace
{
constexpr double kMinBowSpeed = 1e-4; // m/s: below this the bow is taken as still
constexpr double kMinBowForce = 1e-3; // N: below this the bow is taken as lifted
} // namespace

void RegimeDetector::prepare(double sampleRate) noexcept
{
    sampleRate_ = sampleRate > 0.0 ? sampleRate : 48000.0;
    windowLength_ = std::max(64L, static_cast<long>(std::lround(kWindowSeconds * sampleRate_)));
    reset();
}

void RegimeDetector::reset() noexcept
{
    const double periodsPerSample = periodsPerSample_;
    const double sampleRate = sampleRate_;
    const long windowLength = windowLength_;
    *this = RegimeDetector{};
    sampleRate_ = sampleRate;
    windowLength_ = windowLength;
    periodsPerSample_ = periodsPerSample;
}

void RegimeDetector::setNominalFrequency(double hz) noexcept
{
    periodsPerSample_ = std::isfinite(hz) && hz > 0.0 ? hz / sampleRate_ : 0.0;
}

void RegimeDetector::push(const physics::VoiceSample& s, double bowForce) noexcept
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

void RegimeDetector::finishWindow() noexcept
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

    const bool mostlyBowed = bowedSamples_ * 2 > windowSamples_;
    const bool regular = cv < 0.2;
    if (!mostlyBowed || slips_ == 0 || periods <= 0.5)
        regime_ = Regime::Silent;
    else if (regular && flybacksPerPeriod_ >= 0.8f && flybacksPerPeriod_ <= 1.25f)
        regime_ = Regime::Helmholtz;
    else if (flybacksPerPeriod_ >= 1.6f && flybacksPerPeriod_ <= 4.5f)
        regime_ = Regime::MultipleSlipping; // flybacks alternate short and long intervals: no CV test
    else
        regime_ = Regime::Raucous;

    windowSamples_ = bowedSamples_ = stickSamples_ = slips_ = flybacks_ = intervals_ = slipMuSamples_ = 0;
    intervalSum_ = intervalSquares_ = periods_ = slipMuSum_ = 0.0;
}

void RegimeDetector::fillReadout(StringReadout& r) const noexcept
{
    r.regime = regime_;
    r.flybacksPerPeriod = flybacksPerPeriod_;
    r.slipsPerPeriod = slipsPerPeriod_;
    r.irregularity = irregularity_;
    r.stickFraction = stickFraction_;
    r.muSlip = muSlip_;
}

} // namespace rosin::plugin
