// [Smith2000]'s single-mode stick-slip rig (OscillatorRig.h).
#include "core/physics/rig/OscillatorRig.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/physics/units/Range.h"

namespace rosin::physics
{

void OscillatorRig::prepare(const OscillatorRigParameters& rig, std::unique_ptr<FrictionLaw> friction,
                            double sampleRate)
{
    if (!friction)
        throw std::invalid_argument("OscillatorRig::prepare: a friction law is required");
    if (!(sampleRate >= limits::sampleRate.min && sampleRate <= limits::sampleRate.max))
        throw std::invalid_argument("OscillatorRig::prepare: sample rate must be " +
                                    formatNumber(limits::sampleRate.min) + ".." +
                                    formatNumber(limits::sampleRate.max) + " Hz");
    rig.validate();
    rig_ = rig;
    sampleRate_ = sampleRate;
    // x'' + (omega0/Q) x' + omega0^2 x = f/m: ModalBank's loss factor 1/Q gives sigma = omega0 / (2Q) =
    // R/(2m).
    mode_.configure({ModeSpec{rig.angularFrequency(), 1.0 / rig.qualityFactor}}, sampleRate);
    gain_ = 1.0 / rig.modalMass;
    gainIn_ = static_cast<ModalReal>(gain_);
    auto weights = [&](OutputWeights& o, ModalOutput kind)
    {
        o.assign(1);
        const auto r = 2.0 * mode_.residue(0, kind);
        o.set(0, r);
    };
    weights(xWeights_, ModalOutput::Displacement);
    weights(vWeights_, ModalOutput::Velocity);
    weights(aWeights_, ModalOutput::Acceleration);
    xDirect_ = mode_.direct(0, ModalOutput::Displacement) * gain_;
    vDirect_ = mode_.direct(0, ModalOutput::Velocity) * gain_;
    aDirect_ = mode_.direct(0, ModalOutput::Acceleration) * gain_;
    bandCorrection_ = 0.5 / (sampleRate * rig.modalMass);
    y0_ = vDirect_ + bandCorrection_;
    // The load line needs a positive instantaneous admittance (about T / 2m); a sampled mode always has one
    // below Nyquist, so failing here means a broken discretisation, not a user error.
    if (!(y0_ > 0.0))
        throw std::logic_error("OscillatorRig::prepare: non-positive contact admittance");
    friction_ = std::move(friction);
    friction_->prepare(sampleRate);
    reset();
}

void OscillatorRig::reset() noexcept
{
    mode_.reset();
    xHistory_ = vHistory_ = aHistory_ = previousForce_ = 0.0;
    if (friction_)
        friction_->reset();
    recovered_ = false;
}

RigSample OscillatorRig::step(const RigInput& in) noexcept
{
    recovered_ = false;
    const double N = std::isfinite(in.normalForce) ? std::max(0.0, in.normalForce) : 0.0;
    const double vRod = std::isfinite(in.rodVelocity) ? in.rodVelocity : 0.0;
    // The same junction as the string's: sliding speed with zero force this sample, and 2Z = 1/y0.
    const double vh = vHistory_ - bandCorrection_ * previousForce_;
    const JunctionSolution s = friction_->solve({vh - vRod, 1.0 / y0_, N});
    const double f = s.frictionForce;

    RigSample out;
    out.displacement = xHistory_ + xDirect_ * f;
    out.velocity = vh + y0_ * f; // = vRod + s.dv: the contact's velocity, band correction included
    out.acceleration = aHistory_ + aDirect_ * f;
    out.frictionForce = f;
    out.slidingSpeed = s.dv;
    out.rodVelocity = vRod;
    out.normalForce = N;
    out.supportForce = rig_.stiffness() * out.displacement + rig_.resistance() * out.velocity;
    out.contactTemperature = friction_->contactTemperature();
    out.sticking = s.sticking;

    const ThreeSums next = advanceOneInputThreeOutputs(mode_, &gainIn_, f, xWeights_, vWeights_, aWeights_);
    xHistory_ = next.first, vHistory_ = next.second, aHistory_ = next.third;
    previousForce_ = f;
    // A runaway is reset rather than heard (as BowedStringVoice does): no rig of this kind reaches 1e3 m/s.
    if (!std::isfinite(vHistory_) || !std::isfinite(f) || std::abs(vHistory_) > 1e3)
    {
        reset();
        recovered_ = true;
        out = RigSample{};
        out.rodVelocity = vRod;
        out.normalForce = N;
    }
    return out;
}

} // namespace rosin::physics
