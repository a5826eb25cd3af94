// The moving side's washout (Washout.h, [Notes §2.3a]): the polynomial forms against their closed forms,
// and the heat balance's fast-sliding limit against the exact high-Peclet disc computed here by a second
// method (quadrature over the chords of the disc, no Beta function).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "core/physics/thermal/ContactParameters.h"
#include "core/physics/thermal/HeatBalance.h"
#include "core/physics/thermal/Washout.h"

using namespace rosin::physics;

namespace ROSIN_FILE_LOCAL
{
constexpr double pi = std::numbers::pi;

/// Heat per second (W) a disc of radius a at temperature T puts into a half-space of effusivity e sliding
/// under it at v, when every chord of material meets a 1-D half-space held at T for its transit time c/v:
/// int 2 e T sqrt(c(y) v / pi) dy by the midpoint rule in the angle (y = a sin phi).
double chordHeat(double a, double e, double T, double v)
{
    const int n = 200000;
    double sum = 0.0;
    for (int i = 0; i < n; ++i)
    {
        const double phi = -0.5 * pi + (i + 0.5) * pi / n;
        const double c = 2.0 * a * std::cos(phi);
        sum += 2.0 * e * T * std::sqrt(c * v / pi) * a * std::cos(phi) * (pi / n);
    }
    return sum;
}

TEST(Washout, SeriesMatchTheirClosedForms)
{
    for (double x : {0.0, 1e-6, 1e-3, 0.05, 0.1, 0.2, 0.2499, 0.25, 0.5, 2.0, 30.0})
    {
        EXPECT_NEAR(washout::decay(x), std::exp(-x), 2e-8) << "x = " << x;
        const double exact = x == 0.0 ? 1.0 : 0.5 * std::sqrt(pi / x) * std::erf(std::sqrt(x));
        EXPECT_NEAR(washout::firstStepFactor(x), exact, 3e-8) << "x = " << x;
    }
}

TEST(Washout, FastSlidingLimitIsTheExactHighPecletDisc)
{
    // A stationary side of near-zero conductivity and no advection leave the moving side alone; at 3 m/s over
    // a 2 mm disc the washout time ell/v (0.85 ms) is far below a^2/kappa (~20 s for rosin), where the 1-D
    // kernel holds, so the model's conductance must be the chord integral's within a few per cent.
    ContactMaterials m;
    m.moving = materials::rosin;
    m.stationary = ThermalMaterial{1e-9, 1e3};
    m.advectionWidthRatio = 0.0;
    const ContactGeometry g{2e-3, 1.0, 1e-6, ContactScaling::Coulomb};
    for (double v : {1.0, 3.0})
    {
        const double model = HeatBalance::steadyConductance(g, m, 1.0, v);
        const double exact = chordHeat(g.radius, m.moving.effusivity(), 1.0, v);
        EXPECT_NEAR(model / exact, 1.0, 0.03) << "v = " << v;
        // [Notes §2.3]'s quasi-steady pi a^2 e sqrt(3 v / (8 a)) lies 31 % below it.
        const double quasiSteady =
            pi * g.radius * g.radius * m.moving.effusivity() * std::sqrt(3.0 * v / (8.0 * g.radius));
        EXPECT_NEAR(quasiSteady / exact, 0.69, 0.01);
    }
}

TEST(Washout, TimeSteppedSlideConvergesToTheAnalyticConductance)
{
    // The SOE scheme with per-step washout against the quadrature of G_avg e^{-v t / ell}: two methods of one
    // continuous model, at a slow and a fast slide on the Galluzzo contact.
    const ContactParameters c = galluzzoContact();
    HeatBalance heat;
    heat.prepare(c, 48000.0);
    for (double v : {0.01, 0.3})
    {
        const double discrete = heat.steadyConductance(v, 1.0);
        const double analytic = HeatBalance::steadyConductance(c.rig, c.materials, 1.0, v);
        EXPECT_NEAR(discrete / analytic, 1.0, 0.01) << "v = " << v;
    }
}

TEST(Washout, AStuckContactConductsIntoBothSolidsAlike)
{
    // v = 0: nothing washes out, both solids are the same half-space problem, so the steady conductance is
    // the two disc conductances (3 pi^2 / 8) K a side by side.
    ContactMaterials m;
    m.stationary = materials::rosin;
    m.moving = materials::glass;
    const ContactGeometry g{250e-6, 1.0, 1e-6, ContactScaling::Coulomb};
    const double expected =
        3.0 * pi * pi / 8.0 * (m.stationary.conductivity + m.moving.conductivity) * g.radius;
    EXPECT_NEAR(HeatBalance::steadyConductance(g, m, 1.0, 0.0) / expected, 1.0, 1e-9);
}

} // namespace ROSIN_FILE_LOCAL
