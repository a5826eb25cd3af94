// The plastic law lane by lane; each step mirrors PlasticThermalLaw::solve, ThermalContact and HeatBalance.
#include "PlasticLanes.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

namespace rosin::physics
{

namespace
{
double sanitiseNonNegative(double x) noexcept
{
    return std::isfinite(x) ? std::abs(x) : 0.0;
}
} // namespace

PlasticLanes::PlasticLanes(std::unique_ptr<PlasticThermalLaw> law) : law_(std::move(law))
{
    if (!law_)
        throw std::invalid_argument("PlasticLanes: a prepared plastic law is required");
    decay_ = law_->heat().decays();
    weight_ = law_->heat().weights();
    history_.assign(decay_.size(), Lanes{});
    force_.fill(std::numeric_limits<double>::quiet_NaN());
    reset();
}

void PlasticLanes::reset() noexcept
{
    for (int l = 0; l < kLanes; ++l)
        resetLane(l);
}

void PlasticLanes::resetLane(int l) noexcept
{
    for (auto& u : history_)
        u[l] = 0.0;
    temperature_[l] = historySum_[l] = previousPower_[l] = previousSpeed_[l] = 0.0;
}

std::optional<double> PlasticLanes::restingLimit(double bowForce) const noexcept
{
    const double a = law_->contact().rig.radiusAt(bowForce);
    return law_->yieldStress(0.0) * std::numbers::pi * a * a; // ThermalContact::area at ambient
}

void PlasticLanes::updateForces(const Lanes& bowForce) noexcept
{
    for (int l = 0; l < kLanes; ++l)
    {
        if (bowForce[l] == force_[l])
            continue;
        force_[l] = bowForce[l];
        const HeatBalance::ForceTerms t = law_->heat().forceTermsAt(bowForce[l]);
        capacityRate_[l] = t.capacityRate;
        advectionPerSpeed_[l] = t.advectionPerSpeed;
        movingPerRootSpeed_[l] = t.movingPerRootSpeed;
        kernelScale_[l] = t.kernelScale;
        invScaledG0_[l] = t.invScaledG0;
        const double a = law_->contact().rig.radiusAt(bowForce[l]);
        area_[l] = std::numbers::pi * a * a; // ThermalContact::area
    }
}

// T = (P + C T_prev + H / g0) / (C + G_loc(v) + 1 / g0), HeatBalance::solveTemperature with local().
void PlasticLanes::predict(const Lanes& power, const Lanes& speed, Lanes& T) const noexcept
{
#pragma omp simd
    for (int l = 0; l < kLanes; ++l)
    {
        const double v = sanitiseNonNegative(speed[l]);
        const double conductance = advectionPerSpeed_[l] * v + movingPerRootSpeed_[l] * std::sqrt(v);
        T[l] = (sanitiseNonNegative(power[l]) + capacityRate_[l] * temperature_[l] +
                historySum_[l] * invScaledG0_[l]) /
               (capacityRate_[l] + conductance + invScaledG0_[l]);
    }
}

void PlasticLanes::limits(const Lanes& T, Lanes& limit) const noexcept
{
    for (int l = 0; l < kLanes; ++l)
        limit[l] = law_->yieldStress(T[l]) * area_[l]; // the shared table: one lookup per lane
}

void PlasticLanes::solveCharacteristic(const Lanes& dvh, double twoZ, const Lanes& limit,
                                       LaneJunctionSolution& out) const noexcept
{
    for (int l = 0; l < kLanes; ++l)
        out[l] = PlasticThermalLaw::solveCharacteristic(dvh[l], twoZ, limit[l]);
}

// ThermalContact::commit and HeatBalance::commit for every lane.
void PlasticLanes::commit(const LaneJunctionSolution& s) noexcept
{
    Lanes power, speed, T;
    for (int l = 0; l < kLanes; ++l)
    {
        power[l] = std::abs(s[l].frictionForce * s[l].dv);
        speed[l] = std::abs(s[l].dv);
    }
    previousPower_ = power;
    previousSpeed_ = speed;
    predict(power, speed, T);
    Lanes scaledFlux;
    for (int l = 0; l < kLanes; ++l)
    {
        const double flux = (T[l] - historySum_[l]) * invScaledG0_[l];
        if (!std::isfinite(T[l]) || !std::isfinite(flux))
        {
            // HeatBalance::reset(): this lane's heat model back to ambient (its previous power stays).
            for (auto& u : history_)
                u[l] = 0.0;
            T[l] = 0.0;
            scaledFlux[l] = 0.0;
            continue;
        }
        scaledFlux[l] = kernelScale_[l] * flux;
    }
    Lanes sum{};
    const std::size_t M = history_.size();
    for (std::size_t m = 0; m < M; ++m)
    {
        const double r = decay_[m], w = weight_[m];
        double* __restrict u = history_[m].data();
#pragma omp simd
        for (int l = 0; l < kLanes; ++l)
        {
            double next = r * (u[l] + w * scaledFlux[l]);
            next = std::abs(next) < 1e-250 ? 0.0 : next; // keep long silences free of denormals
            u[l] = next;
            sum[l] += next;
        }
    }
    historySum_ = sum;
    temperature_ = T;
}

void PlasticLanes::solve(const LaneJunctionInput& in, LaneJunctionSolution& out) noexcept
{
    Lanes dvh, Fb;
    for (int l = 0; l < kLanes; ++l)
    {
        dvh[l] = std::isfinite(in.dvHistory[l]) ? in.dvHistory[l] : 0.0;
        Fb[l] = std::isfinite(in.bowForce[l]) ? std::max(in.bowForce[l], 0.0) : 0.0;
    }
    updateForces(Fb);
    // Predictor with last sample's power, corrector with this sample's (PlasticThermalLaw::solve).
    Lanes T, limit, power, speed;
    predict(previousPower_, previousSpeed_, T);
    limits(T, limit);
    solveCharacteristic(dvh, in.loadSlope, limit, out);
    for (int l = 0; l < kLanes; ++l)
    {
        power[l] = std::abs(out[l].frictionForce * out[l].dv);
        speed[l] = std::abs(out[l].dv);
    }
    predict(power, speed, T);
    limits(T, limit);
    solveCharacteristic(dvh, in.loadSlope, limit, out);
    commit(out);
}

} // namespace rosin::physics
