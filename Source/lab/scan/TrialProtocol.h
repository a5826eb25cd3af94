#pragma once
// The bow gesture of one scan trial, sample by sample.
//   Guettler ([Galluzzo2017] section 3.2; [Notes §6.3]): constant force N at beta, bow speed v_b = a t from
//   rest for the whole trial, uncapped (3.2 m/s^2 reaches 1.6 m/s at 0.5 s). The transient that decides the
//   cell is over within ~20 periods (0.14 s) of the first slip, long before the speed is unusual. Schelleng
//   (section 3.1): constant force N at beta; the bow accelerates uniformly from rest to v_b over the ramp
//   time (0.1 s by default: 0.5 m/s^2 for 0.05 m/s, a gentle start well inside Guettler's wedge for most
//   forces, as a bowing machine would use) and then holds v_b to the end.
#include <cstddef>

#include "core/physics/voice/BowedStringVoice.h"
#include "lab/scan/ScanSpec.h"

namespace rosin::scan
{

class TrialProtocol
{
  public:
    TrialProtocol(const ScanSpec& spec, const CellSettings& cell);

    std::size_t samples() const noexcept { return samples_; }
    /// First sample at the final bow speed (Schelleng), 0 for Guettler.
    std::size_t rampEnd() const noexcept { return rampEnd_; }
    physics::BowInput at(std::size_t k) const noexcept;

  private:
    bool accelerating_ = true;
    double force_ = 0.0, beta_ = 0.1;
    double acceleration_ = 0.0; ///< m/s^2 until rampEnd_
    double speed_ = 0.0;        ///< m/s after rampEnd_ (Schelleng)
    double sampleRate_ = 48000.0;
    std::size_t samples_ = 0, rampEnd_ = 0;
};

} // namespace rosin::scan
