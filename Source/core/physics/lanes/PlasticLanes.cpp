// The plastic law lane by lane; each step mirrors PlasticThermalLaw::solve, ThermalContact and HeatBalance.
#include "core/physics/lanes/PlasticLanes.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <numbers>
#include <stdexcept>

#include "core/physics/modal/KernelDispatch.h"
#include "core/physics/modal/VectorBlock.h"
#include "core/physics/thermal/Washout.h"

namespace rosin::physics
{

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
// Eight lanes of doubles fill one AVX-512 register: unlike the modal lanes (eight floats, LaneModes.cpp),
// these kernels take the best level. Lane-wise arithmetic, so every level gives a lane the same result where
// both fuse multiply-adds (x86-64-v3 and v4: a 60 x 60 Guettler scan is byte-identical on the two).
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
    ROSIN_KERNEL_DISPATCH(simdLevel(), advanceSide,
                          (history, decay, weight, terms, scaledFlux, washout, sum));
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

namespace
{
// The per-sample arithmetic of every lane in vectors of the kernel's width (VectorBlock.h: w = 8 doubles on
// AVX-512, 4 on AVX2, 2 on SSE; the lanes go w at a time), each line the scalar law's (HeatBalance,
// ThermalContact, PlasticThermalLaw) applied lane-wise in the same order. Lanes the vector formulas do not
// cover (a washout step x >= 0.25, a temperature off the calibration's uniform grid) take the scalar
// functions.
struct StepData
{
    // Per lane, this sample.
    const double *dvh, *capacityRate, *advectionPerSpeed, *kernelScale, *invStationaryG0, *invMovingG0,
        *washoutPerSpeed, *area;
    const double *stationarySum, *movingSum, *temperature, *previousPower, *previousSpeed;
    double loadSlope, ambientOffset;
    ThermalCalibration::UniformGrid grid;
    const ThermalCalibration* table;
    // Results: the solution, the commit's fluxes, the moving side's washout and temperature.
    double *dv, *frictionForce, *sticking, *power, *speed, *toStationary, *toMoving, *washout, *committed;
};

template <typename V> ROSIN_KERNEL_BODY V absolute(V x) noexcept
{
    return x < 0.0 ? -x : x;
}
/// sanitiseNonNegative, lane-wise: |x|, or 0 where x is not finite.
template <typename V> ROSIN_KERNEL_BODY V nonNegative(V x) noexcept
{
    const V a = absolute(x);
    return a <= std::numeric_limits<double>::max() ? a : V{};
}
/// True if any lane of a comparison's result is set.
template <typename M> ROSIN_KERNEL_BODY bool any(M mask) noexcept
{
    constexpr int w = sizeof(M) / sizeof(mask[0]);
    long long bits[w];
    std::memcpy(bits, &mask, sizeof bits);
    long long all = 0;
    for (int l = 0; l < w; ++l)
        all |= bits[l];
    return all != 0;
}

/// washout::firstStepFactor and washout::decay of x = |dv| dt / ell: their series, and the functions
/// themselves in the lanes past the series' limit.
template <typename V> ROSIN_KERNEL_BODY void washoutTerms(V x, V& firstStep, V& decay) noexcept
{
    firstStep = washout::firstStepSeries(x);
    decay = washout::decaySeries(x);
    if (any(!(x < washout::kSeriesLimit)))
        for (int l = 0; l < static_cast<int>(sizeof(V) / sizeof(double)); ++l)
            if (!(x[l] < washout::kSeriesLimit))
                firstStep[l] = washout::firstStepFactor(x[l]), decay[l] = washout::decay(x[l]);
}
/// washout::depositFactor, likewise.
template <typename V> ROSIN_KERNEL_BODY V depositFactor(V x) noexcept
{
    V d = washout::depositSeries(x);
    if (any(!(x < washout::kSeriesLimit)))
        for (int l = 0; l < static_cast<int>(sizeof(V) / sizeof(double)); ++l)
            if (!(x[l] < washout::kSeriesLimit))
                d[l] = washout::depositFactor(x[l]);
    return d;
}

/// HeatBalance::predict with local(): the temperature each lane reaches with power P at sliding speed v.
template <typename V>
ROSIN_KERNEL_BODY V predictTemperature(const StepData& d, int j, V power, V speed, V& invMoving,
                                       V& decay) noexcept
{
    const V v = nonNegative(speed);
    V firstStep;
    washoutTerms(v * loadBlock<V>(d.washoutPerSpeed + j), firstStep, decay);
    invMoving = loadBlock<V>(d.invMovingG0 + j) / firstStep;
    const V C = loadBlock<V>(d.capacityRate + j), invS = loadBlock<V>(d.invStationaryG0 + j);
    const V advection = loadBlock<V>(d.advectionPerSpeed + j) * v;
    return (nonNegative(power) + C * loadBlock<V>(d.temperature + j) +
            loadBlock<V>(d.stationarySum + j) * invS + loadBlock<V>(d.movingSum + j) * invMoving) /
           (C + advection + invS + invMoving);
}

/// PlasticThermalLaw::frictionLimit: tau_y(T + ambient offset) from the uniform grid, times the area.
template <typename V> ROSIN_KERNEL_BODY V frictionLimit(const StepData& d, int j, V T) noexcept
{
    constexpr int w = sizeof(V) / sizeof(double);
    using I = VectorBlock<long long, w>;
    const V Toff = T + d.ambientOffset;
    const V x = Toff / d.grid.step;
    // Lanes off the grid (below its first cell, above its top, NaN) read cell 1 and are replaced below.
    const auto onGrid = Toff > 0.0 && x >= 1.0 && x < static_cast<double>(d.grid.size - 1);
    const V inside = onGrid ? x : V{} + 1.0;
    const I i = __builtin_convertvector(inside, I);
    const V frac = inside - __builtin_convertvector(i, V);
    V lower, upper;
    for (int l = 0; l < w; ++l)
        lower[l] = d.grid.values[i[l]], upper[l] = d.grid.values[i[l] + 1];
    V tau = lower + frac * (upper - lower);
    if (d.grid.isLog || any(!onGrid))
        for (int l = 0; l < w; ++l)
            tau[l] = !onGrid[l] ? d.table->lookup(Toff[l]) : d.grid.isLog ? std::exp(tau[l]) : tau[l];
    return tau * loadBlock<V>(d.area + j);
}

/// PlasticThermalLaw::solveCharacteristic, lane-wise.
template <typename V>
ROSIN_KERNEL_BODY void solveCharacteristic(const StepData& d, V dvh, V limit, V& dv, V& f, V& stuck) noexcept
{
    const V pull = d.loadSlope * dvh;
    const auto holds = absolute(pull) <= limit;
    const V side = dvh > 0.0 ? V{} + 1.0 : V{} - 1.0;
    dv = holds ? V{} : dvh - side * limit / d.loadSlope;
    f = holds ? -pull : -side * limit;
    stuck = holds ? V{} + 1.0 : V{};
}

// PlasticThermalLaw::step for lanes j .. j + w - 1, up to the heat balance's side advances: predictor, exact
// solve, corrector, exact solve, and the commit's temperature and fluxes.
template <typename V> ROSIN_KERNEL_BODY void stepLanes(const StepData& d, int j) noexcept
{
    const V dvh = loadBlock<V>(d.dvh + j);
    V invMoving, decay, dv, f, stuck;
    V T = predictTemperature(d, j, loadBlock<V>(d.previousPower + j), loadBlock<V>(d.previousSpeed + j),
                             invMoving, decay);
    solveCharacteristic(d, dvh, frictionLimit(d, j, T), dv, f, stuck);
    T = predictTemperature(d, j, absolute(f * dv), absolute(dv), invMoving, decay);
    solveCharacteristic(d, dvh, frictionLimit(d, j, T), dv, f, stuck);
    const V power = absolute(f * dv), speed = absolute(dv);
    T = predictTemperature(d, j, power, speed, invMoving, decay);
    const V qs = (T - loadBlock<V>(d.stationarySum + j)) * loadBlock<V>(d.invStationaryG0 + j);
    const V qm = (T - loadBlock<V>(d.movingSum + j)) * invMoving;
    const V ks = loadBlock<V>(d.kernelScale + j);
    storeBlock(d.toStationary + j, ks * qs);
    storeBlock(d.toMoving + j,
               ks * qm * depositFactor(nonNegative(speed) * loadBlock<V>(d.washoutPerSpeed + j)));
    storeBlock(d.washout + j, decay);
    storeBlock(d.committed + j, T);
    storeBlock(d.dv + j, dv);
    storeBlock(d.frictionForce + j, f);
    storeBlock(d.sticking + j, stuck);
    storeBlock(d.power + j, power);
    storeBlock(d.speed + j, speed);
}

template <int bytes> ROSIN_KERNEL_BODY void stepBody(const StepData& d) noexcept
{
    constexpr int w = bytes / static_cast<int>(sizeof(double));
    static_assert(kLanes % w == 0, "the lanes fill whole vectors");
#pragma GCC unroll 4
    for (int j = 0; j < kLanes; j += w)
        stepLanes<VectorBlock<double, w>>(d, j);
}

ROSIN_KERNEL_VARIANTS_BY_WIDTH(void, step, (const StepData& d), (d))

void stepAllLanes(const StepData& d) noexcept
{
    ROSIN_KERNEL_DISPATCH(simdLevel(), step, (d));
}
} // namespace

void PlasticLanes::solve(const LaneJunctionInput& in, LaneJunctionSolution& out) noexcept
{
    Lanes dvh, Fb;
    for (int l = 0; l < kLanes; ++l)
    {
        dvh[l] = std::isfinite(in.dvHistory[l]) ? in.dvHistory[l] : 0.0;
        Fb[l] = std::isfinite(in.bowForce[l]) ? std::max(in.bowForce[l], 0.0) : 0.0;
    }
    updateForces(Fb);
    Lanes dv, f, stuck, power, speed, toStationary, toMoving, washout, T;
    const StepData d{dvh.data(),
                     capacityRate_.data(),
                     advectionPerSpeed_.data(),
                     kernelScale_.data(),
                     invStationaryG0_.data(),
                     invMovingG0_.data(),
                     washoutPerSpeed_.data(),
                     area_.data(),
                     stationary_.sum.data(),
                     moving_.sum.data(),
                     temperature_.data(),
                     previousPower_.data(),
                     previousSpeed_.data(),
                     in.loadSlope,
                     law_->contact().ambientOffset,
                     law_->calibration().uniformGrid(),
                     &law_->calibration(),
                     dv.data(),
                     f.data(),
                     stuck.data(),
                     power.data(),
                     speed.data(),
                     toStationary.data(),
                     toMoving.data(),
                     washout.data(),
                     T.data()};
    stepAllLanes(d);
    for (int l = 0; l < kLanes; ++l)
    {
        out[l] = {dv[l], f[l], stuck[l] != 0.0};
        if (Fb[l] == 0.0)
        {
            // Bow lifted: the open contact makes and passes no heat, each side decays alone
            // (HeatBalance::open); its temperature is set from the stationary side below.
            power[l] = speed[l] = toStationary[l] = toMoving[l] = 0.0;
            washout[l] = 1.0;
        }
        else if (!std::isfinite(T[l]) || !std::isfinite(toStationary[l]) || !std::isfinite(toMoving[l]))
        {
            // HeatBalance::reset(): this lane's heat model back to ambient (its previous power stays).
            stationary_.resetLane(l);
            moving_.resetLane(l);
            T[l] = toStationary[l] = toMoving[l] = 0.0;
        }
    }
    static constexpr Lanes kNoWashout = []
    {
        Lanes one{};
        for (double& x : one)
            x = 1.0;
        return one;
    }();
    stationary_.advance(toStationary, kNoWashout);
    moving_.advance(toMoving, washout);
    for (int l = 0; l < kLanes; ++l)
        temperature_[l] = Fb[l] == 0.0 ? stationary_.sum[l] : T[l];
    previousPower_ = power;
    previousSpeed_ = speed;
}

} // namespace rosin::physics
