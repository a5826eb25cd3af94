#include "VoiceLanes.h"

#include <cmath>
#include <stdexcept>

#include "../body/BridgeBody.h"

namespace rosin::physics
{

void VoiceLanes::prepare(const BowedStringVoice& voice, std::vector<std::unique_ptr<FrictionLaw>> laws)
{
    if (laws.size() != static_cast<std::size_t>(kLanes))
        throw std::invalid_argument("VoiceLanes::prepare: one friction law per lane is required");
    for (const auto& law : laws)
        if (!law)
            throw std::invalid_argument("VoiceLanes::prepare: a lane has no friction law");
    laws_ = std::move(laws);
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
    for (auto& law : laws_)
        law->reset();
}

void VoiceLanes::resetLane(int l) noexcept
{
    trans_.resetLane(l);
    tors_.resetLane(l);
    body_.resetLane(l);
    for (auto* x : {&h_.Sv, &h_.Sa, &h_.Tv, &h_.uh, &h_.udh, &h_.uddh, &h_.previousFriction})
        (*x)[l] = 0.0;
    laws_[l]->reset();
}

// BowedStringVoice::step() lane by lane: solveJunction(in, 0), G = R / (1 + c), finishStep(G), body advance.
void VoiceLanes::step(const LaneBowInput& in, std::array<VoiceSample, kLanes>& out) noexcept
{
    const double PL = c_.tensionPerLength, beta = c_.beta;
    LaneValues force, bridgeAcceleration, bridgeForce;
    std::array<JunctionSolution, kLanes> solution;
    std::array<double, kLanes> F{};
    for (int l = 0; l < kLanes; ++l)
    {
        const double uh = h_.uh[l], udh = h_.udh[l], uddh = h_.uddh[l];
        const double Fh = (-PL * uh - c_.M3 * uddh - h_.Sa[l]) / c_.D;
        const double vh = h_.Sv[l] + h_.Tv[l] - c_.Bv * (uddh + c_.U2 * Fh) +
                          (1.0 - beta) * (udh + c_.U1 * Fh) - c_.bandCorrection * h_.previousFriction[l];
        const double vb = in.bowVelocity[l];
        solution[l] = laws_[l]->solve({vh - vb, 1.0 / c_.y0, std::max(0.0, in.bowForce[l])});
        const double f = solution[l].frictionForce;
        const double R = (1.0 - beta - c_.A1) * f - PL * uh - c_.M3 * uddh - h_.Sa[l];
        const double G = R / (1.0 + c_.bridgeCoupling);
        F[l] = R - c_.bridgeCoupling * G;
        force.v[l] = static_cast<ModalReal>(f);
        bridgeAcceleration.v[l] = static_cast<ModalReal>(-(uddh + c_.U2 * G));
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
        out[l] = {F[l],
                  vb + solution[l].dv,
                  solution[l].frictionForce,
                  vb,
                  laws_[l]->contactTemperature(),
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
