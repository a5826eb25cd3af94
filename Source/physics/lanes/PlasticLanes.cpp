// The plastic law lane by lane; each step mirrors PlasticThermalLaw::solve, ThermalContact and HeatBalance.
#include "PlasticLanes.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

#include "../modal/KernelDispatch.h"
#include "../modal/VectorBlock.h"
#include "../thermal/Washout.h"

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
    stationary_.prepare(law_->heat().stationarySide());
    moving_.prepare(law_->heat().movingSide());
    force_.fill(std::numeric_limits<double>::quiet_NaN());
    reset();
}

void PlasticLanes::SideLanes::prepare(const ConductingSide& side)
{
    decay = side.decays();
    weight = side.weights();
    history.assign(decay.size(), Lanes{});
    sum = {};
}

void PlasticLanes::SideLanes::resetLane(int l) noexcept
{
    for (auto& u : history)
        u[l] = 0.0;
    sum[l] = 0.0;
}

namespace
{
// The lanes stay at x86-64-v3 at most, as their modal kernels do (LaneModes.cpp).
const SimdLevel kLevel = simdLevel() == SimdLevel::V4 ? SimdLevel::V3 : simdLevel();

// ConductingSide::advance for every lane: history holds `terms` rows of kLanes values, each row taken as
// vectors of the kernel's width.
template <int bytes>
ROSIN_KERNEL_BODY void advanceSideBody(double* __restrict history, const double* __restrict decay,
                                       const double* __restrict weight, int terms, const double* scaledFlux,
                                       const double* washout, double* sum) noexcept
{
    constexpr int lanes = bytes / static_cast<int>(sizeof(double));
    constexpr int parts = kLanes / lanes;
    using Block = VectorBlock<double, lanes>;
    Block flux[parts], s[parts], total[parts] = {};
    for (int j = 0; j < parts; ++j)
        flux[j] = loadBlock<Block>(scaledFlux + j * lanes), s[j] = loadBlock<Block>(washout + j * lanes);
    for (int m = 0; m < terms; ++m)
    {
        double* row = history + static_cast<std::ptrdiff_t>(m) * kLanes;
#pragma GCC unroll 4
        for (int j = 0; j < parts; ++j)
        {
            const Block u = loadBlock<Block>(row + j * lanes);
            const Block next = flushTinyToZero(s[j] * decay[m] * (u + weight[m] * flux[j]));
            storeBlock(row + j * lanes, next);
            total[j] += next;
        }
    }
    for (int j = 0; j < parts; ++j)
        storeBlock(sum + j * lanes, total[j]);
}

ROSIN_KERNEL_VARIANTS_BY_WIDTH(void, advanceSide,
                               (double* history, const double* decay, const double* weight, int terms,
                                const double* scaledFlux, const double* washout, double* sum),
                               (history, decay, weight, terms, scaledFlux, washout, sum))

void advanceSide(double* history, const double* decay, const double* weight, int terms,
                 const double* scaledFlux, const double* washout, double* sum) noexcept
{
    ROSIN_KERNEL_DISPATCH(kLevel, advanceSide, (history, decay, weight, terms, scaledFlux, washout, sum));
}
} // namespace

void PlasticLanes::SideLanes::advance(const Lanes& scaledFlux, const Lanes& washout) noexcept
{
    static_assert(sizeof(Lanes) == kLanes * sizeof(double), "history rows are contiguous");
    advanceSide(history.empty() ? nullptr : history.front().data(), decay.data(), weight.data(),
                static_cast<int>(history.size()), scaledFlux.data(), washout.data(), sum.data());
}

void PlasticLanes::reset() noexcept
{
    for (int l = 0; l < kLanes; ++l)
        resetLane(l);
}

void PlasticLanes::resetLane(int l) noexcept
{
    stationary_.resetLane(l);
    moving_.resetLane(l);
    temperature_[l] = previousPower_[l] = previousSpeed_[l] = 0.0;
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
        termsValid_ = false; // movingTerms() depend on the force
        const HeatBalance::ForceTerms t = law_->heat().forceTermsAt(bowForce[l]);
        capacityRate_[l] = t.capacityRate;
        advectionPerSpeed_[l] = t.advectionPerSpeed;
        kernelScale_[l] = t.kernelScale;
        invStationaryG0_[l] = t.invStationaryG0;
        invMovingG0_[l] = t.invMovingG0;
        washoutPerSpeed_[l] = t.washoutPerSpeed;
        const double a = law_->contact().rig.radiusAt(bowForce[l]);
        area_[l] = std::numbers::pi * a * a; // ThermalContact::area
    }
}

void PlasticLanes::movingTerms(const Lanes& speed, Lanes& invMoving, Lanes& decay) const noexcept
{
    if (!(termsValid_ && speed == termsSpeed_))
    {
        for (int l = 0; l < kLanes; ++l)
        {
            const double x = sanitiseNonNegative(speed[l]) * washoutPerSpeed_[l];
            termsInvMoving_[l] = invMovingG0_[l] / washout::firstStepFactor(x);
            termsWashout_[l] = washout::decay(x);
        }
        termsSpeed_ = speed;
        termsValid_ = true;
    }
    invMoving = termsInvMoving_;
    decay = termsWashout_;
}

// HeatBalance::solveTemperature with local(), lane by lane.
void PlasticLanes::predict(const Lanes& power, const Lanes& speed, Lanes& T) const noexcept
{
    Lanes invMoving, decay;
    movingTerms(speed, invMoving, decay);
    for (int l = 0; l < kLanes; ++l)
    {
        const double advection = advectionPerSpeed_[l] * sanitiseNonNegative(speed[l]);
        T[l] = (sanitiseNonNegative(power[l]) + capacityRate_[l] * temperature_[l] +
                stationary_.sum[l] * invStationaryG0_[l] + moving_.sum[l] * invMoving[l]) /
               (capacityRate_[l] + advection + invStationaryG0_[l] + invMoving[l]);
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
    Lanes invMoving, decay, toStationary, toMoving;
    movingTerms(speed, invMoving, decay);
    for (int l = 0; l < kLanes; ++l)
    {
        const double qs = (T[l] - stationary_.sum[l]) * invStationaryG0_[l];
        const double qm = (T[l] - moving_.sum[l]) * invMoving[l];
        if (!std::isfinite(T[l]) || !std::isfinite(qs) || !std::isfinite(qm))
        {
            // HeatBalance::reset(): this lane's heat model back to ambient (its previous power stays).
            stationary_.resetLane(l);
            moving_.resetLane(l);
            T[l] = toStationary[l] = toMoving[l] = 0.0;
            continue;
        }
        toStationary[l] = kernelScale_[l] * qs;
        toMoving[l] = kernelScale_[l] * qm *
                      washout::depositFactor(sanitiseNonNegative(speed[l]) * washoutPerSpeed_[l]);
    }
    static constexpr Lanes kNoWashout = []
    {
        Lanes one{};
        for (double& x : one)
            x = 1.0;
        return one;
    }();
    stationary_.advance(toStationary, kNoWashout);
    moving_.advance(toMoving, decay);
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
