#include "core/physics/body/BridgeBody.h"

#include "core/physics/body/BodyRadiation.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace rosin::physics
{

void BridgeBody::configure(const BodyParameters& body, double sampleRate, double modeLimit, bool radiates)
{
    radiates_ = radiates;
    std::vector<ModeSpec> specs;
    std::vector<double> radiation; // c_k, Pa per m/s^2
    gain_.clear();
    for (const auto& mode : body.modes)
    {
        const double omega = 2.0 * std::numbers::pi * mode.frequency;
        if (omega >= modeLimit)
            continue;
        specs.push_back({omega, 1.0 / mode.q});
        gain_.push_back(1.0 / mode.effectiveMass);
        radiation.push_back(pressurePerAcceleration(mode, body.radiation));
    }
    while (!specs.empty() && static_cast<int>(specs.size()) % kModalBlock != 0)
    {
        specs.push_back(specs.back());
        gain_.push_back(0.0); // silent padding: never driven, so its state stays zero
        radiation.push_back(0.0);
    }
    bank_.configure(specs, sampleRate);
    lowpassCoefficient_ =
        -std::expm1(-2.0 * std::numbers::pi * body.radiation.unityEfficiencyHz / sampleRate);
    gainIn_.assign(gain_.begin(), gain_.end());
    for (auto* o : {&u_, &ud_, &udd_, &p_})
        o->assign(bank_.size());
    U0_ = U1_ = U2_ = P0_ = 0.0;
    for (int j = 0; j < bank_.size(); ++j)
    {
        const auto rd = 2.0 * bank_.residue(j, ModalOutput::Displacement);
        const auto rv = 2.0 * bank_.residue(j, ModalOutput::Velocity);
        const auto ra = 2.0 * bank_.residue(j, ModalOutput::Acceleration);
        u_.set(j, rd);
        ud_.set(j, rv);
        udd_.set(j, ra);
        p_.set(j, ra * radiation[static_cast<std::size_t>(j)]);
        U0_ += bank_.direct(j, ModalOutput::Displacement) * gain_[j];
        U1_ += bank_.direct(j, ModalOutput::Velocity) * gain_[j];
        U2_ += bank_.direct(j, ModalOutput::Acceleration) * gain_[j];
        P0_ += bank_.direct(j, ModalOutput::Acceleration) * gain_[j] * radiation[static_cast<std::size_t>(j)];
    }
    reset();
}

void BridgeBody::reset() noexcept
{
    bank_.reset();
    uh_ = udh_ = uddh_ = ph_ = lastForce_ = 0.0;
    pressureNow_ = velocityNow_ = compactPressure_ = 0.0;
}

void BridgeBody::advance(double bridgeForce) noexcept
{
    lastForce_ = bridgeForce;
    if (bank_.size() == 0)
        return;
    if (radiates_)
    {
        compactPressure_ = ph_ + P0_ * bridgeForce;
        pressureNow_ += lowpassCoefficient_ * (compactPressure_ - pressureNow_);
    }
    velocityNow_ = udh_ + U1_ * bridgeForce;
    if (radiates_) // the pressure's history comes out of the same pass over the modes
    {
        const FourSums s = advanceOneInputFourOutputs(bank_, gainIn_.data(), bridgeForce, u_, ud_, udd_, p_);
        uh_ = s.first, udh_ = s.second, uddh_ = s.third, ph_ = s.fourth;
        return;
    }
    const ThreeSums s = advanceOneInputThreeOutputs(bank_, gainIn_.data(), bridgeForce, u_, ud_, udd_);
    uh_ = s.first, udh_ = s.second, uddh_ = s.third;
}

int BridgeBody::modeCount() const noexcept
{
    return static_cast<int>(std::count_if(gain_.begin(), gain_.end(), [](double g) { return g != 0.0; }));
}

double BridgeBody::displacementAtLastStep() const noexcept
{
    double u = 0.0;
    for (int j = 0; j < bank_.size(); ++j)
        u += bank_.outputAtLastStep(j, ModalOutput::Displacement, lastForce_ * gain_[j]);
    return u;
}

double BridgeBody::velocityAtLastStep() const noexcept
{
    double v = 0.0;
    for (int j = 0; j < bank_.size(); ++j)
        v += bank_.outputAtLastStep(j, ModalOutput::Velocity, lastForce_ * gain_[j]);
    return v;
}

double BridgeBody::energyAtLastStep() const noexcept
{
    double e = 0.0;
    for (int j = 0; j < bank_.size(); ++j)
    {
        if (gain_[j] == 0.0)
            continue; // padding
        const double in = lastForce_ * gain_[j];
        const double x = bank_.outputAtLastStep(j, ModalOutput::Displacement, in);
        const double v = bank_.outputAtLastStep(j, ModalOutput::Velocity, in);
        e += 0.5 / gain_[j] * (v * v + bank_.modalStiffness(j) * x * x);
    }
    return e;
}

} // namespace rosin::physics
