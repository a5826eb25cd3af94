#include "core/physics/lanes/VoiceLanes.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/physics/body/BridgeBody.h"

namespace rosin::physics
{

void VoiceLanes::prepare(const BowedStringVoice& voice, std::unique_ptr<LaneFriction> friction)
{
    if (!friction)
        throw std::invalid_argument("VoiceLanes::prepare: the lanes need their friction");
    friction_ = std::move(friction);
    retune(voice);
}

void VoiceLanes::retune(const BowedStringVoice& voice)
{
    c_ = voice.coefficients();
    trans_.assign(*c_.transverse, c_.transverseForceGain, c_.transverseBridgeGain, c_.transverseVelocity,
                  c_.transverseAcceleration);
    tors_.assign(*c_.torsional, c_.torsionalForceGain, nullptr, c_.torsionalVelocity);
    const BridgeBody& b = *c_.body;
    body_.assign(b.bank(), b.inputGains(), nullptr, &b.displacementWeights(), &b.velocityWeights(),
                 &b.accelerationWeights());
    reset();
}

void VoiceLanes::reset() noexcept
{
    trans_.reset();
    tors_.reset();
    body_.reset();
    h_ = {};
    friction_->reset();
}

void VoiceLanes::resetLane(int l) noexcept
{
    trans_.resetLane(l);
    tors_.resetLane(l);
    body_.resetLane(l);
    for (auto* x : h_.all())
        (*x)[l] = 0.0;
    friction_->resetLane(l);
}

void VoiceLanes::captureLane(int l, LaneState& state) const
{
    state.modes.clear();
    for (const LaneModes* bank : {&trans_, &tors_, &body_})
        for (int k = 0; k < bank->modes; ++k)
        {
            state.modes.push_back(bank->w[k].re[l]);
            state.modes.push_back(bank->w[k].im[l]);
        }
    const auto h = h_.all();
    for (std::size_t i = 0; i < h.size(); ++i)
        state.histories[i] = (*h[i])[l];
}

void VoiceLanes::restoreLane(int l, const LaneState& state, double scale) noexcept
{
    const auto scaled = [scale](ModalReal x)
    { return static_cast<ModalReal>(scale * static_cast<double>(x)); };
    std::size_t i = 0;
    for (LaneModes* bank : {&trans_, &tors_, &body_})
        for (int k = 0; k < bank->modes && i + 1 < state.modes.size(); ++k, i += 2)
        {
            bank->w[k].re[l] = scaled(state.modes[i]);
            bank->w[k].im[l] = scaled(state.modes[i + 1]);
        }
    auto h = h_.all();
    for (std::size_t j = 0; j < h.size(); ++j)
        (*h[j])[l] = scale * state.histories[j];
    friction_->resetLane(l);
}

// BowedStringVoice::step() lane by lane: solveJunction(in, 0), G = R / (1 + c), finishStep(G), body advance.
void VoiceLanes::step(const LaneBowInput& in, std::array<VoiceSample, kLanes>& out) noexcept
{
    const JunctionTerms& j = c_.junction;
    const HairTerms& hair = c_.hair;
    const bool compliantHair = hair.admittance > 0.0;
    LaneJunctionInput junction;
    junction.loadSlope = 1.0 / (j.y0 + hair.admittance);
    std::array<JunctionHistories, kLanes> histories;
    std::array<double, kLanes> hairH{};
    for (int l = 0; l < kLanes; ++l)
    {
        histories[l] = {
            h_.Sv[l], h_.Sa[l], h_.Tv[l], h_.uh[l], h_.udh[l], h_.uddh[l], h_.previousFriction[l]};
        junction.dvHistory[l] = j.loadLineHistory(histories[l], 0.0) - in.bowVelocity[l];
        if (compliantHair)
        {
            hairH[l] = hairHistory(hair, {h_.hairX[l], h_.hairXd[l]});
            junction.dvHistory[l] -= hairH[l];
        }
        junction.bowForce[l] = std::max(0.0, in.bowForce[l]);
    }
    LaneJunctionSolution solution;
    friction_->solve(junction, solution);
    LaneValues force, bridgeAcceleration, bridgeForce;
    std::array<double, kLanes> F{};
    for (int l = 0; l < kLanes; ++l)
    {
        const double f = solution[l].frictionForce;
        const double R = j.bridgeForceBeforeCoupling(f, histories[l]);
        const double G = R / (1.0 + j.bridgeCoupling);
        F[l] = R - j.bridgeCoupling * G;
        force.v[l] = static_cast<ModalReal>(f);
        bridgeAcceleration.v[l] = static_cast<ModalReal>(-(h_.uddh[l] + j.U2 * G));
        bridgeForce.v[l] = static_cast<ModalReal>(G);
        h_.previousFriction[l] = f;
    }
    LaneValues sv, sa, tv, u, ud, udd;
    advanceTwoInputsTwoOutputs(trans_, force, bridgeAcceleration, sv, sa);
    if (tors_.modes > 0)
        advanceOneInputOneOutput(tors_, force, tv);
    if (body_.modes > 0)
        advanceOneInputThreeOutputs(body_, bridgeForce, u, ud, udd);
    for (int l = 0; l < kLanes; ++l)
    {
        h_.Sv[l] = sv.v[l], h_.Sa[l] = sa.v[l], h_.Tv[l] = tv.v[l];
        h_.uh[l] = u.v[l], h_.udh[l] = ud.v[l], h_.uddh[l] = udd.v[l];
        const double vb = in.bowVelocity[l];
        double stringVelocity = vb + solution[l].dv;
        if (compliantHair)
        {
            HairState s{h_.hairX[l], h_.hairXd[l]};
            stringVelocity += advanceHair(hair, s, hairH[l], solution[l].frictionForce);
            h_.hairX[l] = s.x, h_.hairXd[l] = s.xd;
        }
        out[l] = {F[l],
                  stringVelocity,
                  solution[l].frictionForce,
                  vb,
                  friction_->contactTemperature(l),
                  solution[l].sticking};
        // As the voice: a runaway (non-finite or absurd) lane is reset rather than heard.
        if (!std::isfinite(F[l]) || !std::isfinite(h_.Sv[l]) || std::abs(F[l]) > 1e4)
        {
            resetLane(l);
            out[l] = VoiceSample{};
            out[l].bowVelocity = vb;
        }
    }
}

} // namespace rosin::physics
