#include "core/analysis/FullFlybackTracker.h"

#include <algorithm>
#include <cmath>

namespace rosin::analysis
{

FullFlybackTracker::FullFlybackTracker(double beta, double share, std::size_t expectedOnsets)
    : beta_(beta), share_(share)
{
    onsets_.reserve(expectedOnsets);
}

void FullFlybackTracker::reset() noexcept
{
    samples_ = 0;
    previousSticking_ = inEpisode_ = listed_ = flyback_ = false;
    peakSlipSpeed_ = bowSpeedAtOnset_ = 0.0;
    onsets_.clear();
}

void FullFlybackTracker::add(const physics::VoiceSample& s)
{
    const std::size_t k = samples_++;
    const bool wasSticking = previousSticking_;
    previousSticking_ = s.sticking;
    if (s.sticking)
    {
        inEpisode_ = false;
        return;
    }
    // slipEpisodesFromVoice: an episode starts at a sliding sample after a sticking one (never at sample 0).
    if (k > 0 && wasSticking)
    {
        inEpisode_ = true;
        listed_ = flyback_ = false;
        onset_ = k;
        peakSlipSpeed_ = 0.0;
        bowSpeedAtOnset_ = std::abs(s.bowVelocity);
    }
    if (!inEpisode_ || listed_)
        return;
    const double slip = std::abs(s.bowPointVelocity - s.bowVelocity);
    peakSlipSpeed_ = std::max(peakSlipSpeed_, slip);
    flyback_ = flyback_ || slip > std::abs(s.bowVelocity);
    // fullFlybacksOnly, whose test can only turn true as the episode goes on (both terms only grow).
    const bool measured = peakSlipSpeed_ > 0.0 || bowSpeedAtOnset_ > 0.0;
    if (flyback_ && (!measured || peakSlipSpeed_ >= share_ * bowSpeedAtOnset_ / beta_))
    {
        onsets_.push_back(onset_);
        listed_ = true;
    }
}

} // namespace rosin::analysis
