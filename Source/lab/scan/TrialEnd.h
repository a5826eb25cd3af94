#pragma once
// When a Guettler trial may stop, decided sample by sample as it runs, such that the analysis of the samples
// so far (CellAnalysis.h) reports the same first slip and the same transient (reached or not, and its
// length) as the whole trial would:
//  * the transient window is over: the analysis reads 2 x cap periods after the first full flyback t1, of
//    the period it measures against (the nominal P, or the steady period within +-10 % of it);
//  * (WhenDecided) the transient can no longer start within the cap: a Helmholtz run must start at a full
//    flyback before t1 + cap P' and contain only intervals within 5 % of P'. So once an interval between
//    two full flybacks is outside 5 % of every P' the analysis might use (shorter than 0.855 P or longer
//    than 1.155 P) and ends at or after t1 + cap x 1.1 P, or no full flyback has come for longer than
//    1.155 P when that time is past, every run still to come starts too late. Both must happen within
//    2 x cap x 0.9 P of t1, inside the window for any period, where they break every run the analysis
//    could find. Failed attacks (most cells of [Galluzzo2017]'s Guettler diagrams) end about 20 periods
//    sooner.
// What the analysis then reports from the end of the trial (the regime of its last 20 periods, the
// failure type) describes the motion up to the decision.
#include <cstddef>

#include "core/analysis/FullFlybackTracker.h"
#include "lab/scan/ScanSpec.h"

namespace rosin::scan
{

class TrialEnd
{
  public:
    /// rule: the scan's; trialSamples: the whole trial's length; periodSamples: the nominal P.
    TrialEnd(GuettlerTrialEnd rule, double beta, double periodSamples, std::size_t trialSamples);
    /// Takes the trial's next sample; true when the trial may end after it (always at trialSamples).
    bool add(const physics::VoiceSample& s);

  private:
    bool pastTheCap(std::size_t k) const noexcept;    ///< only after the first full flyback
    bool inEveryWindow(std::size_t k) const noexcept; ///< only after the first full flyback

    GuettlerTrialEnd rule_;
    double P_;
    std::size_t end_; ///< samples after which the trial ends at the latest
    std::size_t samples_ = 0;
    analysis::FullFlybackTracker flybacks_;
    std::size_t onsetsSeen_ = 0;
    bool missed_ = false;                             ///< the transient can no longer start within the cap
    double capReach_ = 0.0, shortestWindowEnd_ = 0.0; ///< samples; set at the first full flyback
};

} // namespace rosin::scan
