// The specification file: a complete, canonical description (resume and merge compare texts), read back to
// the same model and grid.
#include <gtest/gtest.h>

#include "core/config/ConfigError.h"
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

// Spec files keep the trial-end rule their rows were computed with: files from before trials could end
// early describe whole trials, files from before "trialEnd" with "endAfterTransient": true the window rule.
TEST(SpecJson, OlderFilesKeepTheirTrialEndRule)
{
    ScanSpec s = defaultSpec(ScanKind::Guettler);
    ASSERT_EQ(s.trialEnd, GuettlerTrialEnd::WhenDecided);
    nlohmann::json j = specToJson(s);
    EXPECT_EQ(j.at("trialEnd"), "decided");
    EXPECT_EQ(specFromJson(j, "new.json").trialEnd, GuettlerTrialEnd::WhenDecided);
    j.erase("trialEnd");
    EXPECT_EQ(specFromJson(j, "oldest.json").trialEnd, GuettlerTrialEnd::Whole);
    j["endAfterTransient"] = true;
    EXPECT_EQ(specFromJson(j, "old.json").trialEnd, GuettlerTrialEnd::AfterWindow);
    j["endAfterTransient"] = false;
    EXPECT_EQ(specFromJson(j, "old.json").trialEnd, GuettlerTrialEnd::Whole);
    for (auto e : {GuettlerTrialEnd::Whole, GuettlerTrialEnd::AfterWindow, GuettlerTrialEnd::WhenDecided})
    {
        s.trialEnd = e;
        EXPECT_EQ(specText(specFromText(specText(s), "x.json")), specText(s));
    }
}

TEST(SpecJson, AnUnknownTrialEndRuleNamesTheField)
{
    nlohmann::json j = specToJson(defaultSpec(ScanKind::Guettler));
    j["trialEnd"] = "soon";
    try
    {
        specFromJson(j, "bad.json");
        FAIL() << "accepted trialEnd \"soon\"";
    }
    catch (const rosin::config::ConfigError& e)
    {
        EXPECT_EQ(e.field(), "trialEnd");
        EXPECT_NE(std::string(e.what()).find("bad.json"), std::string::npos);
        EXPECT_NE(std::string(e.what()).find("decided"), std::string::npos);
    }
}

TEST(SpecJson, TheBowIsWrittenOnlyWhenNotTheSeedsPoint)
{
    ScanSpec s = defaultSpec(ScanKind::Guettler);
    EXPECT_FALSE(specToJson(s).contains("bow")); // older specs read back byte-identical
    ModelVariations v;
    v.bowWidth = 0.008;
    v.horsehair = true;
    applyVariations(s.model, v);
    const ScanSpec back = specFromText(specText(s), "scan.spec.json");
    EXPECT_EQ(specText(back), specText(s));
    EXPECT_EQ(back.model.bow.width, 0.008);
    EXPECT_TRUE(back.model.bow.compliantHair);
    EXPECT_EQ(back.model.bow.hairStiffness, rosin::physics::horsehairBow(0.0).hairStiffness);
}

TEST(SpecJson, ClassificationIsWrittenOnlyWhenNotTheDefault)
{
    ScanSpec s = defaultSpec(ScanKind::Guettler);
    EXPECT_FALSE(specToJson(s).contains("classification")); // older specs read back byte-identical
    EXPECT_EQ(specFromJson(specToJson(s), "a.json").classification, Classification::State);
    s.classification = Classification::BridgeForce;
    nlohmann::json j = specToJson(s);
    EXPECT_EQ(j.at("classification"), "bridge-force");
    EXPECT_EQ(specFromJson(j, "b.json").classification, Classification::BridgeForce);
    j["classification"] = "guess";
    try
    {
        specFromJson(j, "c.json");
        FAIL() << "an unknown classification was accepted";
    }
    catch (const rosin::config::ConfigError& e)
    {
        EXPECT_NE(std::string(e.what()).find("classification"), std::string::npos) << e.what();
    }
}
