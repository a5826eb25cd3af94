#include "cli/SynthDataCommand.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <optional>

#include "cli/CommandLine.h"
#include "cli/HelpPage.h"
#include "cli/SynthDataOptions.h"
#include "core/config/AtomicFile.h"
#include "core/config/ConfigError.h"
#include "core/gesture/GestureLimits.h"
#include "lab/discovery/DatasetReader.h"
#include "lab/discovery/DatasetWriter.h"
#include "lab/discovery/independent/GeneratorMember.h"
#include "lab/discovery/independent/IndependentRun.h"
#include "lab/discovery/io/TrialSignals.h"
#include "lab/discovery/synth/SynthRun.h"
#include "lab/discovery/synth/SynthTruth.h"
#include "lab/scan/StopSignal.h"

namespace rosin::cli
{

namespace fs = std::filesystem;
using config::ConfigError;

namespace
{
// Ctrl-C or SIGTERM during the run: the partial dataset is removed and the status is 128 + signal.
struct Stopped
{
};

struct OutputPaths
{
    fs::path out;                  ///< the dataset folder, as given
    fs::path partial;              ///< DIR.tmp, where the dataset is built
    std::optional<fs::path> truth; ///< --truth, as given
};

fs::path canonical(const fs::path& p)
{
    fs::path c = fs::weakly_canonical(fs::absolute(p));
    return c.filename().empty() ? c.parent_path() : c;
}

bool inside(const fs::path& file, const fs::path& folder)
{
    // Component by component, so "ds2/x" is not inside "ds".
    return std::mismatch(folder.begin(), folder.end(), file.begin(), file.end()).first == folder.end();
}

// Everything about the paths is checked before the first trial is simulated.
OutputPaths checkPaths(const SynthDataCommandLine& c)
{
    OutputPaths p{c.out, {}, std::nullopt};
    const fs::path folder = canonical(c.out);
    std::error_code ec;
    if (fs::exists(folder, ec) && (!fs::is_directory(folder, ec) || !fs::is_empty(folder, ec)))
        throw ConfigError(
            "--out", "", "a new or empty folder (a dataset is written whole, never into an existing one)",
            "\"" + c.out + "\", which " + (fs::is_directory(folder, ec) ? "is not empty" : "is a file"));
    p.partial = folder;
    p.partial += ".tmp";
    if (fs::exists(p.partial, ec))
        throw ConfigError("--out", "",
                          "no leftover partial dataset " + p.partial.string() +
                              " (remove it: a killed run left it)",
                          "\"" + c.out + "\"");
    if (!c.truth)
        return p;
    const fs::path truth = canonical(*c.truth);
    if (inside(truth, folder) || inside(truth, p.partial))
        throw ConfigError("--truth", "",
                          "a file outside the dataset folder " + c.out +
                              " (a dataset must not hold what it hides)",
                          "\"" + *c.truth + "\"");
    if (fs::is_directory(truth, ec))
        throw ConfigError("--truth", "", "a file name, not a folder", "\"" + *c.truth + "\"");
    if (!fs::is_directory(truth.parent_path(), ec))
        throw ConfigError("--truth", "", "a file in an existing folder", "\"" + *c.truth + "\"");
    p.truth = *c.truth;
    return p;
}

void describe(const discovery::SynthPlan& plan, const SynthDataCommandLine& c, std::ostream& out)
{
    const auto& s = c.settings.scan;
    const bool guettler = s.kind == scan::ScanKind::Guettler;
    out << "synth-data " << scan::kindName(s.kind) << ": preset " << plan.presetName << ", " << s.betas.size()
        << " beta(s) x " << s.forces.size() << " forces x " << s.second.size()
        << (guettler ? " accelerations" : " bow speed") << " = " << s.cellCount() << " trials of "
        << physics::formatNumber(s.trialSeconds) << " s at " << plan.dataset.sampleRate << " Hz, seed "
        << plan.seed << (c.generator == "independent" ? ", independent generator" : "");
    if (plan.generatorMember != 0)
        out << " member " << plan.generatorMember
            << (discovery::isSealedMember(plan.generatorMember) ? " (sealed split)" : " (tuning split)");
    out << "\n";
}

// Simulates and writes every trial into the partial folder, then dataset.json.
void writeDataset(discovery::SynthPlan& plan, const OutputPaths& paths, unsigned threads,
                  const std::string& generator)
{
    plan.dataset.folder = paths.partial.string();
    // The description is checked now (without the noise floor, which the pilot sets), not after the run.
    discovery::parseDatasetDescription(nlohmann::json::parse(discovery::datasetToJson(plan.dataset).dump()),
                                       plan.dataset.descriptionPath(), plan.dataset.folder);
    fs::create_directories(paths.partial);
    const discovery::MeasuredTrialSink sink =
        [&](std::size_t i, const std::vector<std::vector<double>>& channels)
    {
        if (scan::stopSignalled())
            throw Stopped{};
        discovery::writeTrialSignals(plan.dataset, plan.dataset.trials[i], channels);
    };
    if (generator == "independent")
        discovery::runIndependentSynthData(plan, threads, sink);
    else
        discovery::runSynthData(plan, threads, sink);
    if (scan::stopSignalled())
        throw Stopped{};
    discovery::writeDatasetDescription(plan.dataset, plan.dataset.folder);
}

// The truth beside the dataset, then the dataset in place: both or neither.
void publish(const discovery::SynthPlan& plan, const OutputPaths& paths, const std::string& generator)
{
    fs::path truthPartial;
    if (paths.truth)
    {
        truthPartial = *paths.truth;
        truthPartial += ".tmp";
        auto truth = discovery::truthJson(plan, paths.out.string());
        if (generator == "independent")
            truth["independent"] = discovery::independentTruth(plan).toJson();
        config::writeFileAtomically(truthPartial, truth.dump(2) + "\n");
    }
    std::error_code ec;
    if (fs::exists(paths.out, ec))
        fs::remove(paths.out, ec); // an empty folder (checkPaths refused any other)
    fs::rename(paths.partial, paths.out, ec);
    if (ec)
    {
        fs::remove(truthPartial, ec);
        throw ConfigError("--out", "", "a folder that can be created",
                          "\"" + paths.out.string() + "\": " + ec.message());
    }
    if (paths.truth)
        fs::rename(truthPartial, *paths.truth);
}

std::string effectCatalogHelp()
{
    std::string text;
    for (const auto& e : discovery::effectCatalog())
    {
        const std::size_t pad = e.name.size() < 21 ? 21 - e.name.size() : 1;
        text += "  " + e.name + std::string(pad, ' ') + e.summary + "\n";
        for (const auto& p : e.parameters)
        {
            const std::string unit = p.unit.empty() ? "" : " " + p.unit;
            if (!p.choices.empty())
            {
                std::string choices, drawn;
                for (std::size_t c = 0; c < p.choices.size(); ++c)
                {
                    choices += (c ? "|" : "") + p.choices[c];
                    if (c >= p.drawMin && c <= p.drawMax)
                        drawn += (drawn.empty() ? "" : " or ") + p.choices[c];
                }
                text += "      " + p.name + "=" + choices + ": " + p.meaning + "; drawn " + drawn + "\n";
            }
            else
                text += "      " + p.name + "=" + physics::formatNumber(p.min) + ".." +
                        physics::formatNumber(p.max) + unit + ": " + p.meaning + "; drawn " +
                        (p.signedDraw ? "+-" : "") + physics::formatNumber(p.drawMin) + ".." +
                        physics::formatNumber(p.drawMax) + unit + "\n";
        }
        text += "      (" + e.source + ")\n";
    }
    return text;
}
} // namespace

HelpPage synthDataHelpPage()
{
    static const std::string effects =
        effectCatalogHelp() + "  none                 no hidden effect (the baseline model)\n";
    HelpPage page;
    page.command = "synth-data";
    page.usage = {
        "rosin synth-data --effect NAME|none [--effect NAME2 ...] --scan guettler|schelleng [grid options] "
        "[--preset NAME] [--sample-rate HZ] [--channels basic|all] [--generator rosin|independent [--member "
        "K]] "
        "--seed S --out DIR [--truth FILE]"};
    page.sections = {
        {"",
         R"(Writes a measured-like dataset (format rosin-measurements/1, the manual's measurements page) from
Rosin's model with physical effects hidden, through a laboratory's measurement chain: a first-order 0.5 Hz
sensor high-pass on the force channels ([Galluzzo2017]), white noise of about 0.3 % of the typical peak
bridge force, a 1.5 % (rms) trial-to-trial scatter of the actual bow force and acceleration (or speed) while
dataset.json records the nominal settings, and about 2.5 % failed trials (at least one from 20 trials on),
marked "valid": false, whose files are cut short or have a dropout. The dataset records only what a
laboratory would record; the hidden effects and their values are printed, and written to --truth FILE.
)"},
        {"effects (NAME, or NAME:PARAMETER=VALUE,... to fix a value instead of drawing it from the source "
         "texts)",
         effects},
        {"", "", &synthDataOptionTable()},
    };
    page.examples = {
        "rosin synth-data --effect junction-growth --scan guettler --grid 8 --seed 1 --out gu-jg --truth "
        "gu-jg.json",
        "rosin synth-data --effect sticking-creep:creepResistance=60 --effect hertz-contact --scan guettler "
        "\\\n"
        "                 --beta 0.0899,0.1428 --seed 7 --out gu-two",
        "rosin synth-data --effect none --scan schelleng --grid 8 --seed 3 --out sch-none",
    };
    page.exitStatus =
        "0 success, 1 bad value, preset or folder, 2 usage error, 128+signal when stopped (nothing kept)";
    return page;
}

std::string synthDataHelp()
{
    return helpText(synthDataHelpPage());
}

void checkSynthDataArguments(const std::vector<std::string>& args)
{
    parseSynthDataCommandLine(args);
}

int runSynthData(const std::vector<std::string>& args, std::ostream& out, std::ostream& err)
{
    const SynthDataCommandLine c = parseSynthDataCommandLine(args);
    if (c.help)
    {
        out << synthDataHelp();
        return kExitOk;
    }
    const OutputPaths paths = checkPaths(c);
    discovery::SynthPlan plan = discovery::planSynthData(c.settings);
    describe(plan, c, out);
    out.flush();
    scan::installStopSignals();
    const auto start = std::chrono::steady_clock::now();
    try
    {
        writeDataset(plan, paths, c.threads, c.generator);
        publish(plan, paths, c.generator);
    }
    catch (...)
    {
        std::error_code ec;
        fs::remove_all(paths.partial, ec);
        if (!scan::stopSignalled())
            throw;
        err << "stopped by signal " << scan::stopSignal() << ": nothing written\n";
        return 128 + scan::stopSignal();
    }
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::size_t invalid = 0;
    for (const auto& t : plan.dataset.trials)
        invalid += t.valid ? 0 : 1;
    char timing[32];
    std::snprintf(timing, sizeof(timing), "%.1f", seconds);
    out << "wrote " << c.out << ": " << plan.dataset.trials.size() << " trials (" << invalid
        << " marked invalid), channels";
    for (const auto& ch : plan.dataset.channels)
        out << " " << ch.name;
    out << "; sensor high-pass " << physics::formatNumber(*plan.dataset.sensor.highpassHz) << " Hz, noise "
        << physics::formatNumber(*plan.dataset.sensor.noiseRms) << " rms; " << timing << " s\n";
    out << "hidden (not in the dataset): " << discovery::describeHiddenEffects(plan) << "\n";
    if (paths.truth)
        out << "wrote truth " << paths.truth->string() << "\n";
    return kExitOk;
}

} // namespace rosin::cli
