// Seed 000's thermal laws on the same rig, same modal mass and same contact: predictions, not fits.
//  * plastic (eq. 4): "stick-slip motion at about 44 Hz", "contact temperature fluctuates in the range
//    20-40 K above ambient", hysteresis "in the correct sense" (anticlockwise, Fig. 2c);
//  * viscous (eq. 3): "forward slipping" (the oscillator faster than the rod), with the seed's thermal values
//    and with a higher specific heat alike.
// Tests named DISABLED_ are results this model does not reproduce; tests/CMakeLists.txt runs them as
// expected failures (rig.known-failure.*), so they turn red once the physics reproduces them.
#include <gtest/gtest.h>

#include <algorithm>

#include "RigTestSupport.h"

using namespace rosin::physics;
using namespace rosin::test::rig;

namespace
{
struct Range
{
    double low = 1e300, high = -1e300;
};
Range temperatureRange(const RigRun& run, double fromSeconds)
{
    Range r;
    for (std::size_t k = sampleAt(run, fromSeconds); k < run.samples.size(); ++k)
    {
        r.low = std::min(r.low, run.samples[k].contactTemperature);
        r.high = std::max(r.high, run.samples[k].contactTemperature);
    }
    return r;
}
double largestForwardSlip(const RigRun& run)
{
    double dv = 0.0;
    for (const RigSample& s : run.samples)
        dv = std::max(dv, s.slidingSpeed);
    return dv;
}
} // namespace

// Measured: 89.9 Hz once settled (0.5-1 s). The first cycle from rest runs at 44.4 Hz, the next at 52, 60, 68
// Hz: the stationary side stores heat, the contact no longer cools below ~50 K while stuck, mu_s falls and
// the sticking shortens. Unchanged at 96 kHz and for contact radii 0.8-2 mm.
TEST(PlasticRig, DISABLED_StickSlipNear44Hz)
{
    const RigRun run = seedRun(FrictionModel::Plastic);
    const double f = stickSlipFrequency(run, kSettledFrom);
    RecordProperty("stickSlipHz", std::to_string(f));
    EXPECT_NEAR(f, 44.0, 0.15 * 44.0);
}

// Measured: 50.6-60.7 K once settled (22-64 K over the first cycles).
TEST(PlasticRig, DISABLED_TemperatureSwingsBetween20And40Kelvin)
{
    const RigRun run = seedRun(FrictionModel::Plastic);
    const Range T = temperatureRange(run, kSettledFrom);
    RecordProperty("minKelvin", std::to_string(T.low));
    RecordProperty("maxKelvin", std::to_string(T.high));
    EXPECT_NEAR(T.low, 20.0, 5.0);
    EXPECT_NEAR(T.high, 40.0, 5.0);
}

TEST(PlasticRig, StillStickSlips)
{
    // Whatever its frequency, the plastic law keeps sticking and slipping on this rig (it has a static
    // limit).
    const RigRun run = seedRun(FrictionModel::Plastic);
    EXPECT_GT(stickSlipFrequency(run, kSettledFrom), 0.0);
}

TEST(PlasticRig, LoopRunsAnticlockwise)
{
    const RigRun run = seedRun(FrictionModel::Plastic);
    const double area = loopSignedArea(run, kSettledFrom);
    RecordProperty("signedArea", std::to_string(area));
    EXPECT_GT(area, 0.0);
    // And the loop is open, not a trace retraced: per cycle, a sizeable share of the rectangle it spans.
    const auto onsets = slipOnsetTimes(run, kSettledFrom);
    ASSERT_GE(onsets.size(), 2u);
    const double cycles = static_cast<double>(onsets.size()) * (1.0 - kSettledFrom) /
                          (onsets.back() - onsets.front() + 1.0 / stickSlipFrequency(run, kSettledFrom));
    double dvMin = 0.0, muMin = 1e300, muMax = -1e300;
    for (std::size_t k = sampleAt(run, kSettledFrom); k < run.samples.size(); ++k)
    {
        dvMin = std::min(dvMin, run.samples[k].slidingSpeed);
        muMin = std::min(muMin, run.samples[k].frictionCoefficient());
        muMax = std::max(muMax, run.samples[k].frictionCoefficient());
    }
    EXPECT_GT(area / cycles, 0.05 * (-dvMin) * (muMax - muMin));
}

TEST(ViscousRig, ForwardSlippingWithTheSeedsThermalValues)
{
    const RigRun run = seedRun(FrictionModel::Viscous);
    const double dv = largestForwardSlip(run);
    RecordProperty("largestForwardSlip", std::to_string(dv));
    // The oscillator overtakes the rod by far more than a creep: several times the rod's own speed.
    EXPECT_GT(dv, CantileverLoad::rodSpeed);
}

// Measured: no forward slip at 10x (largest v - v_rod 2e-7 m/s): after the first release the cooled, viscous
// layer damps the swing before it overtakes the rod. 2x, 3x and 5x do slip forward (2.4, 2.6, 3.0 m/s).
TEST(ViscousRig, DISABLED_ForwardSlippingWithAnOrderOfMagnitudeHigherSpecificHeat)
{
    ContactParameters c = cantileverContact();
    c.material.volumetricHeatCapacity *= 10.0; // "an order of magnitude higher", as for paraffin wax
    const RigRun run = seedRun(FrictionModel::Viscous, c);
    const double dv = largestForwardSlip(run);
    RecordProperty("largestForwardSlip", std::to_string(dv));
    EXPECT_GT(dv, CantileverLoad::rodSpeed);
}
