#pragma once
// kLanes copies of one BowedStringVoice (same string, body and bow position) advanced together, each with its
// own bow force, bow velocity, friction law and state: the independent trials of a scan column. The modes run
// in SIMD lanes (LaneModes.h); the junction of each lane is the voice's own solve (BowedStringVoice.cpp,
// single string on its own body), with the friction of all lanes in one LaneFriction (LaneFriction.h: any
// law, one object per lane, or the plastic law lane-wise). A lane's samples do not depend on the other lanes.
//
// The modal sums are formed in another order than the voice's (mode by mode per lane rather than across
// modes), so a lane agrees with BowedStringVoice to float rounding, not bit for bit; tests/core/physics/
// checks the two against each other.
#include <array>
#include <memory>
#include <vector>

#include "core/physics/lanes/LaneFriction.h"
#include "core/physics/lanes/LaneModes.h"
#include "core/physics/voice/BowedStringVoice.h"

namespace rosin::physics
{

/// Per-lane bow input for one sample (beta is the voice's, fixed at prepare()).
struct LaneBowInput
{
    std::array<double, kLanes> bowForce{};    ///< N
    std::array<double, kLanes> bowVelocity{}; ///< m/s
};

/// One lane's string and body state (its friction's is not included), captured to be scaled into another.
struct LaneState
{
    std::vector<ModalReal> modes; ///< re, im of every transverse, torsional and body mode
    std::array<double, 9> histories{};
};

class VoiceLanes
{
  public:
    /// Off the audio thread. Copies the voice's discrete system at its current bow position (set it with
    /// BowedStringVoice::setBowPosition first) and takes the lanes' friction.
    void prepare(const BowedStringVoice& voice, std::unique_ptr<LaneFriction> friction);
    /// New coefficients for another bow position of the same voice, keeping the laws. Resets every lane.
    void retune(const BowedStringVoice& voice);
    /// Every lane back to rest.
    void reset() noexcept;
    /// One lane back to rest, as after reset(): the others go on undisturbed.
    void resetLane(int lane) noexcept;
    /// Copies a lane's string and body state.
    void captureLane(int lane, LaneState& state) const;
    /// Sets a lane to `scale` times a captured state, with its friction at rest: the state of a trial that
    /// has stuck to the bow so far, which is linear in the bow's motion (RampStart.h).
    void restoreLane(int lane, const LaneState& state, double scale) noexcept;
    const LaneFriction& friction() const noexcept { return *friction_; }
    /// Advances every lane one sample and writes each lane's output.
    void step(const LaneBowInput& in, std::array<VoiceSample, kLanes>& out) noexcept;

  private:
    struct Histories
    {
        std::array<double, kLanes> Sv{}, Sa{}, Tv{}, uh{}, udh{}, uddh{}, previousFriction{};
        std::array<double, kLanes> hairX{}, hairXd{}; ///< the bow hair's state (BowHair.h)
        std::array<std::array<double, kLanes>*, 9> all() noexcept
        {
            return {&Sv, &Sa, &Tv, &uh, &udh, &uddh, &previousFriction, &hairX, &hairXd};
        }
        std::array<const std::array<double, kLanes>*, 9> all() const noexcept
        {
            return {&Sv, &Sa, &Tv, &uh, &udh, &uddh, &previousFriction, &hairX, &hairXd};
        }
    };

    VoiceCoefficients c_; ///< only its numbers are used after retune(): the pointers follow the voice
    LaneModes trans_, tors_, body_;
    Histories h_;
    std::unique_ptr<LaneFriction> friction_;
};

} // namespace rosin::physics
