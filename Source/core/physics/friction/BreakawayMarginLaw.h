#pragma once
// Breakaway in its phenomenological form: a contact at rest holds more than the law's static limit until it
// first slips. [Woodhouse-thermal] measured the force jump at the first slip of over 1000 Guettler transients
// and found it larger than steady sliding explains while the rosin is cold (its modified law, eqs. 6, 12-13,
// puts that in a jump curve h(v)). This wrapper states the same signature without a curve: until the first
// sliding sample after reset() the wrapped law sees the bow force x (1 + margin), so its static limit is
// (1 + margin) times its own (exactly so for Coulomb scaling); the first slip releases the margin for good,
// as the first slip warms a cold contact. Sliding friction is the wrapped law's throughout. Real-time safe.
#include <memory>

#include "core/physics/friction/HeldContactLaw.h"

namespace rosin::physics
{

class BreakawayMarginLaw final : public HeldContactLaw
{
  public:
    /// margin: fractional excess of the static limit at rest, >= 0.
    BreakawayMarginLaw(std::unique_ptr<FrictionLaw> inner, double margin);

    double forceFactor() const noexcept override { return released_ ? 1.0 : 1.0 + margin_; }
    /// At rest nothing has slipped: the wrapped law's limit at the raised force.
    std::optional<double> restingLimit(double bowForce) const noexcept override;
    /// Whether the contact has slipped since reset() (the margin is gone).
    bool released() const noexcept { return released_; }

  private:
    void forget() noexcept override { released_ = false; }
    /// Creeping counts as held: the junctions have not broken.
    void observe(const JunctionSolution& s) noexcept override { released_ = released_ || !s.sticking; }
    double margin_;
    bool released_ = false;
};

} // namespace rosin::physics
