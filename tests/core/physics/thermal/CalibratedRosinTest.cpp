// What the calibrated rosin (RosinMaterial.h: rho c fixed once, by [Smith2000]'s 44 Hz) predicts for the
// heat-balance statements of the other two texts, side by side with the handbook rosin. Predictions, not
// fits: nothing here was tuned. Where a statement is met, its number is asserted with a stated tolerance;
// where it is not, the measured band, so that a change either way is noticed.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/physics/thermal/ContactParameters.h"
#include "core/physics/thermal/HeatBalance.h"
#include "core/physics/thermal/RosinMaterial.h"
#include "core/physics/thermal/ThermalTestSupport.h"

using namespace rosin::physics;
using namespace rosin::test::thermal;

namespace ROSIN_FILE_LOCAL
{
ContactParameters galluzzoWith(RosinMaterial which)
{
    ContactParameters c = galluzzoContact();
    c.materials = withRosin(c.materials, rosinMaterial(which));
    return c;
}

/// Steady-sliding temperature on the calibration contact ([Notes] eq. 2.7), as the crossing-temperature test
/// of HeatBalanceTest.cpp finds the time-stepped balance converges to within 1 %.
double steadyTemperature(const ContactParameters& c, double v)
{
    const ContactGeometry& cal = c.calibration;
    const double F = cal.referenceForce;
    return F * muSteady(v) * v / HeatBalance::steadyConductance(cal, c.materials, F, v);
}

// [Woodhouse-thermal] eqs. 12-13: the crossing speeds of its two fits (HeatBalanceTest.cpp solves them).
constexpr double kBowCrossingSpeed = 0.01816, kRodCrossingSpeed = 0.08175;
constexpr double kBowT0 = 26.2, kRodT0 = 36.8;

// Seed 002's crossing temperatures, 26.2 K (bow) and 36.8 K (rod). Handbook rosin: 14.8 and 20.4 K (ratio
// 1.374 against 1.405). Calibrated rosin: more heat capacity carries more heat away with the advected layer,
// so both fall, the rod's more: 13.3 and 16.4 K (ratio 1.227, -13 %). Known discrepancy: the calibrated rosin
// predicts both the level and the ratio worse.
TEST(CalibratedRosin, CrossingTemperaturesOfTheModifiedLaw)
{
    const ContactParameters hb = galluzzoWith(RosinMaterial::Handbook);
    const ContactParameters cal = galluzzoWith(RosinMaterial::Calibrated);
    const double bowH = steadyTemperature(hb, kBowCrossingSpeed),
                 rodH = steadyTemperature(hb, kRodCrossingSpeed);
    const double bowC = steadyTemperature(cal, kBowCrossingSpeed),
                 rodC = steadyTemperature(cal, kRodCrossingSpeed);
    std::printf("[ T0       ] handbook %.2f / %.2f K (ratio %.3f); calibrated %.2f / %.2f K (ratio %.3f); "
                "published %.1f / %.1f K (%.3f)\n",
                bowH, rodH, rodH / bowH, bowC, rodC, rodC / bowC, kBowT0, kRodT0, kRodT0 / kBowT0);
    EXPECT_LT(bowC, bowH); // the direction: more rho c, a cooler contact
    EXPECT_LT(rodC, rodH);
    EXPECT_NEAR(bowC, 13.3, 1.0); // measured band
    EXPECT_NEAR(rodC, 16.4, 1.0);
    EXPECT_GT(std::abs(rodC / bowC - kRodT0 / kBowT0),
              std::abs(rodH / bowH - kRodT0 / kBowT0)); // ratio worse
}

/// Where the steady-sliding temperature on the calibration contact peaks, over 1 mm/s..3 m/s.
struct Peak
{
    double kelvin = 0.0, speed = 0.0;
};
Peak steadyPeak(const ContactParameters& c)
{
    Peak p;
    for (double v = 1e-3; v < 3.0; v *= 1.02)
        if (const double T = steadyTemperature(c, v); T > p.kelvin)
            p = {T, v};
    return p;
}

// Seed 002: the steady temperature rises with speed (T ~ mu_steady sqrt v). Handbook rosin: it rises to
// 22.7 K at 0.48 m/s, then falls (the advected 10 um layer). Calibrated: the advection, ~ rho c, wins sooner,
// the peak is at 0.11 m/s and 16.6 K. Known discrepancy, worse with the calibrated rosin; band asserted.
TEST(CalibratedRosin, SteadyTemperatureAgainstSpeed)
{
    const Peak hb = steadyPeak(galluzzoWith(RosinMaterial::Handbook));
    const Peak cal = steadyPeak(galluzzoWith(RosinMaterial::Calibrated));
    std::printf("[ steady   ] peak: handbook %.1f K at %.3f m/s, calibrated %.1f K at %.3f m/s\n", hb.kelvin,
                hb.speed, cal.kelvin, cal.speed);
    EXPECT_LT(cal.speed, hb.speed);
    EXPECT_GT(cal.speed, 0.07);
    EXPECT_LT(cal.speed, 0.17);
    EXPECT_NEAR(cal.kelvin, 16.6, 1.5);
}

// [Euphonics] 9.6 via [Notes §2.6b]: the original model's contact in Helmholtz motion at ~50 K mean, ~30 K
// swing. Handbook: 18.7 K mean, 36.3 K swing. Calibrated: 18.2 K mean, 24.8 K swing: the larger heat capacity
// of the layer damps the swing (now 17 % under the source's rather than 21 % over), the mean stays ~2.7x low.
// Bands measured.
TEST(CalibratedRosin, HelmholtzMotionTemperatures)
{
    const HelmholtzTemperatures hb = helmholtzSliding(galluzzoWith(RosinMaterial::Handbook), 48000.0);
    const HelmholtzTemperatures cal = helmholtzSliding(galluzzoWith(RosinMaterial::Calibrated), 48000.0);
    std::printf("[ Helmholtz] handbook mean %.1f K swing %.1f K; calibrated mean %.1f K swing %.1f K\n",
                hb.mean, hb.swing(), cal.mean, cal.swing());
    EXPECT_LT(cal.mean, hb.mean);
    EXPECT_LT(cal.swing(), hb.swing());
    EXPECT_NEAR(cal.mean, 18.2, 3.0);
    EXPECT_NEAR(cal.swing(), 24.8, 4.0);
}

} // namespace ROSIN_FILE_LOCAL
