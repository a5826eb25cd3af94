// Law-level checks of the thermal friction laws and the factory: static limits at ambient temperature,
// the viscous law's linear solve, energy dissipation for every law.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <numbers>
#include <random>
#include <stdexcept>

#include "core/physics/laws/FrictionLawFactory.h"
#include "core/physics/thermal/HeatBalance.h"
#include "core/physics/thermal/ModifiedThermalLaw.h"
#include "core/physics/thermal/PlasticThermalLaw.h"
#include "core/physics/thermal/ViscousThermalLaw.h"

using namespace rosin::physics;

namespace ROSIN_FILE_LOCAL
{
constexpr double pi = std::numbers::pi;
double muClassical(double v)
{
    return 0.4 * std::exp(-v / 0.01) + 0.45 * std::exp(-v / 0.1) + 0.35;
}

/// Does a fresh (ambient) law stick for this load? 2Z = 1 kg/s.
JunctionSolution firstSample(FrictionLaw& law, double stickForce, double Fb)
{
    law.reset();
    return law.solve({stickForce, 1.0, Fb}); // |2Z dvh| = stickForce
}

/// Checks that a fresh law holds |2Z dvh| just below mu_s Fb and slips just above.
void expectStaticLimit(FrictionLaw& law, double muS, double Fb)
{
    const JunctionSolution below = firstSample(law, muS * Fb * (1.0 - 1e-6), Fb);
    EXPECT_TRUE(below.sticking) << law.name() << " Fb = " << Fb;
    EXPECT_EQ(below.dv, 0.0);
    EXPECT_NEAR(below.frictionForce, -muS * Fb * (1.0 - 1e-6), 1e-12);
    const JunctionSolution above = firstSample(law, muS * Fb * (1.0 + 1e-3), Fb);
    EXPECT_FALSE(above.sticking) << law.name() << " Fb = " << Fb;
    EXPECT_GT(above.dv, 0.0);
    law.reset();
    EXPECT_NEAR(law.staticCoefficient(Fb), muS, 1e-9 * muS) << law.name();
}

TEST(PlasticThermalLaw, StaticCoefficientAtAmbientFollowsAreaPerNewton)
{
    // [Galluzzo2017] Fig. 14 / [Notes §2.1]: mu_s = 1.2 (A_rig/N_rig) / (A_cal/N_cal): 0.90 (Galluzzo), 0.576
    // (Schumacher).
    for (const ContactParameters& p : {galluzzoContact(), schumacherContact()})
    {
        PlasticThermalLaw law(p);
        law.prepare(48000.0);
        const double expected = 1.2 * (p.rig.radius * p.rig.radius / p.rig.referenceForce) /
                                (p.calibration.radius * p.calibration.radius / p.calibration.referenceForce);
        for (double Fb : {0.5, 1.0, 2.0})
            expectStaticLimit(law, expected, Fb);
    }
    EXPECT_NEAR(1.2 * (0.25 * 0.25 / 1.0) / (0.5 * 0.5 / 3.0), 0.90, 1e-12);
}

TEST(PlasticThermalLaw, HertzContactGivesForceDependentStaticCoefficient)
{
    ContactParameters p = galluzzoContact();
    p.rig.scaling = ContactScaling::Hertz;
    PlasticThermalLaw law(p);
    law.prepare(48000.0);
    for (double Fb : {0.5, 1.0, 3.0})
    {
        const double a = 250e-6 * std::cbrt(Fb); // Hertz: a = a_ref (N/N_ref)^(1/3)
        const double expected = 1.2 * (pi * a * a / Fb) / (pi * 500e-6 * 500e-6 / 3.0);
        expectStaticLimit(law, expected, Fb);
    }
}

TEST(PlasticThermalLaw, SlidesAtTheTemperatureLimitedForce)
{
    PlasticThermalLaw law(galluzzoContact());
    law.prepare(48000.0);
    const double twoZ = 0.84, Fb = 1.0, dvh = 2.0;
    for (int k = 0; k < 480; ++k) // 10 ms of hard sliding heats the contact
    {
        const JunctionSolution s = law.solve({dvh, twoZ, Fb});
        ASSERT_FALSE(s.sticking);
        // Exact characteristic solve: f = -limit, dv = dvh - limit / 2Z ([Notes] eq. 2.3).
        EXPECT_NEAR(s.dv, dvh + s.frictionForce / twoZ, 1e-12);
    }
    EXPECT_GT(law.contactTemperature(), 10.0);
    EXPECT_LT(law.staticCoefficient(Fb), 0.90); // softened rosin
}

TEST(ModifiedThermalLaw, StaticCoefficientAtAmbientIsSteadyFitAtZeroSpeed)
{
    // K Y(0) h(0) = mu_steady(0) = 0.2 * 0.011^-0.4 for either jump curve ([Woodhouse-thermal] eqs. 9, 11).
    const double muS = 0.2 * std::pow(0.011, -0.4);
    for (auto variant : {ModifiedThermalLaw::Variant::Bow, ModifiedThermalLaw::Variant::Rod})
    {
        ModifiedThermalLaw law(galluzzoContact(), variant);
        law.prepare(48000.0);
        for (double Fb : {0.5, 1.0, 2.0})
            expectStaticLimit(law, muS, Fb);
    }
    ContactParameters hertz = galluzzoContact();
    hertz.rig.scaling = ContactScaling::Hertz;
    ModifiedThermalLaw law(hertz, ModifiedThermalLaw::Variant::Bow);
    law.prepare(48000.0);
    expectStaticLimit(law, muS * std::pow(2.0 / 1.0, -1.0 / 3.0), 2.0); // (Fb/N_ref)^(-1/3)
}

TEST(ViscousThermalLaw, LinearSolveWithoutStickingBarrier)
{
    const ContactParameters p = galluzzoContact();
    ViscousThermalLaw law(p);
    law.prepare(48000.0);
    EXPECT_EQ(law.staticCoefficient(1.0), 0.0);
    // At ambient the viscosity is the calibration's value at the creep floor v_min ([Smith2000] eq. 3):
    // eta = F_cal mu(v_min) delta_cal / (A_cal v_min); c = A_rig eta / delta_rig.
    const double vmin = ThermalCalibration::kMinSpeed, Fb = 1.0, twoZ = 0.84;
    const double Acal = pi * 500e-6 * 500e-6, Arig = pi * 250e-6 * 250e-6;
    const double eta = 3.0 * muClassical(vmin) * 10e-6 / (Acal * vmin);
    const double c = Arig * eta / 1e-6;
    for (double dvh : {1e-3, -0.05, 0.5})
    {
        law.reset();
        const JunctionSolution s = law.solve({dvh, twoZ, Fb});
        EXPECT_NE(s.dv, 0.0); // never stuck exactly
        EXPECT_NEAR(s.dv / (twoZ * dvh / (twoZ + c)), 1.0, 1e-6);
        EXPECT_NEAR(s.frictionForce, twoZ * (s.dv - dvh), 1e-12 * std::abs(twoZ * dvh));
    }
    // Cold, the calibrated rosin is so viscous (c ~ 9e7 kg/s) that the string only creeps. Pre-warm the rosin
    // to the analytic steady temperature of a 0.1 m/s slide on the calibration rig ([Notes] eq. 2.7):
    // then eta = F_cal mu(0.1) delta_cal / (A_cal 0.1) and the same linear solve applies, with no barrier.
    const double v = 0.1;
    const double Gss = HeatBalance::steadyConductance(p.calibration, p.materials, 3.0, v);
    ContactParameters warm = p;
    warm.ambientOffset = 3.0 * muClassical(v) * v / Gss;
    ViscousThermalLaw hot(warm);
    hot.prepare(48000.0);
    const double cWarm = Arig / 1e-6 * 3.0 * muClassical(v) * 10e-6 / (Acal * v);
    const double dvh = 0.01; // small enough that this sample's own heating (~1e-4 K) does not change eta
    const JunctionSolution s = hot.solve({dvh, twoZ, Fb});
    EXPECT_NEAR(s.dv / (twoZ * dvh / (twoZ + cWarm)), 1.0, 0.01);
    EXPECT_FALSE(s.sticking);
}

TEST(FrictionLaws, FrictionAlwaysOpposesSliding)
{
    std::mt19937 rng(42);
    std::uniform_real_distribution<double> U(-1.0, 1.0);
    for (const std::string& name : frictionModelNames())
    {
        auto law = makeFrictionLaw(frictionModelFromName(name), galluzzoContact());
        law->prepare(44100.0);
        bool ok = true;
        double dvh = 0.0;
        for (int k = 0; k < 40000; ++k)
        {
            dvh = (k % 400 == 0) ? U(rng) : 0.9 * dvh + 0.2 * U(rng); // wandering, with jumps
            // Load slopes from a soft string (0.3 kg/s) to velocity control (1e4 kg/s), log-uniform.
            const double twoZ = 0.3 * std::pow(10.0, 2.25 * (1.0 + U(rng)));
            const JunctionInput in{dvh, twoZ, (k % 97 == 0) ? 0.0 : 3.0 * std::abs(U(rng))};
            const JunctionSolution s = law->solve(in);
            ok = ok && s.frictionForce * s.dv <= 0.0 && std::isfinite(s.dv) &&
                 std::isfinite(s.frictionForce) && std::isfinite(law->contactTemperature()) &&
                 law->contactTemperature() >= -1e-9;
            ok = ok && std::abs(s.frictionForce - in.loadSlope * (s.dv - in.dvHistory)) <=
                           1e-9 * (1.0 + std::abs(in.loadSlope * in.dvHistory)); // on the load line
        }
        EXPECT_TRUE(ok) << name;
    }
}

// A lifted bow (Fb = 0) has no contact area (a ~ sqrt(Fb)), so it holds nothing and rubs nothing at any
// temperature, and the open contact passes no heat between string and bow (HeatBalance::open): the string's
// spot cools by conduction into the string alone, so the temperature reported is its conduction memory
// decaying with no flux (checked against a copy of that memory taken at the lift), which falls monotonically
// (every term decays, none is fed).
template <class Law> void expectLiftedBowOnlyCools(Law& law)
{
    law.prepare(48000.0);
    for (int k = 0; k < 4800; ++k) // 0.1 s of sliding at 1 N, held at 0.2 m/s by a stiff load line
        law.solve({0.2, 100.0, 1.0});
    const double warm = law.contactTemperature();
    ASSERT_GT(warm, 1.0) << law.name();
    ConductingSide string = law.heat().stationarySide();
    bool noForce = true, noFlux = true, sameHeat = true, falling = true;
    double previous = law.contactTemperature();
    for (int k = 0; k < 9600; ++k)
    {
        const double dvh = 0.3 * std::sin(2.0 * pi * 147.0 * k / 48000.0); // the free string swinging by
        const JunctionSolution s = law.solve({dvh, 1.0, 0.0});
        string.advance(0.0, 1.0);
        noForce = noForce && s.frictionForce == 0.0 && s.dv == dvh;
        noFlux = noFlux && law.heat().stationaryFlux() == 0.0 && law.heat().movingFlux() == 0.0;
        sameHeat = sameHeat && law.contactTemperature() == string.historySum();
        falling = falling && (k == 0 || law.contactTemperature() <= previous);
        previous = law.contactTemperature();
    }
    std::printf("[ figures  ] %s: contact %.2f K when lifted, string spot %.2f K 0.2 s later\n", law.name(),
                warm, law.contactTemperature());
    EXPECT_TRUE(noForce) << law.name();
    EXPECT_TRUE(noFlux) << law.name();
    EXPECT_TRUE(sameHeat) << law.name();
    EXPECT_TRUE(falling) << law.name();
    EXPECT_LT(law.contactTemperature(), 0.5 * warm) << law.name();
    EXPECT_GE(law.contactTemperature(), 0.0) << law.name();
}

TEST(ThermalLaws, ALiftedBowExertsNoForceAndItsStringSpotCoolsAlone)
{
    PlasticThermalLaw plastic(galluzzoContact());
    expectLiftedBowOnlyCools(plastic);
    ViscousThermalLaw viscous(galluzzoContact());
    expectLiftedBowOnlyCools(viscous);
    for (const auto variant : {ModifiedThermalLaw::Variant::Bow, ModifiedThermalLaw::Variant::Rod})
    {
        ModifiedThermalLaw modified(galluzzoContact(), variant);
        expectLiftedBowOnlyCools(modified);
    }
}

TEST(FrictionLawFactory, NamesRoundTripAndErrorsListValidNames)
{
    const std::vector<std::string> expected{"classical", "reconstructed", "plastic",
                                            "viscous",   "modified-bow",  "modified-rod"};
    EXPECT_EQ(frictionModelNames(), expected);
    for (const auto& n : expected)
    {
        const FrictionModel m = frictionModelFromName(n);
        EXPECT_EQ(std::string(frictionModelName(m)), n);
        EXPECT_EQ(std::string(makeFrictionLaw(m, galluzzoContact())->name()), n);
    }
    try
    {
        frictionModelFromName("thermal");
        FAIL() << "expected std::invalid_argument";
    }
    catch (const std::invalid_argument& e)
    {
        const std::string what = e.what();
        for (const auto& n : expected)
            EXPECT_NE(what.find(n), std::string::npos) << what;
    }
}

} // namespace ROSIN_FILE_LOCAL
