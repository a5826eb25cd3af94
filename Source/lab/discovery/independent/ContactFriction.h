#pragma once
// The friction solve of one sample ([Notes §2.2] with §2.5's coupling, made implicit in the step's own
// heating): the plastic law f = A tau_y(T) with the contact temperature of ContactHeat, plus the own-form
// effects (OwnEffects.h) that act on the static limit and on sticking.
//
// The load line is f = (dv - dv_h) / Y (Y the bow point's admittance, dv = v - v_b, dv_h its history part).
//   stick  if the force that holds dv = 0, |dv_h| / Y, is within the static limit at the unheated temperature
//          (a sticking contact does no work); with creep, a nominally stuck contact above the creep threshold
//          slides back at (|f| - threshold) / resistance, which lowers the force it needs;
//   slide  otherwise, at |f| = A tau_y(T(P)) with P = |f| |dv| and T(P) = free + P / pivot from the heat
//          step: one unknown |f| in [0, |dv_h| / Y], bracketed (the residual is negative at 0 and positive at
//          the sticking force), solved by the Illinois method [DowellJarratt1971].
// With the viscous law (OwnEffects::viscous) there is no stick: the contact always slides, at
// |f| = A eta(T(P)) |dv| / layer with dv on the load line, the same bracket and the same solve.
#include "lab/discovery/independent/ContactHeat.h"
#include "lab/discovery/independent/OwnEffects.h"
#include "lab/discovery/independent/YieldStressTable.h"

namespace rosin::discovery
{

struct FrictionSolution
{
    double force = 0.0; ///< N, on the string
    double slip = 0.0;  ///< dv, m/s (0 when stuck, small when creeping)
    double power = 0.0; ///< W, heat into the contact
    bool sticking = true;
};

class ContactFriction
{
  public:
    /// `area`: the contact area at this trial's bow force (m^2); `layer`: the bowing rig's rosin layer (m).
    ContactFriction(const YieldStressTable& table, double area, double layer, const OwnEffects& effects,
                    double dt);

    FrictionSolution solve(double historySlip, double admittance,
                           const ContactHeat::Prediction& heat) noexcept;
    void reset() noexcept { holdTime_ = 0.0; }

    /// Plastic friction limit A tau_y(T + offset) (N).
    double plastic(double temperature) const noexcept;
    /// Static limit with the effects of sticking: ageing over the hold time, cold breakaway.
    double staticLimit(double temperature) const noexcept;

  private:
    FrictionSolution slide(double historySlip, double admittance, const ContactHeat::Prediction& heat) const;
    FrictionSolution slideViscous(double historySlip, double admittance,
                                  const ContactHeat::Prediction& heat) const;
    const YieldStressTable& table_;
    double area_;
    double layer_;
    OwnEffects effects_;
    double dt_;
    double holdTime_ = 0.0;
};

} // namespace rosin::discovery
