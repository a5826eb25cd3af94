// The cantilever's contact against [Smith2000]'s design condition (about 55 K above ambient in steady sliding
// at the rod speed) and against the steady-sliding curve it is calibrated on.
#include <gtest/gtest.h>

#include <cmath>

#include "core/physics/friction/FrictionCurves.h"
#include "core/physics/rig/RigTestSupport.h"
#include "core/physics/thermal/PlasticThermalLaw.h"

using namespace rosin::physics;
using namespace rosin::test::rig;

// Calibrations ([Smith2000] chose its contact size by this condition), checked, not reproductions.
TEST(CantileverContact, CalibratedRadiusGives55KelvinInSteadySliding)
{
    const ContactParameters c = cantileverContact();
    const double radius =
        contactRadiusForSteadyTemperature(kCantileverSteadyTemperature, CantileverLoad::rodSpeed,
                                          CantileverLoad::normalForce, c.rig.layerThickness, c.materials);
    RecordProperty("radiusMetres", std::to_string(radius));
    EXPECT_NEAR(c.rig.radius, radius, 0.01 * radius);
    EXPECT_NEAR(steadySlidingTemperature(c, CantileverLoad::rodSpeed, CantileverLoad::normalForce), 55.0,
                1.0);
}

TEST(CantileverContact, CalibratedOnItself)
{
    // [Smith2000] measured eq. 2 on the same surfaces, so the calibration contact is the rig contact.
    const ContactParameters c = cantileverContact();
    EXPECT_EQ(c.calibration.radius, c.rig.radius);
    EXPECT_EQ(c.calibration.referenceForce, c.rig.referenceForce);
    EXPECT_EQ(c.calibration.layerThickness, c.rig.layerThickness);
    EXPECT_EQ(c.rig.referenceForce, CantileverLoad::normalForce);
}

TEST(CantileverContact, PlasticLawStartsFromTheCurvesStaticCoefficient)
{
    // Equal area per newton in calibration and rig: mu_s at ambient is eq. 2's 0.4 + 0.45 + 0.35 = 1.2
    // ([Notes §2.1]: 1.2 (A_rig/N)/(A_cal/N_cal)).
    PlasticThermalLaw law(cantileverContact());
    law.prepare(kSampleRate);
    EXPECT_NEAR(law.staticCoefficient(CantileverLoad::normalForce), ClassicalCurve{}.mu(0.0), 1e-3);
}

TEST(CantileverContact, CalibrationHoldsInTimeSteppedSteadySliding)
{
    // A rod sliding steadily over a clamped wedge (velocity-controlled: a very stiff load line) reproduces
    // eq. 2 and heats the contact to the design temperature.
    PlasticThermalLaw law(cantileverContact());
    law.prepare(kSampleRate);
    JunctionSolution s;
    for (int k = 0; k < static_cast<int>(4.0 * kSampleRate); ++k)
        s = law.solve({-CantileverLoad::rodSpeed, 1e7, CantileverLoad::normalForce});
    EXPECT_NEAR(std::abs(s.frictionForce) / CantileverLoad::normalForce,
                ClassicalCurve{}.mu(CantileverLoad::rodSpeed), 0.02);
    EXPECT_NEAR(law.contactTemperature(), 55.0, 3.0);
}
