#include "lab/discovery/independent/IndependentTrial.h"

#include <cmath>
#include <numbers>
#include <stdexcept>

#include "lab/discovery/synth/SynthPlan.h"

namespace rosin::discovery
{

namespace
{
physics::ContactParameters baseContact(const config::Preset& preset)
{
    if (preset.contact == "galluzzo")
        return physics::galluzzoContact();
    if (preset.contact == "schumacher")
        return physics::schumacherContact();
    throw std::invalid_argument("independent generator: unknown contact \"" + preset.contact + "\"");
}

bool hidesBreakaway(const SynthPlan& plan)
{
    for (const auto& e : plan.effects)
        if (e.effect->name == "breakaway-jump")
            return true;
    return false;
}

double bowSpeed(const Gesture& gesture, double t)
{
    if (const auto* a = std::get_if<ConstantAcceleration>(&gesture))
        return a->acceleration * t;
    if (const auto* s = std::get_if<Steady>(&gesture))
        return s->speed;
    throw std::invalid_argument("independent generator: a recorded gesture is not simulated");
}
} // namespace

IndependentRig rigFromPlan(const SynthPlan& plan, const Nuisance& nuisance, const OwnEffects& effects,
                           const GeneratorMember& member)
{
    const config::Preset& p = plan.model.preset;
    if (p.rig)
        throw std::invalid_argument("independent generator: models a bowed string, not an oscillator rig");
    // The catalog's breakaway effect swaps the plan's law for the modified one; this generator keeps the
    // plastic law and adds its own breakaway instead. Its viscous law is its own (OwnEffects::viscous).
    if (p.friction != "plastic" && p.friction != "viscous" && !hidesBreakaway(plan))
        throw std::invalid_argument(
            "independent generator: models the plastic and viscous thermal laws only, not \"" + p.friction +
            "\"");
    IndependentRig rig;
    rig.string = member.torsionOf(nuisance.apply(plan.dataset.rig.string));
    rig.member = member;
    rig.body = physics::bodyByName(plan.dataset.rig.body.value_or("rigid"));
    rig.torsion = p.torsion;
    rig.bendingStiffness = p.bendingStiffness;
    const physics::ContactParameters contact = baseContact(p);
    rig.contactRadius = p.contactOverrides.radius.value_or(contact.rig.radius) * nuisance.contactRadius;
    rig.referenceForce = p.contactOverrides.referenceForce.value_or(contact.rig.referenceForce);
    rig.layerThickness = p.contactOverrides.layerThickness.value_or(contact.rig.layerThickness);
    rig.calibration = {contact.calibration.radius, contact.calibration.referenceForce,
                       contact.calibration.layerThickness};
    physics::ThermalMaterial rosin = contact.materials.layer;
    rosin.conductivity *= nuisance.rosinConductivity;
    rosin.volumetricHeatCapacity *= nuisance.rosinHeatCapacity;
    rig.materials = {rosin, rosin, contact.materials.moving};
    rig.effects = effects;
    return rig;
}

IndependentTrialSimulator::IndependentTrialSimulator(const IndependentRig& rig, double internalRate)
    : rig_(rig), rate_(internalRate), table_(rig.calibration, rig.materials, 1.0 / internalRate)
{
}

double IndependentTrialSimulator::contactArea(double bowForce) const
{
    const double f = std::max(bowForce, 0.0);
    const double a2 = std::numbers::pi * rig_.contactRadius * rig_.contactRadius;
    if (!rig_.effects.hertz)
        return a2 * f / rig_.referenceForce;
    // Equal to the Coulomb area at the reference force, ~ F^exponent about it.
    const double fr = rig_.effects.hertzReferenceForce;
    return a2 * fr / rig_.referenceForce * std::pow(f / fr, rig_.effects.hertzExponent);
}

WaveguideSettings IndependentTrialSimulator::waveguide(double beta) const
{
    const auto& s = rig_.string;
    WaveguideSettings w;
    w.tension = s.tension;
    w.massPerLength = s.massPerLength;
    w.length = s.length;
    w.beta = beta;
    w.transverseLoss = stringLossLaw(
        s.tension, s.massPerLength, rig_.bendingStiffness ? s.bendingStiffness : 0.0, s.etaF(false), s.etaB(),
        s.etaA(), rig_.effects.extraEta, rig_.effects.bendingLossFactor);
    w.bendingStiffness = rig_.bendingStiffness && rig_.dispersion ? s.bendingStiffness : 0.0;
    w.torsion = rig_.torsion;
    w.torsionalWaveSpeed = s.torsionalWaveSpeed;
    w.torsionalQ = s.torsionalQ;
    w.torsionalImpedance = s.torsionalImpedance;
    w.body = rig_.body;
    w.sampleRate = rate_;
    w.lossFitHarmonic = rig_.member.lossFitHarmonic;
    w.dispersionFitTopHz = rig_.member.dispersionFitTopHz;
    return w;
}

const TrialTrace& IndependentTrialSimulator::run(const TrialSettings& settings)
{
    const double dt = 1.0 / rate_;
    const double area = contactArea(settings.bowForce);
    WaveguideString string(waveguide(settings.beta));
    const HeatGrid grid{rig_.member.heatSurfaceCell, rig_.member.heatGridGrowth, rig_.member.advectionWidth};
    ContactHeat heat(std::sqrt(area / std::numbers::pi), rig_.layerThickness, rig_.materials, dt, grid);
    ContactFriction friction(table_, area, rig_.layerThickness, rig_.effects, dt);

    const auto n = static_cast<std::size_t>(std::llround(settings.seconds * rate_));
    trace_ = TrialTrace{};
    for (auto* c : {&trace_.bridgeForce, &trace_.frictionForce, &trace_.bowPointVelocity, &trace_.bowVelocity,
                    &trace_.temperature})
        c->reserve(n);
    trace_.sticking.reserve(n);
    double lastSlip = 0.0;
    for (std::size_t k = 0; k < n; ++k)
    {
        const double vb = bowSpeed(settings.gesture, static_cast<double>(k) * dt);
        const double vh = string.beginStep(k);
        const ContactHeat::Prediction predicted = heat.predict(lastSlip);
        const FrictionSolution s = friction.solve(vh - vb, string.admittance(), predicted);
        lastSlip = std::abs(s.slip);
        heat.finish(s.power);
        string.finishStep(k, s.force);
        trace_.bridgeForce.push_back(string.bridgeForce());
        trace_.frictionForce.push_back(s.force);
        trace_.bowPointVelocity.push_back(vb + s.slip);
        trace_.bowVelocity.push_back(vb);
        trace_.temperature.push_back(heat.temperature());
        trace_.sticking.push_back(s.sticking ? 1 : 0);
    }
    return trace_;
}

} // namespace rosin::discovery
