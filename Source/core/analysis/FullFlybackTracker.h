#pragma once
// The onsets of a simulation's full flybacks, found sample by sample while the trial runs: after any number
// of samples, onsets() equals onsetsOf(fullFlybacksOnly(slipEpisodesFromVoice(those samples), beta, share))
// (SlipOnsets.h), without reading the samples again. A scan uses it to end a trial as soon as its transient
// is decided (scan/TrialEnd.h). An episode's onset is listed from the sample at which it first qualifies.
#include <cstddef>
#include <optional>
#include <vector>

#include "core/physics/voice/BowedStringVoice.h"

namespace rosin::analysis
{

class FullFlybackTracker
{
  public:
    /// beta > 0; share as fullFlybacksOnly. Reserves room for `expectedOnsets`.
    FullFlybackTracker(double beta, double share, std::size_t expectedOnsets = 0);
    /// Back to no samples.
    void reset() noexcept;
    /// The next sample of the trial.
    void add(const physics::VoiceSample& s);

    const std::vector<std::size_t>& onsets() const noexcept { return onsets_; }
    /// The onset of the slip under way if it is not (yet) a full flyback; it may still become one.
    std::optional<std::size_t> pendingOnset() const noexcept
    {
        return inEpisode_ && !listed_ ? std::optional(onset_) : std::nullopt;
    }
    std::size_t samples() const noexcept { return samples_; }

  private:
    double beta_ = 0.1, share_ = 0.25;
    std::size_t samples_ = 0;
    bool previousSticking_ = false;
    bool inEpisode_ = false; ///< in a run of sliding whose onset was seen
    bool listed_ = false;    ///< the current episode's onset is in onsets_
    bool flyback_ = false;
    double peakSlipSpeed_ = 0.0, bowSpeedAtOnset_ = 0.0;
    std::size_t onset_ = 0;
    std::vector<std::size_t> onsets_;
};

} // namespace rosin::analysis
