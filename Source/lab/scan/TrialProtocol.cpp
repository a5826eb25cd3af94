#include "lab/scan/TrialProtocol.h"

#include <cmath>

namespace rosin::scan
{

TrialProtocol::TrialProtocol(const ScanSpec& spec, const CellSettings& cell)
    : accelerating_(spec.kind == ScanKind::Guettler), force_(cell.force), beta_(cell.beta),
      sampleRate_(spec.sampleRate),
      samples_(static_cast<std::size_t>(std::llround(spec.trialSeconds * spec.sampleRate)))
{
    if (accelerating_)
    {
        acceleration_ = cell.second;
        rampEnd_ = 0;
        return;
    }
    speed_ = cell.second;
    rampEnd_ = static_cast<std::size_t>(std::llround(spec.rampSeconds * spec.sampleRate));
    acceleration_ = rampEnd_ > 0 ? speed_ * sampleRate_ / static_cast<double>(rampEnd_) : 0.0;
}

physics::BowInput TrialProtocol::at(std::size_t k) const noexcept
{
    const bool ramping = accelerating_ || k < rampEnd_;
    const double v = ramping ? acceleration_ * static_cast<double>(k) / sampleRate_ : speed_;
    return {force_, v, beta_, 1.0};
}

} // namespace rosin::scan
