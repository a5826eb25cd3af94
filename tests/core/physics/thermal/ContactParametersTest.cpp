// Contact radius scaling and the [Galluzzo2017] Table 2 contacts.
#include <gtest/gtest.h>

#include <cmath>

#include "core/physics/thermal/ContactParameters.h"

using namespace rosin::physics;

TEST(ContactParameters, CoulombRadiusGrowsWithSquareRootOfForce)
{
    const ContactGeometry g{250e-6, 1.0, 1e-6, ContactScaling::Coulomb};
    EXPECT_NEAR(g.radiusAt(1.0), 250e-6, 1e-15);
    EXPECT_NEAR(g.radiusAt(4.0), 500e-6, 1e-15); // A proportional to N
    EXPECT_NEAR(g.radiusAt(3.0), 250e-6 * std::sqrt(3.0), 1e-15);
    EXPECT_EQ(g.radiusAt(0.0), 0.0);
    EXPECT_EQ(g.radiusAt(-1.0), 0.0);
}

TEST(ContactParameters, HertzRadiusGrowsWithCubeRootOfForce)
{
    const ContactGeometry g{250e-6, 1.0, 1e-6, ContactScaling::Hertz};
    EXPECT_NEAR(g.radiusAt(8.0), 500e-6, 1e-15); // A proportional to N^(2/3)
    EXPECT_NEAR(g.radiusAt(0.125), 125e-6, 1e-15);
}

TEST(ContactParameters, SeedTable2Contacts)
{
    const ContactParameters g = galluzzoContact();
    EXPECT_DOUBLE_EQ(g.rig.radius, 250e-6);
    EXPECT_DOUBLE_EQ(g.rig.referenceForce, 1.0);
    EXPECT_DOUBLE_EQ(g.rig.layerThickness, 1e-6);
    EXPECT_DOUBLE_EQ(g.calibration.radius, 500e-6);
    EXPECT_DOUBLE_EQ(g.calibration.referenceForce, 3.0);
    EXPECT_DOUBLE_EQ(g.calibration.layerThickness, 10e-6);
    const ContactParameters s = schumacherContact();
    EXPECT_DOUBLE_EQ(s.rig.radius, 200e-6);
    EXPECT_DOUBLE_EQ(s.rig.referenceForce, 1.0);
    EXPECT_DOUBLE_EQ(s.rig.layerThickness, 1e-6);
    EXPECT_EQ(s.rig.scaling, ContactScaling::Coulomb);
}
