// Steady-sliding calibration ([Notes §2.4], §3.2) and steady sliding through the thermal laws, which must
// reproduce the measured curves they were calibrated on ([Galluzzo2017] eq. 1, [Woodhouse-thermal] eq. 11).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include "core/physics/thermal/HeatBalance.h"
#include "core/physics/thermal/ModifiedThermalLaw.h"
#include "core/physics/thermal/PlasticThermalLaw.h"
#include "core/physics/thermal/ThermalCalibration.h"
#include "core/physics/thermal/ThermalTestSupport.h"
#include "core/physics/thermal/ViscousThermalLaw.h"

using namespace rosin::physics;
using namespace rosin::test::thermal;

namespace ROSIN_FILE_LOCAL
{
constexpr double pi = std::numbers::pi;
double muClassical(double v)
{
    return 0.4 * std::exp(-v / 0.01) + 0.45 * std::exp(-v / 0.1) + 0.35;
} // [Galluzzo2017] eq. 1
double hBow(double v)
{
    return 0.5 * std::pow(v + 0.27, -0.4);
} // [Woodhouse-thermal] eq. 12
double hRod(double v)
{
    return 0.37 * std::pow(v + 0.35, -0.4);
} // [Woodhouse-thermal] eq. 13

/// Steady temperature on the calibration rig from the continuous model ([Notes] eq. 2.7 with §2.3a's moving
/// side, by quadrature of the Green's function), a second method beside the discrete scheme the table uses.
double steadyT(const ContactParameters& p, double mu, double v)
{
    const auto& g = p.calibration;
    return g.referenceForce * mu * v / HeatBalance::steadyConductance(g, p.materials, g.referenceForce, v);
}

/// The calibration rig used as the bowing contact, so a steady slide at 3 N must reproduce the curve.
ContactParameters calibrationAsRig()
{
    ContactParameters p = galluzzoContact();
    p.rig = p.calibration;
    return p;
}

/// Steady slide at about speed v through `law` for `seconds` at the law's rate: a stiff load line
/// (2Z = 1e4 kg/s, far steeper than any friction curve here) offset so that dv ~ v. Returns |f| / Fb at
/// the end and the final dv.
double slideThrough(FrictionLaw& law, double fs, double v, double Fb, double seconds, double* dvOut,
                    double (*mu)(double))
{
    law.reset();
    JunctionSolution s;
    const double twoZ = 1e4;
    const long n = std::lround(seconds * fs);
    for (long k = 0; k < n; ++k)
        s = law.solve({v + Fb * mu(v) / twoZ, twoZ, Fb});
    *dvOut = s.dv;
    return std::abs(s.frictionForce) / Fb;
}

TEST(ThermalCalibration, YieldStressTableInvertsAnalyticSteadyMap)
{
    const ContactParameters p = galluzzoContact();
    ThermalCalibration t;
    t.build(p, 44100.0, CalibrationQuantity::YieldStress);
    EXPECT_FALSE(t.truncated()); // T_ss(v) increases over 1e-7..10 m/s for the classical curve (§2.4)
    const double Acal = pi * 500e-6 * 500e-6, Fcal = 3.0;
    EXPECT_NEAR(t.lookup(0.0) * Acal / Fcal, 1.2, 1e-12);              // mu_s of [Galluzzo2017] eq. 1
    EXPECT_NEAR(t.lookup(1e4) * Acal / Fcal, muClassical(10.0), 1e-9); // held above the table's top
    for (double v : {1e-4, 1e-3, 1e-2, 3e-2, 0.1, 0.3, 1.0, 3.0})
    {
        const double mu = t.lookup(steadyT(p, muClassical(v), v)) * Acal / Fcal;
        EXPECT_NEAR(mu / muClassical(v), 1.0, 2e-3) << "v = " << v;
    }
    for (size_t i = 1; i < t.values().size(); ++i)
        ASSERT_LE(t.values()[i], t.values()[i - 1]); // tau_y non-increasing with T (0.35 plateau)
}

TEST(ThermalCalibration, ModifiedTablesCrossUnityAtTheModelsOwnT0)
{
    // [Woodhouse-thermal] eq. 8: K Y(T0) = 1 where h and mu_steady cross (v* = 0.01816 m/s bow, 0.08175 m/s
    // rod), at the model's own steady temperature there. (Its values against the published 26.2 K and 36.8 K
    // are predictions: HeatBalance.CrossingTemperaturesOfTheModifiedLawAsPredictions.)
    const ContactParameters p = galluzzoContact();
    ThermalCalibration bow, rod;
    bow.build(p, 44100.0, CalibrationQuantity::ModifiedBow);
    rod.build(p, 44100.0, CalibrationQuantity::ModifiedRod);
    const double T0bow = steadyT(p, muSteady(0.01816), 0.01816),
                 T0rod = steadyT(p, muSteady(0.08175), 0.08175);
    std::printf("[ KY       ] bow K Y(%.2f K) = %.4f, rod K Y(%.2f K) = %.4f; steady map peaks at %.2f K, "
                "v = %.3f m/s\n",
                T0bow, bow.lookup(T0bow), T0rod, rod.lookup(T0rod), bow.maxTemperature(), bow.maxSpeed());
    EXPECT_NEAR(bow.lookup(T0bow), 1.0, 0.01);
    EXPECT_NEAR(rod.lookup(T0rod), 1.0, 0.01);
    EXPECT_NEAR(bow.lookup(0.0), muSteady(0.0) / hBow(0.0), 1e-12);
    EXPECT_NEAR(rod.lookup(0.0), muSteady(0.0) / hRod(0.0), 1e-12);
    // Known discrepancy with [Woodhouse-thermal] ("T approximately proportional to mu_steady sqrt(|v|)",
    // rising): on the 10 um calibration layer the advected rosin (~ v) outgrows the conduction (~ sqrt v) and
    // the steady map peaks (measured: 22.7 K at 0.48 m/s), so the table is cut there. Without advection it
    // would rise, but the crossing temperatures' ratio would then move from 1.37 to 1.47 (published 1.40).
    // Band asserted.
    EXPECT_TRUE(bow.truncated());
    EXPECT_GT(bow.maxTemperature(), 18.0);
    EXPECT_LT(bow.maxTemperature(), 28.0);
    EXPECT_GT(bow.maxSpeed(), 0.3);
    EXPECT_LT(bow.maxSpeed(), 0.8);
    EXPECT_NEAR(bow.lookup(1e3), muSteady(bow.maxSpeed()) / hBow(bow.maxSpeed()), 1e-9);
}

TEST(ThermalCalibration, SteadySlidingThroughPlasticLawReproducesClassicalCurve)
{
    // 1 kHz keeps 1000 s of sliding cheap. (The heat update is stable at any step, but the one-sample lag
    // between temperature and force is a fixed-point iteration whose gain grows as the step grows: at
    // 100 Hz it settles on a spurious two-cycle near 0.1 m/s. At audio rates its gain is < 0.2.)
    const double fs = 1000.0;
    PlasticThermalLaw law(calibrationAsRig());
    law.prepare(fs);
    double worst = 0.0;
    for (double v : {0.001, 0.003, 0.01, 0.03, 0.1, 0.3, 1.0})
    {
        double dv = 0.0;
        const double mu = slideThrough(law, fs, v, 3.0, 1000.0, &dv, muClassical);
        const double err = mu / muClassical(std::abs(dv)) - 1.0;
        worst = std::max(worst, std::abs(err));
        std::printf(
            "[ plastic  ] v = %6.3f m/s: mu = %.4f, [Galluzzo2017] eq. 1 %.4f, error %+.3f %%, T = %.2f K\n",
            v, mu, muClassical(std::abs(dv)), 100.0 * err, law.contactTemperature());
        EXPECT_NEAR(err, 0.0, 0.02) << "v = " << v;
    }
    std::printf("[ plastic  ] worst steady-sliding error %.3f %%\n", 100.0 * worst);
}

TEST(ThermalCalibration, SteadySlidingThroughViscousLawReproducesClassicalCurve)
{
    const double fs = 1000.0;
    ViscousThermalLaw law(calibrationAsRig());
    law.prepare(fs);
    double worst = 0.0;
    for (double v : {0.001, 0.01, 0.1, 1.0})
    {
        double dv = 0.0;
        const double mu = slideThrough(law, fs, v, 3.0, 1000.0, &dv, muClassical);
        EXPECT_NEAR(mu / muClassical(std::abs(dv)), 1.0, 0.02) << "v = " << v;
        worst = std::max(worst, std::abs(mu / muClassical(std::abs(dv)) - 1.0));
    }
    std::printf("[ viscous  ] worst steady-sliding error vs [Galluzzo2017] eq. 1: %.3f %%\n", 100.0 * worst);
}

TEST(ThermalCalibration, SteadySlidingThroughModifiedLawReproducesSteadyFit)
{
    const double fs = 1000.0;
    for (auto variant : {ModifiedThermalLaw::Variant::Bow, ModifiedThermalLaw::Variant::Rod})
    {
        ModifiedThermalLaw law(calibrationAsRig(), variant);
        law.prepare(fs);
        ASSERT_GT(law.calibration().maxSpeed(), 0.2);
        double worst = 0.0;
        // Up to 0.15 m/s: nearer the steady map's peak (0.48 m/s) T_ss(v) flattens, and the slow
        // stationary-side drift left after 300 s (< 0.1 % in T) moves v(T), hence mu, by percent
        // (measured: 4.0 % at 0.2 m/s).
        for (double v : {0.001, 0.01, 0.03, 0.1, 0.15})
        {
            double dv = 0.0; // 300 s: the remaining slow stationary-side drift moves mu by < 0.5 %
            const double mu = slideThrough(law, fs, v, 3.0, 300.0, &dv, muSteady);
            const double err = mu / muSteady(std::abs(dv)) - 1.0;
            worst = std::max(worst, std::abs(err));
            EXPECT_NEAR(err, 0.0, 0.02) << law.name() << " v = " << v;
        }
        std::printf("[ modified ] %s: worst steady-sliding error vs [Woodhouse-thermal] eq. 11: %.3f %%\n",
                    law.name(), 100.0 * worst);
    }
}

} // namespace ROSIN_FILE_LOCAL
