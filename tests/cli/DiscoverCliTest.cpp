// `rosin discover` through the built binary on small datasets made in the test by `rosin synth-data` (8 x 8
// Guettler grids of 0.4 s trials at beta 0.0899, the workflow's specified test size); the only channel
// between generator and workflow is the dataset folder. For each of the six effects of the catalog, hidden
// alone, the effect is named first and at least half of the gap goes; two hidden effects are both named; a
// dataset with nothing hidden names nothing, also on data of the independent generator (its gap explained by
// calibration), whose hertz contact in a steady scan is named; a malformed dataset is refused with a message
// naming the file and field.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <ostream>

#include <nlohmann/json.hpp>

#include "cli/CliSupport.h"
#include "core/config/TempFiles.h"

#include "lab/discovery/EffectCatalog.h"
#include "lab/discovery/SimulationModel.h"

namespace ROSIN_FILE_LOCAL
{
namespace fs = std::filesystem;
using rosin::test::cli::Result;
using rosin::test::cli::slurp;

class DiscoverCli : public ::testing::Test
{
  protected:
    Result rosin(const std::vector<std::string>& args)
    {
        return rosin::test::cli::runRosin(dir.path(), args);
    }
    // A Guettler dataset at the workflow's specified test size with `effects` hidden (extra options after
    // them).
    void makeDataset(const std::vector<std::string>& effects, const std::string& seed, const std::string& out,
                     const std::vector<std::string>& extra = {"--beta", "0.0899"})
    {
        std::vector<std::string> args{"synth-data"};
        for (const auto& e : effects)
            args.insert(args.end(), {"--effect", e});
        args.insert(args.end(), {"--scan", "guettler", "--grid", "8", "--duration", "0.4", "--seed", seed,
                                 "--threads", "2", "--out", out});
        args.insert(args.end(), extra.begin(), extra.end());
        const Result r = rosin(args);
        ASSERT_EQ(r.status, 0) << r.err;
    }
    /// `extra`: e.g. {"--max-effects", "1"} where only the first step is asserted (the search then stops
    /// there: half the time of a run whose second step tries every candidate again).
    nlohmann::json discover(const std::string& dataset, const std::vector<std::string>& extra = {})
    {
        std::vector<std::string> args{"discover",        dataset,    "--json",
                                      dataset + ".json", "--report", dataset + "-report",
                                      "--threads",       "2"};
        args.insert(args.end(), extra.begin(), extra.end());
        const Result r = rosin(args);
        EXPECT_EQ(r.status, 0) << r.err;
        EXPECT_TRUE(fs::exists(path(dataset + "-report/report.md")));
        std::printf("[ figures  ] %s\n", r.out.c_str());
        return nlohmann::json::parse(slurp(path(dataset + ".json")));
    }
    std::string path(const std::string& name) const { return dir.path() + "/" + name; }

    rosin::test::TempDir dir;
};

// One hidden effect: named first, significant on the held-out half, and the gap at least halved; the search
// stops after the first step (--max-effects 1), which is all this asserts.
struct HiddenEffect
{
    std::string name, spec, seed;
    std::vector<std::string> extra{"--beta", "0.0899"};
    std::string parameter{}; ///< non-empty: its fitted value must lie within a factor 1.5 of the hidden one
    double hidden = 0.0;
};

// ctest lists a parameter by what is hidden, not by its bytes.
void PrintTo(const HiddenEffect& h, std::ostream* os)
{
    *os << h.spec;
}

// The loss factor of the cello D string's partial n with the extra-string-damping of `parameters`
// (lossScale, lossTerms) applied to the baseline: n = 1 where the transient and the pitch read the losses,
// n = 36 the middle of the harmonic tilt's band.
double lossAtPartial(const nlohmann::json& parameters, int n)
{
    using namespace rosin::discovery;
    const Effect& effect = *findEffect("extra-string-damping");
    const auto& choices = effect.parameters[1].choices;
    const std::string terms = parameters.value("lossTerms", std::string("all"));
    const double choice =
        static_cast<double>(std::find(choices.begin(), choices.end(), terms) - choices.begin());
    SimulationModel model;
    applyEffect(effect, {parameters["lossScale"].get<double>(), choice}, model);
    const auto cfg = voiceConfig(model);
    return cfg.lossScale * cfg.string.lossFactor(n, cfg.string.length, false);
}

class DiscoverHiddenEffect : public DiscoverCli, public ::testing::WithParamInterface<HiddenEffect>
{
};

TEST_P(DiscoverHiddenEffect, IsNamedFirstAndAtLeastHalvesTheGap)
{
    const HiddenEffect& h = GetParam();
    makeDataset({h.spec}, h.seed, "d", h.extra);
    const auto j = discover("d", {"--max-effects", "1"});
    EXPECT_EQ(j["maxEffects"], 1);
    EXPECT_EQ(j["status"], "effect-found");
    ASSERT_FALSE(j["steps"].empty());
    EXPECT_EQ(j["steps"][0]["effect"], h.name);
    EXPECT_GT(j["gapBefore"].get<double>(), 0.1);
    EXPECT_LE(j["gapAfter"].get<double>(), 0.5 * j["gapBefore"].get<double>());
    EXPECT_LT(j["steps"][0]["pValue"].get<double>(), j["steps"][0]["alpha"].get<double>());
    EXPECT_GE(j["steps"][0]["heldOutGain"].get<double>(), 0.2);
    EXPECT_GE(j["trialsSkipped"].get<int>(), 1);
    if (h.name == "extra-string-damping")
    {
        // A family: the fit may put the loss into the bending term alone (the tilt's band)
        // or the internal one alone (the low partials), and an 8 x 8 scan cannot always tell which (seen:
        // internal x 3.02 for all x 3, gap 0.226 -> 0); the signature is the loss where the features read it,
        // so the fitted loss must match the hidden one within 1.5x at the fundamental or in the tilt's band.
        const auto& fittedParameters = j["steps"][0]["parameters"];
        const nlohmann::json hiddenParameters = {{"lossScale", h.hidden}, {"lossTerms", "all"}};
        auto matches = [&](int n)
        {
            const double ratio = lossAtPartial(fittedParameters, n) / lossAtPartial(hiddenParameters, n);
            return ratio > 1.0 / 1.5 && ratio < 1.5;
        };
        EXPECT_TRUE(matches(1) || matches(36)) << fittedParameters.dump();
    }
    else if (!h.parameter.empty())
    {
        const double fitted = j["steps"][0]["parameters"][h.parameter].get<double>();
        EXPECT_GT(fitted, h.hidden / 1.5) << h.parameter;
        EXPECT_LT(fitted, h.hidden * 1.5) << h.parameter;
    }
}

// String losses show in the corners of Helmholtz motion (harmonicTilt), so their dataset scans where the
// string speaks, as a laboratory studying damping would: forces 0.2-1.2 N, accelerations 0.1-1.2 m/s^2, two
// bow positions. Over the full grid most cells never reach Helmholtz motion in 0.4 s. (With the two-sided
// heat balance the plastic law's window lies lower: 0.4-2.4 N gave 15 % Helmholtz cells and p = 0.0027,
// 0.2-1.2 N gives 31 % and p = 5e-5, gain +64 %.)
INSTANTIATE_TEST_SUITE_P(EveryEffect, DiscoverHiddenEffect,
                         ::testing::Values(HiddenEffect{"junction-growth",
                                                        "junction-growth:growth=0.3,onsetTime=0.003",
                                                        "3",
                                                        {"--beta", "0.0899"},
                                                        "growth",
                                                        0.3},
                                           HiddenEffect{"hertz-contact", "hertz-contact", "8"},
                                           HiddenEffect{"sticking-creep",
                                                        "sticking-creep:creepResistance=60",
                                                        "5",
                                                        {"--beta", "0.0899"},
                                                        "creepResistance",
                                                        60.0},
                                           HiddenEffect{"extra-string-damping",
                                                        "extra-string-damping:lossScale=3",
                                                        "7",
                                                        {"--beta", "0.0899,0.1428", "--force-range",
                                                         "0.2:1.2", "--acceleration-range", "0.1:1.2"},
                                                        "lossScale",
                                                        3.0},
                                           HiddenEffect{"ambient-temperature",
                                                        "ambient-temperature:ambientOffset=12",
                                                        "9",
                                                        {"--beta", "0.0899"},
                                                        "ambientOffset",
                                                        12.0}),
                         [](const auto& info)
                         {
                             std::string name = info.param.name;
                             name.erase(std::remove(name.begin(), name.end(), '-'), name.end());
                             return name;
                         });

// Since the calibration, a larger contact (radius at its prior's top, x1.15) mimics most of the modified
// law's cold breakaway on this 8 x 8 set (gap 1.67 -> 0.62), and the paired test leaves breakaway-jump, the
// best candidate (held-out gain +41 %, every other one below +7 %), short of its Bonferroni bar (p 0.01
// against 0.00083, cross-fitted). Its signature names it: z +6.3 against a threshold of 4.
TEST_F(DiscoverCli, BreakawayJumpShortOfThePairedTestsBarIsNamedByItsSignature)
{
    makeDataset({"breakaway-jump:jumpCurve=rod"}, "6", "jump");
    const auto j = discover("jump");
    ASSERT_EQ(j["status"], "effect-found");
    ASSERT_FALSE(j["steps"].empty());
    const auto& step = j["steps"][0];
    EXPECT_EQ(step["effect"], "breakaway-jump");
    const auto& tried = step["tried"];
    const auto chosen = std::find_if(tried.begin(), tried.end(),
                                     [](const auto& t) { return t["effect"] == "breakaway-jump"; });
    ASSERT_NE(chosen, tried.end());
    EXPECT_TRUE((*chosen)["significantBySignature"].get<bool>()) << chosen->dump();
    EXPECT_GT((*chosen)["heldOutGain"].get<double>(), 0.3);
    EXPECT_LT(j["calibration"]["gapAfterCalibration"].get<double>(), 0.5 * j["gapBefore"].get<double>());
    EXPECT_LT(j["gapAfter"].get<double>(), 0.5 * j["gapBefore"].get<double>());
}

// Two effects hidden together: both are the explanation the search finds, one adopted first and the other
// adopted after it or, where its paired test lands at its Bonferroni bar, the best remaining candidate by a
// wide margin. Measured on the three SIMD paths: x86-64-v4 and v3 adopt both; on the baseline path creep is
// adopted (+47 %, p 5e-5) and hertz-contact then gains +36.5 % with p = 0.0021 against a bar of 0.002 (every
// other candidate +0.0 % or less): whether it is "named" there is decided by a hair, so the test asserts the
// ranking, which is decided with margin, and not the bar.
TEST_F(DiscoverCli, TwoHiddenEffectsAreTheTwoExplanations)
{
    makeDataset({"sticking-creep:creepResistance=60", "hertz-contact"}, "10", "two");
    const auto j = discover("two", {"--max-effects", "2"}); // a third step would fit the other four again
    EXPECT_EQ(j["status"], "effect-found");
    ASSERT_GE(j["steps"].size(), 1u);
    std::vector<std::string> found;
    for (const auto& step : j["steps"])
        found.push_back(step["effect"]);
    if (found.size() < 2 && j.contains("notAdopted"))
    {
        const nlohmann::json* best = nullptr;
        for (const auto& t : j["notAdopted"])
            if (!best || t["heldOutGain"].get<double>() > (*best)["heldOutGain"].get<double>())
                best = &t;
        ASSERT_NE(best, nullptr);
        EXPECT_GT((*best)["heldOutGain"].get<double>(), 0.2);
        EXPECT_LT((*best)["pValue"].get<double>(), 0.01);
        for (const auto& t : j["notAdopted"])
            if (&t != best)
                EXPECT_LT(t["heldOutGain"].get<double>(), 0.1) << t["effect"];
        found.push_back((*best)["effect"]);
    }
    EXPECT_NE(std::find(found.begin(), found.end(), "sticking-creep"), found.end());
    EXPECT_NE(std::find(found.begin(), found.end(), "hertz-contact"), found.end());
    EXPECT_LT(j["gapAfter"].get<double>(), 0.75 * j["gapBefore"].get<double>()); // 0.57 with one adopted
}

// A law of the source texts in the baseline's place, hidden by the independent generator, which simulates
// its viscous law its own way (its plastic calibration read as a viscosity): the friction-law candidate
// names the law first, the gap beyond the model-form tolerance at least halved.
TEST_F(DiscoverCli, AViscousRosinIsNamedAsTheLawItIs)
{
    makeDataset({"friction-law:replacementLaw=viscous"}, "12", "viscous",
                {"--beta", "0.0899", "--generator", "independent"});
    const auto j = discover("viscous", {"--max-effects", "1"});
    EXPECT_EQ(j["status"], "effect-found");
    ASSERT_FALSE(j["steps"].empty());
    EXPECT_EQ(j["steps"][0]["effect"], "friction-law");
    EXPECT_EQ(j["steps"][0]["parameters"]["replacementLaw"], "viscous");
    EXPECT_LT(j["steps"][0]["pValue"].get<double>(), j["steps"][0]["alpha"].get<double>());
    EXPECT_GE(j["steps"][0]["heldOutGain"].get<double>(), 0.2);
    const auto& beyond = j["gapBeyondModelForm"];
    EXPECT_LE(beyond["after"].get<double>(), 0.5 * beyond["calibrated"].get<double>()) << beyond.dump();
}

// The other way round: plastic-law data diagnosed against the classical curve as the baseline. The data's
// own law is the candidate's answer, and a law the model already has is the candidate's null.
TEST_F(DiscoverCli, PlasticDataAgainstAClassicalBaselineNamesThePlasticLaw)
{
    makeDataset({"none"}, "4", "plastic");
    const auto j = discover("plastic", {"--max-effects", "1", "--baseline", "classical"});
    EXPECT_EQ(j["status"], "effect-found");
    ASSERT_FALSE(j["steps"].empty());
    EXPECT_EQ(j["steps"][0]["effect"], "friction-law");
    EXPECT_EQ(j["steps"][0]["parameters"]["replacementLaw"], "plastic");
    EXPECT_LE(j["gapAfter"].get<double>(), 0.5 * j["gapBefore"].get<double>());
}

TEST_F(DiscoverCli, NothingHiddenNamesNothing)
{
    makeDataset({"none"}, "4", "none");
    const auto j = discover("none");
    EXPECT_EQ(j["status"], "no-significant-discrepancy");
    EXPECT_TRUE(j["steps"].empty());
    EXPECT_LT(j["gapAfter"].get<double>(), 0.3); // after calibration: within the measurement's scatter
    EXPECT_GT(j["remainingGap"]["pValue"].get<double>(), 0.01);
}

// Data that Rosin's stepper did not make: the independent generator's waveguide string,
// heat balance and measurement chain, with the rig's constants off nominal within a lab's tolerances and an
// unstated low-pass, gain error and start delay. The nominal baseline is far off (gap 1.59 measured), the
// calibration within the stated tolerances explains it (0.26), and no effect is named (every candidate's
// held-out gain negative; the remaining gap's p 1 with the verdict's model-form tolerance, 0.022-0.06
// without it, against the verdict's 0.01).
TEST_F(DiscoverCli, ForeignDataWithNothingHiddenIsExplainedByCalibration)
{
    makeDataset({"none"}, "4", "foreign", {"--beta", "0.0899", "--generator", "independent"});
    const auto j = discover("foreign");
    EXPECT_EQ(j["status"], "no-significant-discrepancy");
    EXPECT_TRUE(j["steps"].empty());
    EXPECT_GT(j["gapBefore"].get<double>(), 0.7);
    EXPECT_LT(j["calibration"]["gapAfterCalibration"].get<double>(), 0.3 * j["gapBefore"].get<double>());
    EXPECT_GT(j["remainingGap"]["pValue"].get<double>(), 0.02);
}

// Calibration recovers what a lab states wrongly: the independent generator's Schelleng scan (12 x 12, seed
// 31) drew the string's tension 1.17 % above the stated one (the truth file says so, the dataset does not),
// and the pitch of its Helmholtz trials pins it. The calibrated tension must lie within 0.5 % of the drawn
// one (1.01 measured) and the calibration must remove at least 20 % of the gap (1.25 -> 0.53 measured; the
// gap reported compares pitch and tilt where both sides show Helmholtz motion, the calibration fits them
// where the measurement does, so it does not minimise this number). The descent that fitted the contact
// radius first, which flattens the pitch a little as a lower tension does, stayed at the nominal tension
// there (gap 1.08 -> 1.10). Nothing is hidden, so nothing may be named and the verdict must be clean: the
// remaining gap's p was 0.51 on x86-64-v4 and 1 on x86-64-v3 and the baseline path (with
// the steady level's model-form tolerance measured on six other seeds; before it, 0.0075 on x86-64-v4,
// where the calibration takes another of two near-equal optima), against the verdict's 0.01.
TEST_F(DiscoverCli, CalibrationRecoversTheTensionOfAForeignString)
{
    const Result made = rosin({"synth-data", "--generator", "independent", "--effect", "none", "--scan",
                               "schelleng", "--grid", "12", "--duration", "0.4", "--seed", "31", "--threads",
                               "2", "--out", "steady", "--truth", "steady-truth.json"});
    ASSERT_EQ(made.status, 0) << made.err;
    const auto j = discover("steady");
    const double drawn =
        nlohmann::json::parse(slurp(path("steady-truth.json")))["independent"]["nuisance"]["tension"];
    ASSERT_GT(std::abs(drawn - 1.0), 0.01) << "the seed no longer draws a tension worth calibrating";
    double calibrated = 0.0;
    for (const auto& p : j["calibration"]["parameters"])
        if (p["name"] == "tension")
            calibrated = p["baseline"];
    EXPECT_NEAR(calibrated / drawn, 1.0, 0.005) << "calibrated " << calibrated << ", drawn " << drawn;
    EXPECT_LT(j["calibration"]["gapAfterCalibration"].get<double>(), 0.8 * j["gapBefore"].get<double>());
    EXPECT_TRUE(j["steps"].empty()) << j["steps"].dump();
    EXPECT_EQ(j["status"], "no-significant-discrepancy") << j["remainingGap"].dump();
    const double p = j["remainingGap"]["pValue"].get<double>();
    RecordProperty("remainingGapP", std::to_string(p));
    EXPECT_GT(p, 0.05) << j["remainingGap"].dump();
}

// Hertz contact in another string model's steady bowing: the independent generator's own form
// (area ~ F^0.634 about 0.68 N) in a 12 x 12 Schelleng scan. On the held-out half alone the catalog's
// hertz contact came within a hair of the bar (+26.5 %, p 0.0028 against 0.0017 on x86-64-v4; p 1e-4 on
// x86-64-v3), so the candidate is cross-fitted: fitted on each half and scored on the other, +32 %,
// p 5e-5 over both halves against 0.00083. The gap falls 1.73 -> 1.07 (the tilt's model-form misfit
// stays), not by half: asserted as a fall of at least a quarter; beyond the model-form tolerance it halves.
TEST_F(DiscoverCli, ForeignHertzContactInASteadyScanIsNamedFirst)
{
    const Result made =
        rosin({"synth-data", "--generator", "independent", "--effect", "hertz-contact", "--scan", "schelleng",
               "--grid", "12", "--duration", "0.4", "--seed", "31", "--threads", "2", "--out", "hertz"});
    ASSERT_EQ(made.status, 0) << made.err;
    const auto j = discover("hertz", {"--max-effects", "1"});
    EXPECT_EQ(j["status"], "effect-found");
    ASSERT_FALSE(j["steps"].empty());
    const auto& first = j["steps"][0];
    EXPECT_EQ(first["effect"], "hertz-contact");
    EXPECT_LT(first["pValue"].get<double>(), 0.5 * first["alpha"].get<double>());
    EXPECT_GE(first["heldOutGain"].get<double>(), 0.2);
    RecordProperty("crossFitted", first["crossFitted"].get<bool>() ? "yes" : "no");
    EXPECT_LT(j["gapAfter"].get<double>(), 0.75 * j["gapBefore"].get<double>());
    // Beyond what two string models with the same physics leave between them, the effect explains most of
    // the gap (1.11 -> 0.37 on x86-64-v4).
    const auto& beyond = j["gapBeyondModelForm"];
    EXPECT_LT(beyond["after"].get<double>(), 0.5 * beyond["before"].get<double>()) << beyond.dump();
    EXPECT_LE(beyond["before"].get<double>(), j["gapBefore"].get<double>());
}

TEST_F(DiscoverCli, MalformedDatasetIsRefusedWithFileAndField)
{
    fs::create_directories(path("bad/trials"));
    nlohmann::json d = {
        {"format", "rosin-measurements/1"},
        {"channels", {{{"name", "bridgeForce"}, {"unit", "N"}}}},
        {"rig", {{"string", {{"tension", 111.0}, {"massPerLength", 0.0027}, {"length", 0.69}}}}},
        {"trials", nlohmann::json::array()}};
    std::ofstream(path("bad/dataset.json")) << d.dump(1);
    const Result r = rosin({"discover", "bad", "--json", "bad.json", "--report", "bad-report"});
    EXPECT_EQ(r.status, 1);
    EXPECT_NE(r.err.find("dataset.json"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("sampleRate"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(path("bad.json")));
}

TEST_F(DiscoverCli, RecordedBowedPointAddsSlipFractionAndLoopArea)
{
    makeDataset({"none"}, "4", "all", {"--beta", "0.0899", "--channels", "all"});
    const auto j = discover("all");
    EXPECT_EQ(j["status"], "no-significant-discrepancy");
    for (const auto& f : j["features"])
        if (f["name"] == "slipFraction" || f["name"] == "loopArea" || f["name"] == "regime")
        {
            EXPECT_GE(f["trials"].get<int>(), 3) << f["name"];
            EXPECT_LT(f["gapBefore"].get<double>(), 0.5) << f["name"];
        }
}

TEST_F(DiscoverCli, TruncatedTrialFileIsRefusedWithItsName)
{
    const Result made = rosin({"synth-data", "--effect", "none", "--scan", "guettler", "--grid", "3",
                               "--duration", "0.1", "--seed", "1", "--threads", "2", "--out", "cut"});
    ASSERT_EQ(made.status, 0) << made.err;
    const auto d = nlohmann::json::parse(slurp(path("cut/dataset.json")));
    std::string file;
    for (const auto& t : d["trials"])
        if (t.value("valid", true))
            file = t["file"];
    ASSERT_FALSE(file.empty());
    fs::resize_file(path("cut/" + file), fs::file_size(path("cut/" + file)) / 2);
    const Result r = rosin({"discover", "cut", "--json", "cut.json", "--report", "cut-report"});
    EXPECT_EQ(r.status, 1) << r.err;
    EXPECT_NE(r.err.find(file), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(path("cut.json")));
}

TEST_F(DiscoverCli, MaxEffectsOutsideOneToThreeIsRefused)
{
    for (const char* n : {"0", "4", "1.5"})
    {
        const Result r = rosin({"discover", "any", "--json", "x.json", "--report", "x", "--max-effects", n});
        EXPECT_NE(r.status, 0) << n;
        EXPECT_NE(r.err.find("--max-effects"), std::string::npos) << r.err;
    }
}

TEST_F(DiscoverCli, MissingDatasetArgumentIsAUsageError)
{
    const Result r = rosin({"discover", "--json", "x.json", "--report", "x"});
    EXPECT_EQ(r.status, 2) << r.err;
}

} // namespace ROSIN_FILE_LOCAL
