// [Smith2000]'s thermal laws on the same rig, same modal mass and same contact, with the handbook rosin:
// predictions, not fits (CalibratedRosinRigTest.cpp: the same rig with the calibrated rosin).
//  * plastic (eq. 4): "stick-slip motion at about 44 Hz", "contact temperature fluctuates in the range
//    20-40 K above ambient", hysteresis "in the correct sense" (anticlockwise, Fig. 2c);
//  * viscous (eq. 3): "forward slipping" (the oscillator faster than the rod), with [Smith2000]'s thermal
//  values
//    and with a higher specific heat alike.
// Tests named ...KnownDiscrepancy are seed results this model does not reproduce: each asserts the band that
// was measured, so that a crash or a change in either direction is noticed, and its comment gives
// [Smith2000]'s figure.
#include <gtest/gtest.h>

#include <algorithm>

#include "core/physics/rig/RigTestSupport.h"

using namespace rosin::physics;
using namespace rosin::test::rig;

namespace ROSIN_FILE_LOCAL
{

// Seed: "stick-slip motion at about 44 Hz". Measured with the two-sided heat balance (handbook constants,
// ThermalMaterial.h; perspex wedge, rosin coat on the rod): the first cycle from rest lasts 24.6 ms (40.7 Hz,
// within 8 % of [Smith2000]), then the period shortens (22.8, 21.7, 21.0 ms ...) and settles at 54.9 Hz
// (0.5-1 s): the wedge keeps part of every slip's heat and each settled cycle slides the rod ~0.75 mm, a
// little less than the contact width, so the floor stays above [Smith2000]'s. (Old one-sided balance: 89.9
// Hz.)
TEST(PlasticRig, StickSlipFrequencyKnownDiscrepancy)
{
    const RigRun run = seedRun(FrictionModel::Plastic);
    const double f = stickSlipFrequency(run, kSettledFrom);
    RecordProperty("stickSlipHz", std::to_string(f));
    EXPECT_GT(f, 49.0);
    EXPECT_LT(f, 61.0);
    const auto onsets = slipOnsetTimes(run, 0.0);
    ASSERT_GE(onsets.size(), 2u);
    EXPECT_NEAR(1.0 / (onsets[1] - onsets[0]), 44.0, 0.15 * 44.0); // the first cycle does match [Smith2000]
}

// Seed: "the contact temperature fluctuates in the range 20-40 K above ambient". Measured: 34.4-67.5 K
// settled (0.5-1 s). (Old one-sided balance: 50.6-60.7 K.)
TEST(PlasticRig, TemperatureRangeKnownDiscrepancy)
{
    const RigRun run = seedRun(FrictionModel::Plastic);
    const TemperatureRange T = temperatureRange(run, kSettledFrom);
    RecordProperty("minKelvin", std::to_string(T.low));
    RecordProperty("maxKelvin", std::to_string(T.high));
    EXPECT_GT(T.low, 28.0);
    EXPECT_LT(T.low, 41.0);
    EXPECT_GT(T.high, 60.0);
    EXPECT_LT(T.high, 75.0);
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

// Seed: forward slipping also with "an order of magnitude higher" specific heat. Measured: none at 10x the
// rosin layer's rho c (largest v - v_rod ~2e-7 m/s): after the first release the cooled, viscous layer damps
// the swing before it overtakes the rod. The band asserted is "no forward slip".
TEST(ViscousRig, ForwardSlippingWithAnOrderOfMagnitudeHigherSpecificHeatKnownDiscrepancy)
{
    ContactParameters c = cantileverContact();
    c.materials.layer.volumetricHeatCapacity *= 10.0; // rosin's: "an order of magnitude higher", as for wax
    const RigRun run = seedRun(FrictionModel::Viscous, c);
    const double dv = largestForwardSlip(run);
    RecordProperty("largestForwardSlip", std::to_string(dv));
    EXPECT_LT(dv, 1e-3 * CantileverLoad::rodSpeed);
}

} // namespace ROSIN_FILE_LOCAL
