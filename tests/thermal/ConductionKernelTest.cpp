// Disc-average half-space Green's function (reference eq. 2.5) and its SOE fit (eq. 2.8).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include "physics/thermal/ConductionKernel.h"
#include "physics/thermal/ContactParameters.h"
#include "physics/thermal/ThermalMaterial.h"

using namespace rosin::physics;

namespace
{
const ThermalMaterial kMaterial = materials::rosin;
constexpr double pi = std::numbers::pi;
/// Classical mean temperature of a uniformly heated disc on a half-space, per watt: 8 / (3 pi^2 K a).
double discResistance(double a)
{
    return 8.0 / (3.0 * pi * pi * kMaterial.conductivity * a);
}
} // namespace

TEST(ConductionKernel, GreenFunctionIntegratesToDiscMeanResistance)
{
    for (double a : {200e-6, 250e-6, 500e-6})
    {
        // The integrand decays like t^-3/2; the tail beyond 1e9 s is ~1e-5 of the total.
        const double I = ConductionKernel::integrateGreen(0.0, 1e9, a, kMaterial.conductivity,
                                                          kMaterial.volumetricHeatCapacity, 400000);
        EXPECT_NEAR(I / discResistance(a), 1.0, 1e-3) << "a = " << a;
    }
}

TEST(ConductionKernel, GreenFunctionShortTimeLimitIsOneDimensional)
{
    // t << a^2/kappa: G -> 1 / (A e sqrt(pi t)) (reference §2.3.1).
    const double a = 500e-6, K = kMaterial.conductivity, rc = kMaterial.volumetricHeatCapacity;
    const double t = 1e-6 * a * a / (K / rc);
    const double oneD = 1.0 / (pi * a * a * std::sqrt(K * rc) * std::sqrt(pi * t));
    EXPECT_NEAR(ConductionKernel::green(t, a, K, rc) / oneD, 1.0, 2e-3);
}

TEST(ConductionKernel, SumOfExponentialsMatchesGreenFunction)
{
    for (double a : {250e-6, 500e-6})
        for (double fs : {44100.0, 48000.0, 192000.0})
        {
            ConductionKernel k;
            k.fit(a, kMaterial.conductivity, kMaterial.volumetricHeatCapacity, 1.0 / fs);
            const double err = k.maxRelativeError(1.0 / fs, 100.0);
            const double integralRatio = k.integral() / discResistance(a);
            const double discreteRatio = k.discreteSteadyResistance() / discResistance(a);
            std::printf(
                "[ SOE      ] a = %3.0f um, fs = %6.0f Hz: %d terms (%d zero), max rel err [dt,100 s] = "
                "%.2e, sum c tau / (8/(3 pi^2 K a)) = %.5f, discrete steady resistance ratio = %.6f\n",
                a * 1e6, fs, k.size(), k.zeroTerms(), err, integralRatio, discreteRatio);
            EXPECT_LT(err, 1e-3);
            EXPECT_NEAR(integralRatio, 1.0, 0.01);
            EXPECT_NEAR(discreteRatio, 1.0, 1e-3);
            EXPECT_GE(k.size(), 30);
            EXPECT_LE(k.size(), 48);
            for (double c : k.coefficients())
                EXPECT_GE(c, 0.0); // non-negative fit: a positive, decaying kernel
        }
}

TEST(ConductionKernel, FirstStepWeightMatchesOneDimensionalIntegral)
{
    // int_0^dt G ~ 2 sqrt(dt) / (A e sqrt(pi)) for dt << a^2/kappa (reference §2.5).
    const double a = 500e-6, K = kMaterial.conductivity, rc = kMaterial.volumetricHeatCapacity;
    for (double fs : {44100.0, 192000.0})
    {
        ConductionKernel k;
        k.fit(a, K, rc, 1.0 / fs);
        const double oneD = 2.0 * std::sqrt(1.0 / fs) / (pi * a * a * std::sqrt(K * rc) * std::sqrt(pi));
        EXPECT_NEAR(k.firstStepWeight() / oneD, 1.0, 0.01);
        EXPECT_LT(k.firstStepWeight(), oneD); // lateral spreading only lowers the average temperature
    }
}
