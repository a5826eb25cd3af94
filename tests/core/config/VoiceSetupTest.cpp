// From presets to the physics configuration.
#include <gtest/gtest.h>

#include "core/config/ConfigError.h"
#include "core/config/PresetLoader.h"
#include "core/config/RefusedPreset.h"
#include "core/config/TempFiles.h"
#include "core/config/VoiceSetup.h"
#include "core/physics/body/BodyParameters.h"
#include "core/physics/thermal/RosinMaterial.h"

namespace rosin::config
{
namespace ROSIN_FILE_LOCAL
{

TEST(VoiceSetup, DefaultIsTheGalluzzoRig)
{
    const VoiceSetup s = buildVoiceSetup(defaultPreset());
    EXPECT_EQ(s.voice.string.name, "cello-D3");
    EXPECT_EQ(s.voice.body.name, "cello");
    EXPECT_FALSE(s.voice.body.rigid());
    EXPECT_EQ(s.friction, physics::FrictionModel::Plastic);
    const auto galluzzo = physics::galluzzoContact();
    EXPECT_EQ(s.contact.rig.radius, galluzzo.rig.radius);
    EXPECT_EQ(s.contact.rig.referenceForce, galluzzo.rig.referenceForce);
    EXPECT_TRUE(s.voice.torsion);
    EXPECT_TRUE(s.voice.bendingStiffness);
}

TEST(VoiceSetup, SchumacherRigIsAMonochord)
{
    const VoiceSetup s = buildVoiceSetup(loadPreset("schumacher-rig"));
    EXPECT_EQ(s.voice.string.name, "violin-E5");
    EXPECT_TRUE(s.voice.body.rigid());
    EXPECT_EQ(s.contact.rig.radius, physics::schumacherContact().rig.radius);
}

TEST(VoiceSetup, ContactOverridesAndSwitchesApply)
{
    Preset p = defaultPreset();
    p.contactOverrides.radius = 4.33e-4;
    p.contactOverrides.scaling = physics::ContactScaling::Hertz;
    p.ambientOffset = 3.0;
    p.torsion = false;
    p.bendingStiffness = false;
    p.friction = "modified-rod";
    p.body = "rigid";
    const VoiceSetup s = buildVoiceSetup(p);
    EXPECT_EQ(s.contact.rig.radius, 4.33e-4);
    EXPECT_EQ(s.contact.rig.referenceForce, physics::galluzzoContact().rig.referenceForce);
    EXPECT_EQ(s.contact.rig.scaling, physics::ContactScaling::Hertz);
    EXPECT_EQ(s.contact.ambientOffset, 3.0);
    EXPECT_FALSE(s.voice.torsion);
    EXPECT_FALSE(s.voice.bendingStiffness);
    EXPECT_EQ(s.friction, physics::FrictionModel::ModifiedRod);
    EXPECT_TRUE(s.voice.body.rigid());
}

// "rosin": the calibrated rosin changes rho c of the layer and of every rosin-coated side, nothing else; the
// cantilever preset ([Smith2000]'s rig) carries it, the instrument's presets keep the handbook rosin.
TEST(VoiceSetup, RosinMaterialReplacesEveryRosinSurface)
{
    Preset p = defaultPreset();
    EXPECT_EQ(p.rosin, "handbook");
    const VoiceSetup handbook = buildVoiceSetup(p);
    p.rosin = "calibrated";
    const VoiceSetup calibrated = buildVoiceSetup(p);
    const double factor = physics::kCalibratedRosinHeatCapacityFactor;
    EXPECT_DOUBLE_EQ(calibrated.contact.materials.layer.volumetricHeatCapacity,
                     factor * handbook.contact.materials.layer.volumetricHeatCapacity);
    EXPECT_DOUBLE_EQ(calibrated.contact.materials.stationary.volumetricHeatCapacity, // the string's coat
                     factor * handbook.contact.materials.stationary.volumetricHeatCapacity);
    EXPECT_EQ(calibrated.contact.materials.moving.volumetricHeatCapacity, // Galluzzo's acrylic rod
              handbook.contact.materials.moving.volumetricHeatCapacity);
    EXPECT_EQ(calibrated.contact.materials.layer.conductivity, handbook.contact.materials.layer.conductivity);

    const VoiceSetup rig = buildVoiceSetup(loadPreset("cantilever"));
    EXPECT_DOUBLE_EQ(rig.contact.materials.moving.volumetricHeatCapacity, // the rod's rosin coat
                     factor * physics::materials::rosin.volumetricHeatCapacity);
    EXPECT_EQ(rig.contact.materials.stationary.volumetricHeatCapacity, // the perspex wedge
              physics::materials::acrylic.volumetricHeatCapacity);
    EXPECT_EQ(loadPreset("cello-solo").rosin, "handbook");

    test::TempDir dir;
    test::expectPresetRefused(dir.write("bad.json", R"({"format": "rosin-preset/1", "rosin": "wax"})"),
                              "rosin", "handbook", "an unknown rosin");
}

TEST(VoiceSetup, EveryShippedPresetBuildsAFrictionLaw)
{
    for (const auto& name : presetNames())
    {
        SCOPED_TRACE(name);
        const VoiceSetup s = buildVoiceSetup(loadPreset(name));
        EXPECT_NE(physics::makeFrictionLaw(s.friction, s.contact), nullptr);
    }
}

TEST(VoiceSetup, FrictionAndBodyNamesMatchThePhysics)
{
    EXPECT_EQ(frictionNames(), (std::vector<std::string>{"classical", "reconstructed", "plastic", "viscous",
                                                         "modified-bow", "modified-rod"}));
    for (const auto& body : bodyNames())
        EXPECT_EQ(physics::bodyByName(body).name, body);
}

TEST(VoiceSetup, UnknownNamesFromCodeAreReportedNotCrashed)
{
    Preset p = defaultPreset();
    p.friction = "plasticc";
    try
    {
        buildVoiceSetup(p);
        FAIL();
    }
    catch (const ConfigError& e)
    {
        EXPECT_EQ(e.field(), "friction");
        EXPECT_EQ(e.file(), "<built-in default>");
    }
}

} // namespace ROSIN_FILE_LOCAL
} // namespace rosin::config
