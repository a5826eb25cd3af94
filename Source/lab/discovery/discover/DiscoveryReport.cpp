#include "lab/discovery/discover/DiscoveryReport.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "lab/discovery/discover/ModelFormTolerance.h"

namespace rosin::discovery
{

namespace
{
constexpr const char* kGapDefinition =
    "per feature: sqrt(max(0, mean rho(z) - E[rho])), rho(z) = 4 ln(1 + z^2 / 4) (Student-t, 4 degrees "
    "of freedom), E[rho] = 0.775 its mean for a right model, z = (measured - simulated) / scatter of the "
    "measurement (+-3 when only one side shows the feature); overall: mean over features present in >= 3 "
    "trials; 0 = agreement within the measurement's scatter";

nlohmann::json parameters(const EffectScore& s)
{
    nlohmann::json p = nlohmann::json::object();
    for (std::size_t j = 0; j < s.effect->parameters.size(); ++j)
    {
        const auto& param = s.effect->parameters[j];
        if (!param.choices.empty())
            p[param.name] = param.choices[static_cast<std::size_t>(s.values[j])];
        else
            p[param.name] = s.values[j];
    }
    return p;
}

/// What a candidate whose fit stayed at its null scored is the nuisance refit's gain, not its own.
std::string nullNote(const EffectScore& s)
{
    return s.leftNull ? "" : ", its fit never left the null: no evidence for or against it";
}

nlohmann::json tried(const std::vector<EffectScore>& scores)
{
    nlohmann::json a = nlohmann::json::array();
    for (const auto& s : scores)
        a.push_back({{"effect", s.effect->name},
                     {"parameters", parameters(s)},
                     {"heldOutGain", s.heldOutGain},
                     {"pValue", s.pValue},
                     {"crossFitted", s.crossFitted},
                     {"significant", s.significant},
                     {"significantBySignature", s.bySignature},
                     {"leftNull", s.leftNull},
                     {"signatureZ", s.signature.z},
                     {"signatureBeyondTrends", s.signature.beyondTrends},
                     {"evaluations", s.evaluations}});
    return a;
}

nlohmann::json calibrationJson(const Discovery& d)
{
    nlohmann::json parameters = nlohmann::json::array();
    const auto& ps = nuisanceParameters();
    for (std::size_t j = 0; j < ps.size(); ++j)
    {
        const auto& p = ps[j];
        const bool active = std::find(d.calibration.active.begin(), d.calibration.active.end(), j) !=
                            d.calibration.active.end();
        parameters.push_back({{"name", p.prior.name},
                              {"meaning", p.prior.meaning},
                              {"prior", {p.prior.min, p.prior.max}},
                              {"nominal", p.nominal()},
                              {"baseline", d.calibration.values.*p.value},
                              {"final", d.finalNuisance.*p.value},
                              {"objectiveSwing", d.calibration.swing[j]},
                              {"screeningSwing", d.calibration.screening[j]},
                              {"refittedWithEffects", active}});
    }
    return {{"parameters", parameters},
            {"trainingObjectiveBefore", d.calibration.objectiveBefore},
            {"trainingObjectiveAfter", d.calibration.objectiveAfter},
            {"gapAfterCalibration", d.gapCalibrated.overall},
            {"evaluations", d.calibration.evaluations}};
}

std::string number(double v, const char* format = "%.3g")
{
    char text[64];
    std::snprintf(text, sizeof(text), format, v);
    return text;
}

/// The signature test's figures (SignatureTest.h), or nothing for a fit at its null.
std::string signatureNote(const EffectScore& s)
{
    if (!s.leftNull)
        return "";
    return ", signature z " + number(s.signature.z, "%+.1f") + " with " +
           number(100.0 * s.signature.beyondTrends, "%.0f") + " % beyond trends";
}
} // namespace

nlohmann::json discoveryJson(const Discovery& d, const Dataset& dataset)
{
    nlohmann::json j;
    j["dataset"] = d.datasetFolder;
    j["trialsUsed"] = d.trialsUsed;
    j["trialsSkipped"] = d.trialsSkipped;
    j["maxEffects"] = d.maxEffects;
    j["baseline"] = {{"friction", d.baselineFriction},
                     {"contact", "galluzzo"},
                     {"body", dataset.rig.body.value_or("cello")},
                     {"string", "rig.string of dataset.json"},
                     {"sensorHighpassHz", dataset.sensor.highpassHz.value_or(0.0)},
                     {"sampleRate", dataset.sampleRate}};
    j["gapDefinition"] = kGapDefinition;
    j["gapBefore"] = d.gapBefore.overall;
    j["calibration"] = calibrationJson(d);
    j["features"] = nlohmann::json::array();
    for (std::size_t f = 0; f < kFeatureCount; ++f)
        j["features"].push_back({{"name", featureName(f)},
                                 {"unit", featureUnit(f)},
                                 {"scatter", d.scatter.sigma[f]},
                                 {"scatterMethod", d.scatter.method[f]},
                                 {"trials", d.gapBefore.count[f]},
                                 {"gapBefore", d.gapBefore.gap[f]},
                                 {"gapCalibrated", d.gapCalibrated.gap[f]},
                                 {"gapAfter", d.gapAfter.gap[f]},
                                 {"where", d.whereBefore[f]},
                                 {"whereAfter", d.whereAfter[f]}});
    j["steps"] = nlohmann::json::array();
    for (std::size_t k = 0; k < d.search.steps.size(); ++k)
    {
        const auto& s = d.search.steps[k];
        j["steps"].push_back({{"effect", s.chosen.effect->name},
                              {"parameters", parameters(s.chosen)},
                              {"gapAfter", d.stepGaps[k].overall},
                              {"heldOutGain", s.chosen.heldOutGain},
                              {"pValue", s.chosen.pValue},
                              {"crossFitted", s.chosen.crossFitted},
                              {"alpha", s.alpha},
                              {"evidence", describeEvidence(s.chosen, s.alpha)},
                              {"tried", tried(s.tried)}});
        if (s.rival)
            j["steps"].back()["rival"] = {{"effect", s.tried[s.rival->index].effect->name},
                                          {"heldOutGain", s.tried[s.rival->index].heldOutGain},
                                          {"pValue", s.rival->test.pValue},
                                          {"decided", s.rival->decided()},
                                          {"evidence", describeRival(s)}};
    }
    if (!d.search.lastTried.empty())
        j["notAdopted"] = tried(d.search.lastTried);
    j["gapAfter"] = d.gapAfter.overall;
    j["gapBeyondModelForm"] = {{"before", d.beyondToleranceBefore.overall},
                               {"calibrated", d.beyondToleranceCalibrated.overall},
                               {"after", d.beyondToleranceAfter.overall}};
    j["remainingGap"] = {
        {"pValue", d.remaining.pValue},
        {"feature", d.remaining.feature < kFeatureCount ? featureName(d.remaining.feature) : ""},
        {"test", "chi-square of sum min(z^2, 9) per feature, Bonferroni over features, sigma widened by the "
                 "model-form tolerance"},
        {"modelFormTolerance", []
         {
             nlohmann::json t = nlohmann::json::object();
             for (std::size_t f = 0; f < kFeatureCount; ++f)
                 if (modelFormTolerance()[f] > 0.0)
                     t[featureName(f)] = modelFormTolerance()[f];
             return t;
         }()}};
    j["status"] = d.status;
    j["verdict"] = d.status;
    j["split"] = {{"training", d.training.size()}, {"heldOut", d.heldOut.size()}, {"rule", "checkerboard"}};
    j["seconds"] = d.seconds;
    return j;
}

nlohmann::json discoveryMaps(const Discovery& d, const Dataset& dataset)
{
    nlohmann::json trials = nlohmann::json::array();
    auto values = [](const TrialFeatures& t)
    {
        nlohmann::json o = nlohmann::json::object();
        for (std::size_t f = 0; f < kFeatureCount; ++f)
            o[featureName(f)] = t[f] ? nlohmann::json(*t[f]) : nlohmann::json(nullptr);
        return o;
    };
    // The unit of each z: the measurement's scatter with the model's sensitivity (null: not compared).
    auto sigmas = [&](std::size_t t)
    {
        TrialFeatures s;
        for (std::size_t f = 0; f < kFeatureCount; ++f)
            if (const double sigma = d.scatter.trialSigma(t, f); !std::isnan(sigma))
                s[f] = sigma;
        return values(s);
    };
    for (const auto& cell : d.grid.cells)
        for (std::size_t t : cell.trials)
            trials.push_back({{"id", dataset.trials[t].id},
                              {"beta", d.grid.betas[cell.beta]},
                              {"force", d.grid.forces[cell.force]},
                              {"motion", d.grid.motion.empty() ? 0.0 : d.grid.motion[cell.motion]},
                              {"measured", values(d.measured[t])},
                              {"baseline", values(d.baseline[t])},
                              {"calibrated", values(d.calibrated[t])},
                              {"final", values(d.final[t])},
                              {"sigma", sigmas(t)}});
    // Maps are drawn for every feature that disagrees before any effect (whatever the verdict: a failure
    // needs its picture most) and for every feature an adopted effect changed.
    constexpr double kMappedGap = 0.2;
    nlohmann::json changed = nlohmann::json::array(), disagreeing = nlohmann::json::array();
    nlohmann::json units = nlohmann::json::object();
    for (std::size_t f = 0; f < kFeatureCount; ++f)
    {
        units[featureName(f)] = featureUnit(f);
        if (d.gapBefore.count[f] < kMinTrialsForGap)
            continue;
        if (std::abs(d.gapBefore.gap[f] - d.gapAfter.gap[f]) > kMappedGap)
            changed.push_back(featureName(f));
        if (d.gapBefore.gap[f] > kMappedGap)
            disagreeing.push_back(featureName(f));
    }
    return {
        {"motionAxis", d.grid.kind == ScanKind::Schelleng ? "bow speed (m/s)" : "bow acceleration (m/s^2)"},
        {"changed", changed},
        {"disagreeing", disagreeing},
        {"units", units},
        {"adoptedEffects", d.stepGaps.size()},
        {"trials", trials}};
}

std::string discoveryMarkdown(const Discovery& d, const Dataset& dataset,
                              const std::vector<std::string>& figures)
{
    std::string m = "# rosin discover: " + d.datasetFolder + "\n\n";
    m += d.grid.summary() + ". " + std::to_string(d.trialsUsed) + " trials used, " +
         std::to_string(d.trialsSkipped) +
         " skipped (marked `valid: false`). Baseline: the rig's string on the " +
         dataset.rig.body.value_or("cello") + " body, " + d.baselineFriction +
         " friction, galluzzo contact, simulated with the nominal settings through the dataset's sensor "
         "high-pass (" +
         number(dataset.sensor.highpassHz.value_or(0.0)) + " Hz) at " + std::to_string(dataset.sampleRate) +
         " Hz.\n\n";
    m += "## Verdict: " + d.status + "\n\n";
    m += "Overall gap " + number(d.gapBefore.overall) + " before, " + number(d.gapCalibrated.overall) +
         " after calibration, " + number(d.gapAfter.overall) + " after (" + std::string(kGapDefinition) +
         "). Beyond the model-form tolerance (the scatter widened by how far two string models with the same "
         "physics differ, the verdict's units): " +
         number(d.beyondToleranceBefore.overall) + " before, " + number(d.beyondToleranceCalibrated.overall) +
         " after calibration, " + number(d.beyondToleranceAfter.overall) + " after.\n\n";
    m += "## Calibration\n\nWhat a laboratory knows only to a tolerance, fitted on the training half within "
         "its prior before any effect was tried (training objective " +
         number(d.calibration.objectiveBefore) + " -> " + number(d.calibration.objectiveAfter) + ", " +
         std::to_string(d.calibration.evaluations) +
         " simulations): " + describeNuisance(d.calibration.values) +
         ". With the adopted effects: " + describeNuisance(d.finalNuisance) + ".\n\n";
    if (d.search.steps.empty() && d.status == "no-significant-discrepancy" &&
        d.gapCalibrated.overall < d.gapBefore.overall)
        m += "The calibration alone explains the data: what remains is within the measurement's scatter.\n\n";
    if (d.search.steps.empty())
        m += "No effect of the catalog reduced the held-out gap significantly (paired sign-flip test at 1 % "
             "with a Bonferroni correction over the candidates, and a held-out gain of at least 20 %); no "
             "effect is named.\n\n";
    if (d.status == "effect-found" && d.remaining.pValue < kSignificanceLevel)
        m += "A significant gap remains after the adopted effects (" +
             std::string(featureName(d.remaining.feature)) +
             ": chi-square test p = " + number(d.remaining.pValue) +
             "): what is left is not explained by the catalog.\n\n";
    if (d.status == "unexplained")
        m += "Yet the model disagrees with the measurement by more than its scatter explains (" +
             std::string(featureName(d.remaining.feature)) +
             ": chi-square test p = " + number(d.remaining.pValue) +
             "): the missing physics is outside the catalog, or several effects act together that no "
             "single one explains alone.\n\n";
    m += "## What disagrees, and where\n\n| feature | scatter (method) | trials | gap before | calibrated | "
         "gap after | largest before |\n|---|---|---|---|---|---|---|\n";
    for (std::size_t f = 0; f < kFeatureCount; ++f)
        m += std::string("| ") + featureName(f) + " | " +
             (isCategorical(f)
                  ? "mismatch rate " + number(d.scatter.sigma[f]) + " (" + d.scatter.method[f] + ")"
                  : number(d.scatter.sigma[f]) + " " + featureUnit(f) + " (" + d.scatter.method[f] + ")") +
             " | " + std::to_string(d.gapBefore.count[f]) + " | " + number(d.gapBefore.gap[f]) + " | " +
             number(d.gapCalibrated.gap[f]) + " | " + number(d.gapAfter.gap[f]) + " | " + d.whereBefore[f] +
             " |\n";
    m += "\n";
    for (std::size_t k = 0; k < d.search.steps.size(); ++k)
    {
        const auto& s = d.search.steps[k];
        m += "## Step " + std::to_string(k + 1) + ": " + s.chosen.effect->name + "\n\n";
        m += s.chosen.effect->summary + " (" + s.chosen.effect->source +
             "). Fitted: " + describeEffect(*s.chosen.effect, s.chosen.values) +
             ". Gap after this step: " + number(d.stepGaps[k].overall) +
             ".\n\nWhy: " + describeEvidence(s.chosen, s.alpha) + ".\n\n";
        if (s.rival)
            m += "Against the " + describeRival(s) + ".\n\n";
        m += "Candidates (held-out gain, p):";
        for (const auto& t : s.tried)
            m += " " + t.effect->name + " " + number(100.0 * t.heldOutGain, "%.0f") + " % (" +
                 number(t.pValue, "%.2g") + (t.crossFitted ? ", cross-fitted" : "") + signatureNote(t) +
                 nullNote(t) + ");";
        m += "\n\n";
    }
    if (!d.search.lastTried.empty())
    {
        m += "## Not adopted\n\nThe last search step found nothing significant (threshold p < " +
             number(kHalfDecides * d.search.lastAlpha, "%.2g") +
             " on the held-out half or, cross-fitted, over both halves; gain >= 20 %):";
        for (const auto& t : d.search.lastTried)
            m += " " + t.effect->name + " " + number(100.0 * t.heldOutGain, "%.0f") +
                 " % (p = " + number(t.pValue, "%.2g") + (t.crossFitted ? ", cross-fitted" : "") +
                 signatureNote(t) + nullNote(t) + ");";
        m += "\n\n";
    }
    m += "## Figures\n\n";
    const auto maps = discoveryMaps(d, dataset);
    const bool anythingToMap = !maps["disagreeing"].empty() || !maps["changed"].empty();
    if (figures.empty())
        m += anythingToMap ? "No figures were made (the figure script or matplotlib was not available).\n"
                           : "No feature disagrees beyond its scatter, so there is nothing to map.\n";
    for (const auto& f : figures)
        m += "![" + f + "](" + f + ")\n\n";
    m += "\nMethod: training and held-out halves are a checkerboard over the grid (" +
         std::to_string(d.training.size()) + " / " + std::to_string(d.heldOut.size()) +
         " trials); each effect's parameters are fitted on the training half, the gain is measured on the "
         "held-out half; a candidate close to significance there (p < 0.05, gain >= 10 %) is cross-fitted: "
         "also fitted on the held-out half and scored on the training half, the test taken over both (the "
         "two routes share the 1 % level). Time: " +
         number(d.seconds, "%.1f") + " s.\n";
    return m;
}

} // namespace rosin::discovery
