// The finite-difference heat balance against analytic solutions (not against Rosin's heat model):
//  - a heated, stuck contact tends to the mean temperature of a uniformly heated disc on each solid,
//    T = P / ((3 pi^2 / 8) a (K_s + K_m)) ([Notes] eq. 2.7's stationary term: the integral of the disc
//    Green's function, 8 / (3 pi^2 K a));
//  - in steady sliding the discrete steady state equals the continuous model's: advection rho c a delta v,
//    the disc conduction of both solids, and the moving side's washout profile pi a^2 e sqrt(v/a);
//  - the yield-stress calibration gives the static coefficient 1.2 (a_rig / a_cal)^2 ([Notes §2.1]).
#include <gtest/gtest.h>

#include <cmath>

#include "lab/discovery/independent/ContactHeat.h"
#include "lab/discovery/independent/IndependentFixtures.h"
#include "lab/discovery/independent/YieldStressTable.h"

namespace rosin::discovery
{
namespace ROSIN_FILE_LOCAL
{

HeatMaterials galluzzoMaterials()
{
    const auto m = physics::galluzzoContact().materials;
    return {m.layer, m.stationary, m.moving};
}

double discConductance(double a, const HeatMaterials& m)
{
    return 3.0 * std::numbers::pi * std::numbers::pi / 8.0 * a *
           (m.stationary.conductivity + m.moving.conductivity);
}

TEST(ContactHeat, HeatedStuckContactApproachesTheDiscMeanTemperature)
{
    const double a = 250e-6, P = 1e-3, dt = 0.01;
    const HeatMaterials m = galluzzoMaterials();
    ContactHeat heat(a, 1e-6, m, dt);
    for (int k = 0; k < 300000; ++k) // 3000 s >> a^2 / kappa
    {
        heat.predict(0.0);
        heat.finish(P);
    }
    const double analytic = P / discConductance(a, m);
    // The approach is ~ 1 - l / sqrt(pi kappa t) (l = 8a/3pi): 2 % short at 3000 s.
    std::printf("stuck disc: T = %.5f K after 3000 s, analytic steady %.5f K, discrete steady %.5f K\n",
                heat.temperature(), analytic, P * heat.steadyRise(0.0));
    EXPECT_NEAR(heat.temperature() / analytic, 1.0, 0.04);
    EXPECT_NEAR(P * heat.steadyRise(0.0) / analytic, 1.0, 0.01);
}

TEST(ContactHeat, SteadySlidingTemperatureMatchesTheContinuousModel)
{
    const HeatMaterials m = galluzzoMaterials();
    for (double a : {250e-6, 500e-6})
    {
        const ContactHeat heat(a, a > 300e-6 ? 10e-6 : 1e-6, m, 1.0 / test::kRate);
        for (double v : {1e-4, 1e-3, 1e-2, 0.1, 1.0})
        {
            const double e = m.moving.effusivity(), pi = std::numbers::pi;
            const double G = m.layer.volumetricHeatCapacity * a * (a > 300e-6 ? 10e-6 : 1e-6) * v +
                             discConductance(a, m) + pi * a * a * e * std::sqrt(v / a);
            const double ratio = heat.steadyRise(v) * G;
            std::printf("steady sliding a = %.0f um, v = %g m/s: T_ss x G_analytic = %.4f\n", a * 1e6, v,
                        ratio);
            EXPECT_NEAR(ratio, 1.0, 0.03);
        }
    }
}

TEST(ContactHeat, CalibrationGivesTheSeedsStaticCoefficientOnTheGalluzzoRig)
{
    const auto contact = physics::galluzzoContact();
    const YieldStressTable table({500e-6, 3.0, 10e-6}, galluzzoMaterials(), 1.0 / test::kRate);
    for (double force : {0.5, 1.0, 2.5})
    {
        const double a = contact.rig.radius * std::sqrt(force / contact.rig.referenceForce);
        const double mu = std::numbers::pi * a * a * table.at(0.0) / force;
        const double aCal = 500e-6 * std::sqrt(force / 3.0);
        EXPECT_NEAR(mu, 1.2 * (a / aCal) * (a / aCal), 1e-9);
        EXPECT_NEAR(mu, 0.90, 0.005); // [Notes §2.1]: 1.2 x (0.433 / 0.5)^2
    }
    // The table is a monotone map of temperature up to the fast end of the classical curve.
    EXPECT_GT(table.temperatures().back(), 50.0);
    EXPECT_NEAR(table.stresses().back() / table.stresses().front(), 0.35 / 1.2, 0.02);
}

} // namespace ROSIN_FILE_LOCAL
} // namespace rosin::discovery
