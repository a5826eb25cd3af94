#pragma once
// One trial of the independent generator: the waveguide string (WaveguideString), the contact's heat balance
// (ContactHeat) and the plastic friction solve with the own-form effects (ContactFriction), stepped together
// at the internal rate (twice the dataset's), for the bow gesture of the trial (v_b = a t from rest, or a
// constant speed from t = 0). Nothing here comes from Rosin's stepping classes; the rig's handbook data
// (string, body mode table, contact geometry, materials) does.
#include <vector>

#include "lab/discovery/TrialSimulator.h"
#include "lab/discovery/independent/ContactFriction.h"
#include "lab/discovery/independent/GeneratorMember.h"
#include "lab/discovery/independent/Nuisance.h"
#include "lab/discovery/independent/WaveguideString.h"

namespace rosin::discovery
{

struct SynthPlan;

/// Everything fixed for a dataset: the real string and contact (nominal x nuisance) and the own effects.
struct IndependentRig
{
    physics::StringParameters string;
    physics::BodyParameters body; ///< no modes: rigid bridge
    bool torsion = true;
    bool bendingStiffness = true; ///< EI in the loss law (and in the dispersion allpass when that is on)
    /// The stiff string's dispersion allpass (DispersionAllpass), part of the stated physics ([Notes §4.2])
    /// whenever bendingStiffness is on. Without it the Helmholtz corner stays too sharp: the bridge force
    /// came out 3.5-4.5 dB brighter (harmonic tilt) than Rosin's stiff modal string.
    bool dispersion = true;
    double contactRadius = 250e-6; ///< m at referenceForce (Coulomb: a ~ sqrt F)
    double referenceForce = 1.0;   ///< N
    double layerThickness = 1e-6;  ///< m
    CalibrationContact calibration;
    HeatMaterials materials;
    OwnEffects effects;
    GeneratorMember member; ///< the family member's numerics (its constants are applied to `string`)
};

/// The rig of a plan: its preset's string, body and contact (as stated), with the nuisance applied and the
/// plan's hidden effects in their own forms. Throws std::invalid_argument for a preset this generator does
/// not model (a friction law other than the plastic one without a hidden breakaway, or an oscillator rig).
/// The member's torsional constants scale the string's; its body choice is the plan's to state
/// (applyMemberRig), so the rig keeps the plan's body.
IndependentRig rigFromPlan(const SynthPlan& plan, const Nuisance& nuisance, const OwnEffects& effects,
                           const GeneratorMember& member = {});

/// What one trial did, at the internal rate.
struct TrialTrace
{
    std::vector<double> bridgeForce;      ///< N
    std::vector<double> frictionForce;    ///< N, on the string
    std::vector<double> bowPointVelocity; ///< m/s, string surface at the bow
    std::vector<double> bowVelocity;      ///< m/s
    std::vector<double> temperature;      ///< K above ambient (the rosin's start)
    std::vector<unsigned char> sticking;  ///< 1 while (nominally) stuck
};

class IndependentTrialSimulator
{
  public:
    /// Calibrates the yield-stress table for this rig and rate (a few ms).
    IndependentTrialSimulator(const IndependentRig& rig, double internalRate);

    const TrialTrace& run(const TrialSettings& settings);

    /// Real contact area at a bow force (m^2): Coulomb, or the own Hertz form.
    double contactArea(double bowForce) const;
    const YieldStressTable& table() const noexcept { return table_; }
    double internalRate() const noexcept { return rate_; }

  private:
    WaveguideSettings waveguide(double beta) const;
    IndependentRig rig_;
    double rate_;
    YieldStressTable table_;
    TrialTrace trace_;
};

} // namespace rosin::discovery
