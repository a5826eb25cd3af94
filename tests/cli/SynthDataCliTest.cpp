// `rosin synth-data` through the built binary: small datasets read back by the discovery reader and WAV
// reader, byte-identical for one seed, nothing in them naming the hidden effect, nominal settings on the
// grid while the simulation used jittered ones (checked against the truth file and the recorded bow
// velocity), failed trials present, bad input refused with nothing written, and one physics check: the
// first-slip mu_s a laboratory would measure rises when junction growth is hidden.
#include <gtest/gtest.h>

#include "cli/CliSupport.h"

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <sys/wait.h>

#include <nlohmann/json.hpp>

#include "core/analysis/FirstSlip.h"
#include "core/config/TempFiles.h"
#include "lab/discovery/DatasetReader.h"
#include "lab/discovery/EffectCatalog.h"
#include "lab/discovery/independent/GeneratorMember.h"
#include "lab/discovery/io/TrialSignals.h"
#include "lab/scan/Axis.h"

namespace ROSIN_FILE_LOCAL
{
namespace fs = std::filesystem;
using namespace rosin::discovery;

using rosin::test::cli::quote;
using rosin::test::cli::Result;
using rosin::test::cli::slurp;

class SynthDataCli : public ::testing::Test
{
  protected:
    // Runs `rosin synth-data ARGS` (or `rosin SHELL-ARGS` when `raw`) in the scratch folder.
    Result synth(const std::vector<std::string>& args)
    {
        std::string command = "cd " + quote(dir.path()) +
                              " && ROSIN_PRESET_DIR=" + quote(ROSIN_SOURCE_PRESET_DIR) + " " +
                              quote(ROSIN_BINARY) + " synth-data";
        for (const auto& a : args)
            command += " " + quote(a);
        command += " >" + quote(dir.path() + "/stdout.txt") + " 2>" + quote(dir.path() + "/stderr.txt");
        const int raw = std::system(command.c_str());
        return {WIFEXITED(raw) ? WEXITSTATUS(raw) : -1, slurp(dir.path() + "/stdout.txt"),
                slurp(dir.path() + "/stderr.txt")};
    }
    std::string path(const std::string& name) const { return dir.path() + "/" + name; }
    /// Every file of a dataset folder by relative path, with its bytes.
    std::map<std::string, std::string> files(const std::string& folder) const
    {
        std::map<std::string, std::string> all;
        for (const auto& e : fs::recursive_directory_iterator(path(folder)))
            if (e.is_regular_file())
                all[fs::relative(e.path(), path(folder)).string()] = slurp(e.path());
        return all;
    }

    rosin::test::TempDir dir;
};

// 3 x 3 Guettler trials of 0.2 s at one beta.
std::vector<std::string> tiny(const std::string& effect, const std::string& seed, const std::string& out,
                              std::vector<std::string> more = {})
{
    std::vector<std::string> args = {"--effect", effect,   "--scan", "guettler",   "--grid",
                                     "3",        "--beta", "0.0899", "--duration", "0.2",
                                     "--seed",   seed,     "--out",  out};
    args.insert(args.end(), more.begin(), more.end());
    return args;
}

nlohmann::json readJson(const std::string& file)
{
    return nlohmann::json::parse(slurp(file));
}

TEST_F(SynthDataCli, HelpDocumentsTheOptionsAndTheEffects)
{
    const Result r = synth({"--help"});
    EXPECT_EQ(r.status, 0);
    for (const char* text :
         {"--effect NAME|none", "--scan guettler|schelleng", "--grid", "--beta", "--force-range",
          "--acceleration-range", "--bow-speed", "--duration", "--preset", "--sample-rate",
          "--channels basic|all", "--seed", "--out", "--truth", "--threads", "none"})
        EXPECT_NE(r.out.find(text), std::string::npos) << text;
    for (const auto& e : effectCatalog())
    {
        EXPECT_NE(r.out.find(e.name), std::string::npos) << e.name;
        for (const auto& p : e.parameters)
            EXPECT_NE(r.out.find(p.name), std::string::npos) << p.name;
    }
}

TEST_F(SynthDataCli, SmallDatasetReadsBack)
{
    const Result r = synth(tiny("junction-growth", "1", "ds", {"--truth", "truth.json"}));
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.out.find("hidden (not in the dataset): junction-growth: growth = "), std::string::npos)
        << r.out;
    EXPECT_FALSE(fs::exists(path("ds.tmp")));
    const Dataset d = readDatasetDescription(path("ds"));
    ASSERT_EQ(d.trials.size(), 9u);
    EXPECT_EQ(d.sampleRate, 44100);
    ASSERT_EQ(d.channels.size(), 2u);
    EXPECT_EQ(d.channels[0], (Channel{"bridgeForce", "N"}));
    EXPECT_EQ(d.channels[1], (Channel{"bowVelocity", "m/s"}));
    EXPECT_EQ(d.sensor.highpassHz, 0.5);
    ASSERT_TRUE(d.sensor.noiseRms);
    EXPECT_GT(*d.sensor.noiseRms, 0.0);
    EXPECT_TRUE(d.rig.defaultedStringFields.empty());
    EXPECT_EQ(d.rig.body, "cello");
    EXPECT_EQ(d.rig.ambientTemperature, 20.0);
    EXPECT_EQ(d.trials.front().id, "b0899-f00-a00");
    for (const auto& t : d.trials)
    {
        const TrialSignals s = readTrialSignals(d, t);
        EXPECT_EQ(s.frames(), 8820u) << t.id;
    }
    const auto truth = readJson(path("truth.json"));
    EXPECT_EQ(truth["effects"][0]["name"], "junction-growth");
    EXPECT_TRUE(truth["effects"][0]["parameters"].contains("growth"));

    // All channels: four, in the spec's order.
    ASSERT_EQ(synth(tiny("none", "1", "all", {"--channels", "all"})).status, 0);
    const Dataset all = readDatasetDescription(path("all"));
    ASSERT_EQ(all.channels.size(), 4u);
    EXPECT_EQ(all.channels[1].name, "frictionForce");
    EXPECT_EQ(all.channels[2].name, "bowPointVelocity");
    EXPECT_EQ(readTrialSignals(all, all.trials.back()).samples.size(), 4u);
}

TEST_F(SynthDataCli, SameSeedSameBytesOtherSeedOtherData)
{
    ASSERT_EQ(synth(tiny("sticking-creep", "5", "a")).status, 0);
    ASSERT_EQ(synth(tiny("sticking-creep", "5", "b", {"--threads", "1"})).status, 0);
    ASSERT_EQ(synth(tiny("sticking-creep", "6", "c")).status, 0);
    const auto a = files("a"), b = files("b"), c = files("c");
    EXPECT_EQ(a.size(), 10u);
    EXPECT_TRUE(a == b) << "same seed, different thread count: files differ";
    EXPECT_EQ(a.at("dataset.json").empty(), false);
    for (const auto& [name, bytes] : a)
        if (name != "dataset.json") // the nominal description may coincide; the recordings may not
            EXPECT_NE(bytes, c.at(name)) << name;
}

// The independent generator's family: member 0 is what the generator has always written (the same bytes as
// without --member), another member writes other recordings, records its draws in the truth file, and a
// member without a body states the rigid bridge in dataset.json, as the rig it is.
TEST_F(SynthDataCli, GeneratorMembersAreOtherSimulatorsOfTheStatedRig)
{
    auto args = [&](const std::string& out, const std::string& member)
    {
        auto a = tiny("none", "5", out, {"--generator", "independent", "--truth", path(out + ".json")});
        if (!member.empty())
            a.insert(a.end(), {"--member", member});
        return a;
    };
    unsigned rigidMember = 0;
    for (unsigned k = 1; k < 100 && rigidMember == 0; ++k)
        if (!generatorMember(k).body)
            rigidMember = k;
    ASSERT_EQ(synth(args("plain", "")).status, 0);
    ASSERT_EQ(synth(args("zero", "0")).status, 0);
    ASSERT_EQ(synth(args("other", std::to_string(rigidMember))).status, 0);
    const auto plain = files("plain"), zero = files("zero"), other = files("other");
    EXPECT_TRUE(plain == zero) << "member 0 is the nominal design";
    for (const auto& [name, bytes] : plain)
        if (name != "dataset.json")
            EXPECT_NE(bytes, other.at(name)) << name;
    EXPECT_FALSE(readJson(path("zero.json"))["independent"].contains("member"));
    const auto drawn = readJson(path("other.json"))["independent"]["member"];
    EXPECT_EQ(drawn["member"].get<double>(), rigidMember);
    EXPECT_EQ(drawn["body"].get<double>(), 0.0);
    EXPECT_EQ(readJson(path("plain/dataset.json"))["rig"]["body"], "cello");
    EXPECT_EQ(readJson(path("other/dataset.json"))["rig"]["body"], "rigid");
}

TEST_F(SynthDataCli, NothingInTheDatasetNamesTheHiddenEffect)
{
    std::vector<std::string> args = {"--scan",     "guettler", "--grid",  "3",         "--beta",     "0.0899",
                                     "--duration", "0.1",      "--seed",  "2",         "--channels", "all",
                                     "--out",      "hidden",   "--truth", "truth.json"};
    for (const auto& name : effectNames())
        args.insert(args.end(), {"--effect", name});
    const Result r = synth(args);
    ASSERT_EQ(r.status, 0) << r.err;
    std::string grep = "grep -rilF";
    for (const auto& e : effectCatalog())
    {
        grep += " -e " + quote(e.name);
        for (const auto& p : e.parameters)
            grep += " -e " + quote(p.name);
    }
    // Names of files too, not only their contents.
    grep += " " + quote(path("hidden")) + " >" + quote(path("grep.txt")) + "; ls -R " +
            quote(path("hidden")) + " >" + quote(path("ls.txt"));
    ASSERT_EQ(std::system(grep.c_str()) == -1, false);
    EXPECT_EQ(slurp(path("grep.txt")), "") << "files naming the hidden effects";
    const std::string listing = slurp(path("ls.txt"));
    for (const auto& name : effectNames())
        EXPECT_EQ(listing.find(name), std::string::npos) << name;
    // ... while the truth outside the folder has them all.
    const std::string truth = slurp(path("truth.json"));
    for (const auto& name : effectNames())
        EXPECT_NE(truth.find(name), std::string::npos) << name;
}

TEST_F(SynthDataCli, NominalSettingsOnTheGridWhileTheTrialsUsedJitteredOnes)
{
    ASSERT_EQ(synth(tiny("none", "3", "ds", {"--truth", "truth.json"})).status, 0);
    const Dataset d = readDatasetDescription(path("ds"));
    const auto truth = readJson(path("truth.json"));
    const auto forces = rosin::scan::linearAxis(0.4, 3.2, 3),
               accelerations = rosin::scan::linearAxis(0.08, 3.2, 3);
    ASSERT_EQ(truth["trials"].size(), d.trials.size());
    int distinguished = 0;
    for (std::size_t i = 0; i < d.trials.size(); ++i)
    {
        const Trial& t = d.trials[i];
        const double nominalA = std::get<ConstantAcceleration>(t.gesture).acceleration;
        EXPECT_EQ(t.bowForce, forces[(i / 3) % 3]);
        EXPECT_EQ(nominalA, accelerations[i % 3]);
        const auto& actual = truth["trials"][i];
        ASSERT_EQ(actual["id"], t.id);
        const double actualF = actual["bowForce"], actualA = actual["acceleration"];
        EXPECT_NE(actualF, t.bowForce);
        EXPECT_LT(std::abs(actualF / t.bowForce - 1.0), 0.05);
        EXPECT_LT(std::abs(actualA / nominalA - 1.0), 0.05);
        if (!t.valid)
            continue;
        // The recorded bow velocity is the actual a t (plus noise): its slope tells the two apart.
        const auto v = readTrialSignals(d, t).channel("bowVelocity");
        double vt = 0.0, tt = 0.0;
        for (std::size_t n = 0; n < v.size(); ++n)
        {
            const double time = n / 44100.0;
            vt += v[n] * time;
            tt += time * time;
        }
        // Least-squares slope through the origin; its standard error from the stated noise floor.
        const double slope = vt / tt, error = *d.sensor.noiseRms / std::sqrt(tt);
        EXPECT_NEAR(slope, actualA, 4.0 * error) << t.id;
        if (std::abs(actualA - nominalA) > 8.0 * error)
        {
            EXPECT_GT(std::abs(slope - nominalA), 4.0 * error) << t.id;
            ++distinguished;
        }
    }
    EXPECT_GT(distinguished, 0);
}

TEST_F(SynthDataCli, AFewTrialsFailAndStayReadable)
{
    const Result r = synth({"--effect", "none", "--scan", "guettler", "--grid", "5x4", "--duration", "0.1",
                            "--seed", "4", "--out", "ds", "--truth", "truth.json"});
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.out.find("20 trials (1 marked invalid)"), std::string::npos) << r.out;
    const Dataset d = readDatasetDescription(path("ds"));
    const auto truth = readJson(path("truth.json"));
    int invalid = 0;
    for (std::size_t i = 0; i < d.trials.size(); ++i)
    {
        const auto s = readTrialSignals(d, d.trials[i]); // every file reads, failed or not
        if (d.trials[i].valid)
        {
            EXPECT_EQ(s.frames(), 4410u);
            EXPECT_FALSE(truth["trials"][i].contains("fault"));
            continue;
        }
        ++invalid;
        ASSERT_TRUE(truth["trials"][i].contains("fault"));
        const auto& f = s.channel("bridgeForce");
        std::size_t run = 0, longest = 0;
        for (double x : f)
            longest = std::max(longest, run = x == 0.0 ? run + 1 : 0);
        EXPECT_TRUE(s.frames() < 4410u || longest >= 200u) << "neither cut short nor dropped out";
    }
    EXPECT_EQ(invalid, 1);
}

TEST_F(SynthDataCli, TruthInsideTheDatasetIsRefused)
{
    for (const char* truth : {"ds/truth.json", "ds", "./ds/sub/../truth.json", "ds.tmp/truth.json"})
    {
        const Result r = synth(tiny("hertz-contact", "1", "ds", {"--truth", truth}));
        EXPECT_EQ(r.status, 1) << truth;
        EXPECT_NE(r.err.find("--truth: expected a file outside the dataset folder ds"), std::string::npos)
            << r.err;
        EXPECT_FALSE(fs::exists(path("ds"))) << truth;
        EXPECT_FALSE(fs::exists(path("ds.tmp"))) << truth;
    }
}

TEST_F(SynthDataCli, BadEffectNameListsTheValidNames)
{
    const Result r = synth(tiny("junction-growht", "1", "ds"));
    EXPECT_EQ(r.status, 1);
    EXPECT_NE(r.err.find("--effect: expected one of none, junction-growth, breakaway-jump, hertz-contact, "
                         "sticking-creep, extra-string-damping, ambient-temperature, friction-law but got "
                         "\"junction-growht\""),
              std::string::npos)
        << r.err;
    EXPECT_FALSE(fs::exists(path("ds")));
}

TEST_F(SynthDataCli, BadValuesNameTheOptionAndWriteNothing)
{
    struct Case
    {
        std::vector<std::string> args;
        const char* message;
    };
    auto with = [](std::vector<std::string> more)
    {
        auto a = tiny("none", "1", "never");
        a.insert(a.end(), more.begin(), more.end());
        return a;
    };
    for (const Case& c :
         {Case{tiny("junction-growth:growth=5", "1", "never"), "--effect: expected growth in 0..1"},
          Case{tiny("junction-growth:speed=1", "1", "never"), "NAME one of growth, onsetTime"},
          Case{tiny("breakaway-jump:jumpCurve=violin", "1", "never"), "jumpCurve one of rod, bow, none"},
          Case{with({"--effect", "hertz-contact"}), "--effect: expected none alone"},
          Case{{"--effect", "hertz-contact", "--effect", "hertz-contact", "--scan", "guettler", "--seed", "1",
                "--out", "never"},
               "--effect: expected each effect once but got \"hertz-contact\" twice"},
          Case{tiny("none", "-1", "never"), "--seed: expected an integer in 0..18446744073709551615"},
          Case{with({"--scan", "raucous"}), "--scan: expected one of guettler, schelleng"},
          Case{with({"--channels", "some"}), "--channels: expected one of basic, all"},
          Case{with({"--grid", "301"}), "--grid: expected N or NxM"},
          Case{with({"--duration", "0.001"}), "--duration: expected at least 0.01 s"},
          Case{with({"--sample-rate", "44100.5"}), "--sample-rate"},
          Case{with({"--preset", "no-such-preset"}), "no-such-preset"},
          Case{with({"--generator", "independent", "--member", "-3"}),
               "--member: expected an integer in 0..1000000"},
          Case{tiny("friction-law:replacementLaw=classical", "1", "never", {"--generator", "independent"}),
               "independent generator: models the plastic and viscous thermal laws only, not \"classical\""}})
    {
        const Result r = synth(c.args);
        EXPECT_EQ(r.status, 1) << c.message << "\n" << r.err;
        EXPECT_NE(r.err.find(c.message), std::string::npos) << r.err;
        EXPECT_FALSE(fs::exists(path("never"))) << c.message;
        EXPECT_FALSE(fs::exists(path("never.tmp"))) << c.message;
    }
    fs::create_directories(path("full"));
    std::ofstream(path("full/keep.txt")) << "a user's file";
    const Result full = synth(tiny("none", "1", "full"));
    EXPECT_EQ(full.status, 1);
    EXPECT_NE(full.err.find("--out: expected a new or empty folder"), std::string::npos) << full.err;
    EXPECT_EQ(slurp(path("full/keep.txt")), "a user's file");
    fs::create_directories(path("empty"));
    EXPECT_EQ(synth(tiny("none", "1", "empty")).status, 0); // an empty folder is filled
    EXPECT_TRUE(fs::exists(path("empty/dataset.json")));
}

TEST_F(SynthDataCli, UsageErrorsExitWithTwo)
{
    EXPECT_EQ(synth({}).status, 2);
    EXPECT_EQ(synth({"--scan", "guettler", "--seed", "1", "--out", "x"}).status, 2);       // no --effect
    EXPECT_EQ(synth({"--effect", "none", "--seed", "1", "--out", "x"}).status, 2);         // no --scan
    EXPECT_EQ(synth({"--effect", "none", "--scan", "guettler", "--out", "x"}).status, 2);  // no --seed
    EXPECT_EQ(synth({"--effect", "none", "--scan", "guettler", "--seed", "1"}).status, 2); // no --out
    EXPECT_EQ(synth(tiny("none", "1", "x", {"--friction", "classical"})).status, 2);       // hides nothing
    EXPECT_EQ(synth(tiny("none", "1", "x", {"--bow-speed", "0.1"})).status, 2);            // schelleng only
    EXPECT_EQ(synth(tiny("none", "1", "x", {"--member", "3"})).status, 2); // the independent generator's
    EXPECT_FALSE(fs::exists(path("x")));
}

// [Galluzzo2017]'s first-slip analysis as a laboratory runs it (from the bridge force alone, the sensor's
// high-pass undone, the nominal force): junction growth makes the contact stronger after its hold.
TEST_F(SynthDataCli, FirstSlipFrictionRisesWithJunctionGrowth)
{
    ASSERT_EQ(synth(tiny("none", "1", "none")).status, 0);
    ASSERT_EQ(synth(tiny("junction-growth", "1", "aged")).status, 0);
    auto muStatic = [&](const std::string& folder)
    {
        const Dataset d = readDatasetDescription(path(folder));
        std::vector<double> mu;
        for (const auto& t : d.trials)
        {
            rosin::analysis::FirstSlipOptions o;
            o.sampleRate = d.sampleRate;
            o.beta = t.beta;
            o.bowForce = t.bowForce;
            o.periodSeconds = 1.0 / d.rig.string.fundamental();
            o.highPassCutoffHz = *d.sensor.highpassHz;
            const auto first =
                rosin::analysis::firstSlipFromBridgeForce(readTrialSignals(d, t).channel("bridgeForce"), o);
            mu.push_back(t.valid && first.found ? first.muStatic : NAN);
        }
        return mu;
    };
    const auto plain = muStatic("none"), aged = muStatic("aged");
    int compared = 0, higher = 0;
    double ratio = 0.0;
    for (std::size_t i = 0; i < plain.size(); ++i)
        if (std::isfinite(plain[i]) && std::isfinite(aged[i]))
        {
            ++compared;
            higher += aged[i] > plain[i];
            ratio += aged[i] / plain[i];
        }
    std::printf(
        "[figure] first-slip mu_s: %d trials compared, %d higher with junction growth, mean ratio %.3f\n",
        compared, higher, compared ? ratio / compared : 0.0);
    ASSERT_GE(compared, 4);
    EXPECT_EQ(higher, compared);
    EXPECT_GT(ratio / compared, 1.1);
}

} // namespace ROSIN_FILE_LOCAL
