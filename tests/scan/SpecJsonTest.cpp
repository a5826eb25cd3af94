// The specification file: a complete, canonical description (resume and merge compare texts), read back to
// the same model and grid.
#include <gtest/gtest.h>

#include "config/ConfigError.h"
#include "lab/scan/SpecJson.h"
#include "lab/scan/Variations.h"

using namespace rosin::scan;

TEST(SpecJson, RoundTripIsExact)
{
    for (const ScanKind kind : {ScanKind::Schelleng, ScanKind::Guettler})
    {
        ScanSpec s = defaultSpec(kind);
        ModelVariations v;
        v.contactRadius = 7e-4;
        v.scaling = rosin::physics::ContactScaling::Hertz;
        v.noTorsion = true;
        v.fingerDamping = true;
        applyVariations(s.model, v);
        const std::string text = specText(s);
        const ScanSpec back = specFromText(text, "scan.spec.json");
        EXPECT_EQ(specText(back), text);
        EXPECT_EQ(back.forces, s.forces);
        EXPECT_EQ(back.second, s.second);
        EXPECT_EQ(back.model.contact.calibration.radius, 7e-4);
        EXPECT_EQ(back.model.contact.rig.scaling, rosin::physics::ContactScaling::Hertz);
        EXPECT_FALSE(back.model.torsion);
        EXPECT_TRUE(back.model.fingerDamping);
        EXPECT_EQ(back.model.string.tension, s.model.string.tension);
    }
}

TEST(SpecJson, DifferencesAreNamed)
{
    ScanSpec a = defaultSpec(ScanKind::Guettler), b = a;
    b.model.friction = "classical";
    b.trialSeconds = 1.0;
    const std::string d = describeSpecDifference(specText(a), specText(b));
    EXPECT_NE(d.find("friction: \"plastic\" vs \"classical\""), std::string::npos) << d;
    EXPECT_NE(d.find("trialSeconds: 0.5 vs 1.0"), std::string::npos) << d;
}

TEST(SpecJson, BadFilesAreReportedWithTheField)
{
    EXPECT_THROW(specFromText("not json", "f.json"), rosin::config::ConfigError);
    auto j = specToJson(defaultSpec(ScanKind::Guettler));
    j.erase("forces");
    try
    {
        specFromJson(j, "f.json");
        FAIL();
    }
    catch (const rosin::config::ConfigError& e)
    {
        EXPECT_EQ(e.field(), "forces");
    }
}

// Spec files from before trials could end early describe whole trials, and are read as such.
TEST(SpecJson, OlderFilesWithoutTheEarlyEndRunWholeTrials)
{
    ScanSpec s = defaultSpec(ScanKind::Guettler);
    ASSERT_TRUE(s.endAfterTransient);
    nlohmann::json j = specToJson(s);
    EXPECT_TRUE(specFromJson(j, "new.json").endAfterTransient);
    j.erase("endAfterTransient");
    EXPECT_FALSE(specFromJson(j, "old.json").endAfterTransient);
    s.endAfterTransient = false;
    EXPECT_EQ(specText(specFromText(specText(s), "x.json")), specText(s));
}
