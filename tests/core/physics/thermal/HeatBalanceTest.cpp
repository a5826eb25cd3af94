// Contact heat balance ([Notes] eq. 2.4-2.9, §2.3a): crossing temperatures of [Woodhouse-thermal], the
// Helmholtz-motion demonstration of [Notes §2.6b], force scaling, and stability of the implicit update.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>
#include <vector>

#include "core/physics/thermal/ContactParameters.h"
#include "core/physics/thermal/HeatBalance.h"
#include "core/physics/thermal/ThermalTestSupport.h"

using namespace rosin::physics;
using namespace rosin::test::thermal;

namespace ROSIN_FILE_LOCAL
{
constexpr double pi = std::numbers::pi;

/// Crossing speed v* of [Woodhouse-thermal] eq. 11 with h = c (v + x0)^-0.4, solved here by bisection on the
/// two formulas.
double crossingSpeed(double c, double x0)
{
    auto diff = [&](double v) { return c * std::pow(v + x0, -0.4) - muSteady(v); };
    double lo = 1e-6, hi = 10.0; // h < mu_steady at low v, h > mu_steady at high v
    for (int i = 0; i < 200; ++i)
    {
        const double mid = 0.5 * (lo + hi);
        (diff(mid) < 0.0 ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
}

struct Crossing
{
    const char* name;
    double c, x0, publishedT0;
};
const Crossing kCrossings[] = {{"bow", 0.5, 0.27, 26.2},
                               {"rod", 0.37, 0.35, 36.8}}; // [Woodhouse-thermal] eqs. 12-13

// A prediction, not a fit: the rosin and acrylic constants are handbook values (ThermalMaterial.h). Measured
// (48 kHz-independent, 5000 s of sliding at 1 kHz): T0 = 14.8 K (bow) and 20.4 K (rod) against the published
// 26.2 K and 36.8 K, i.e. 0.57x and 0.55x; their ratio 1.374 against the published 1.405 (-2 %). The ratio
// depends on how the conductance grows with speed (advection against conduction), the level on the solids'
// effusivities, which [Galluzzo2017] took from a table the project could not obtain ([Notes §10] Q2).
TEST(HeatBalance, CrossingTemperaturesOfTheModifiedLawAsPredictions)
{
    const ContactParameters contact = galluzzoContact();
    const ContactGeometry& cal = contact.calibration; // 500 um at 3 N, 10 um layer
    const double F = cal.referenceForce;
    const double fs = 1000.0; // the implicit scheme is stable at any step: 1 kHz makes hours of sliding cheap
    HeatBalance heat;
    heat.prepare(cal, contact.materials, fs);
    double predicted[2];
    for (int i = 0; i < 2; ++i)
    {
        const Crossing& x = kCrossings[i];
        const double v = crossingSpeed(x.c, x.x0);
        const double P = F * muSteady(v) * v;
        heat.reset();
        const long steps = static_cast<long>(5000.0 * fs); // 5000 s of steady sliding
        double T1000 = 0.0;
        for (long n = 0; n < steps; ++n)
        {
            heat.commit(P, v, F);
            if (n == steps - static_cast<long>(1000.0 * fs))
                T1000 = heat.temperature();
        }
        const double Tstep = heat.temperature();
        const double Tformula = P / HeatBalance::steadyConductance(cal, contact.materials, F, v); // eq. 2.7
        std::printf("[ T0       ] %s: v* = %.5f m/s, P = %.4f W, time-stepped T = %.2f K (drift over last "
                    "1000 s %.3f K), continuous model T = %.2f K, published %.1f K\n",
                    x.name, v, P, Tstep, Tstep - T1000, Tformula, x.publishedT0);
        EXPECT_NEAR(Tstep / Tformula, 1.0, 0.01); // converged to the continuous model's steady state
        predicted[i] = Tstep;
    }
    const double publishedRatio = kCrossings[1].publishedT0 / kCrossings[0].publishedT0;
    EXPECT_NEAR(predicted[1] / predicted[0], publishedRatio,
                0.05 * publishedRatio); // the prediction that holds
    // Known discrepancy, its measured band asserted so that a change either way is noticed: 0.55-0.57 of the
    // published levels.
    for (int i = 0; i < 2; ++i)
    {
        EXPECT_GT(predicted[i] / kCrossings[i].publishedT0, 0.45) << kCrossings[i].name;
        EXPECT_LT(predicted[i] / kCrossings[i].publishedT0, 0.67) << kCrossings[i].name;
    }
    EXPECT_NEAR(crossingSpeed(0.5, 0.27), 0.01816, 1e-5); // [Notes §3.2]
    EXPECT_NEAR(crossingSpeed(0.37, 0.35), 0.08175, 1e-5);
}

TEST(HeatBalance, HelmholtzMotionTemperaturesAgreeAcrossSampleRates)
{
    const ContactParameters contact = galluzzoContact();
    double means[2], swings[2];
    const double rates[2] = {44100.0, 192000.0};
    for (int r = 0; r < 2; ++r)
    {
        const HelmholtzTemperatures T = helmholtzSliding(contact, rates[r]);
        EXPECT_TRUE(T.finite);
        means[r] = T.mean;
        swings[r] = T.swing();
        std::printf(
            "[ Helmholtz] fs = %6.0f Hz: mean %.2f K over the last 10 periods, last period min %.2f max "
            "%.2f swing %.2f K\n",
            rates[r], means[r], T.low, T.high, swings[r]);
    }
    EXPECT_NEAR(means[0], means[1], 1.0);
    // A prediction against a secondary source: the account of the original model in [Euphonics] 9.6, a mean
    // rise of ~50 K with ~30 K swing per cycle ([Notes §2.6b]). Measured with both solids conducting:
    // mean 18.6-18.9 K, swing 36 K. The swing agrees; the mean is ~2.7x lower, since the moving side now also
    // takes heat while stuck and its patch is refreshed by every flyback (the old one-sided balance gave
    // 56-65 K). The band asserted is the measured one with room for the uncertain constants; it still catches
    // gross errors (a steel stationary side gives ~1 K, a wrong area scale moves the rise by the area ratio).
    for (int r = 0; r < 2; ++r)
    {
        EXPECT_GT(means[r], 12.0);
        EXPECT_LT(means[r], 30.0);
        EXPECT_GT(swings[r], 20.0);
        EXPECT_LT(swings[r], 50.0);
    }
}

TEST(HeatBalance, ShortTimeResponseIsOneDimensionalConductionIntoBothSolids)
{
    // Constant power P into a stuck contact, thin layer, wide disc: for delta^2/kappa << t << a^2/kappa both
    // solids are 1-D half-spaces in parallel, so the surface follows T = 2 (P/A) sqrt(t / pi) / (e_s + e_m)
    // ([Smith2000]: conduction into the two neighbouring solids; [Notes §2.3a]: the moving side conducts
    // while stuck). Rosin on glass, so that the two effusivities differ by 3x.
    ContactMaterials m;
    m.stationary = materials::rosin;
    m.moving = materials::glass;
    const ContactGeometry g{1e-3, 1.0, 0.1e-6, ContactScaling::Coulomb};
    const double fs = 192000.0, P = 0.1, t = 1e-3;
    HeatBalance heat;
    heat.prepare(g, m, fs);
    const long n = std::lround(t * fs);
    for (long k = 0; k < n; ++k)
        heat.commit(P, 0.0, 1.0);
    const double e = m.stationary.effusivity() + m.moving.effusivity();
    const double expected = 2.0 * P / (pi * g.radius * g.radius) * std::sqrt(t / pi) / e;
    EXPECT_NEAR(heat.temperature() / expected, 1.0, 0.03);
    // The heat splits in the ratio of the effusivities.
    EXPECT_NEAR(heat.movingFlux() / heat.stationaryFlux(), m.moving.effusivity() / m.stationary.effusivity(),
                0.03 * m.moving.effusivity() / m.stationary.effusivity());
}

TEST(HeatBalance, ContactAreaRescalingAtRest)
{
    // With Coulomb scaling C and the stationary kernel scale with A, so a stuck contact heated by the same
    // power reaches a temperature inversely proportional to the area ([Notes §2.5], last paragraph).
    const ContactParameters contact = galluzzoContact();
    HeatBalance h1, h2;
    h1.prepare(contact, 48000.0);
    h2.prepare(contact, 48000.0);
    for (int k = 0; k < 4800; ++k)
    {
        h1.commit(0.05, 0.0, 1.0);
        h2.commit(0.05, 0.0, 2.5);
    }
    EXPECT_NEAR(h2.temperature() / h1.temperature(), 1.0 / 2.5, 1e-9);
}

TEST(HeatBalance, SteadyStateMatchesOwnSteadyConductanceAtAnyForce)
{
    const ContactParameters contact = galluzzoContact();
    HeatBalance heat;
    heat.prepare(contact, 100.0);
    for (double F : {0.3, 1.0, 2.0})
    {
        heat.reset();
        const double v = 0.05, P = 0.4 * F * v;
        for (int k = 0; k < 1000000; ++k) // 1e4 s
            heat.commit(P, v, F);
        EXPECT_NEAR(heat.temperature() * heat.steadyConductance(v, F) / P, 1.0, 5e-3) << "F = " << F;
    }
}

TEST(HeatBalance, StableAndPositiveAtAnyTimeStep)
{
    const ContactParameters contact = galluzzoContact();
    std::mt19937 rng(1234);
    std::uniform_real_distribution<double> U(0.0, 1.0);
    for (double fs : {10.0, 1000.0, 44100.0, 1e6})
    {
        HeatBalance heat;
        heat.prepare(contact, fs);
        double previous = 0.0;
        bool ok = true, monotone = true;
        for (int k = 0; k < 2000; ++k) // step response: constant heating must never overshoot or oscillate
        {
            heat.commit(0.2, 0.5, 1.0);
            monotone = monotone && heat.temperature() >= previous - 1e-12;
            previous = heat.temperature();
        }
        for (int k = 0; k < 20000; ++k)
        {
            const bool slide = U(rng) < 0.3;
            const double v = slide ? 2.0 * U(rng) : 0.0, F = 5.0 * U(rng);
            heat.commit(slide ? 0.8 * F * v : 0.0, v, F);
            ok = ok && std::isfinite(heat.temperature()) && heat.temperature() >= -1e-9 &&
                 heat.temperature() < 1e4;
        }
        EXPECT_TRUE(monotone) << "fs = " << fs;
        EXPECT_TRUE(ok) << "fs = " << fs;
        heat.commit(std::nan(""), std::nan(""), std::nan("")); // garbage in: stays finite
        EXPECT_TRUE(std::isfinite(heat.temperature()));
    }
}

TEST(HeatBalance, AnUnheatedContactStaysAmbientAndAHeatedOneKeepsCooling)
{
    // An unbowed string (no power) skips its heat steps, which would only multiply zeros; once heat has
    // arrived every step is computed again, so the contact cools instead of freezing at its last temperature.
    const ContactParameters contact = galluzzoContact();
    HeatBalance heat;
    heat.prepare(contact, 48000.0);
    for (int k = 0; k < 480; ++k)
        heat.commit(0.0, 0.3, 0.0);
    EXPECT_EQ(heat.temperature(), 0.0);
    EXPECT_EQ(heat.predict(0.0, 0.3, 0.0), 0.0);
    EXPECT_GT(heat.predict(0.2, 0.5, 1.0), 0.0); // a prediction with power is computed, not skipped
    for (int k = 0; k < 48; ++k)
        heat.commit(0.2, 0.5, 1.0); // 1 ms of sliding heat
    const double heated = heat.temperature();
    double previous = heated;
    bool cooling = true;
    for (int k = 0; k < 4800; ++k)
    {
        heat.commit(0.0, 0.3, 0.0);
        cooling = cooling && heat.temperature() < previous && heat.temperature() > 0.0;
        previous = heat.temperature();
    }
    EXPECT_GT(heated, 1.0);
    EXPECT_TRUE(cooling);
    EXPECT_LT(previous, 0.5 * heated);
    heat.reset();
    heat.commit(0.0, 0.3, 0.0);
    EXPECT_EQ(heat.temperature(), 0.0);
}

} // namespace ROSIN_FILE_LOCAL
