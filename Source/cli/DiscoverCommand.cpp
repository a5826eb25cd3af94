#include "cli/DiscoverCommand.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <thread>

#include "cli/CommandLine.h"
#include "cli/HelpPage.h"
#include "cli/OptionTable.h"
#include "core/config/AtomicFile.h"
#include "core/config/ConfigError.h"
#include "lab/discovery/DatasetReader.h"
#include "lab/discovery/discover/Discovery.h"
#include "lab/discovery/discover/DiscoveryReport.h"
#include "lab/discovery/io/TrialSignals.h"
#include "lab/scan/ChildProcess.h"
#include "lab/scan/HelperScripts.h"

#ifndef ROSIN_DISCOVER_FIGURE_SCRIPT
#define ROSIN_DISCOVER_FIGURE_SCRIPT ""
#endif

namespace rosin::cli
{

namespace fs = std::filesystem;
using config::ConfigError;

namespace
{
// Runs the figure script if there is one; returns the PNGs it made.
std::vector<std::string> makeFigures(const fs::path& reportDir, std::ostream& err)
{
    const std::string script = scan::findHelperScript("plot_discovery.py", "ROSIN_DISCOVER_FIGURE_SCRIPT",
                                                      ROSIN_DISCOVER_FIGURE_SCRIPT);
    if (script.empty() || !fs::exists(script))
    {
        err << "warning: the report has no figures: the figure script "
            << (script.empty() ? std::string("(none built in)") : script)
            << " is missing (ROSIN_DISCOVER_FIGURE_SCRIPT names another)\n";
        return {};
    }
    const std::string& python = scan::figurePython();
    if (python.empty())
    {
        err << "warning: the report has no figures: no Python with matplotlib and numpy (tried "
            << scan::figurePythonCandidates()
            << "; Debian: apt-get install python3-matplotlib, or set ROSIN_PYTHON)\n";
        return {};
    }
    // An argument vector, no shell: a report folder named with quotes or $(...) is only a folder name.
    if (scan::runProgram({python, script, reportDir.string()}, true) != 0)
    {
        err << "warning: the figure script failed; the report has no figures\n";
        return {};
    }
    std::vector<std::string> pngs;
    for (const auto& e : fs::directory_iterator(reportDir))
        if (e.path().extension() == ".png")
            pngs.push_back(e.path().filename().string());
    std::sort(pngs.begin(), pngs.end());
    return pngs;
}
} // namespace

namespace
{
constexpr physics::Range kThreads{1.0, 1024.0, "", false, false, true};
constexpr physics::Range kSeed{0.0, 9007199254740992.0, "", false, false, true};
constexpr physics::Range kMaxEffectsRange{1.0, static_cast<double>(discovery::kMaxEffects), "", false, false,
                                          true};

const OptionTable& discoverOptionTable()
{
    static const OptionTable table(
        {
            {"--json", "FILE", "the result (gap before/after per feature, steps, status)"},
            {"--report", "DIR", "report.md (and PNG maps when python3 with matplotlib is available)"},
            {"--baseline", "LAW", "friction law of the baseline (default plastic)"},
            {"--threads", "N", "threads (default: every core)"},
            {"--seed", "S", "seed of the significance test's random sign flips (default 0)"},
            {"--max-effects", "N",
             "adopt at most N effects, 1 to 3 (default 3): 1 is a quicker first answer"},
            {"-h, --help", "", "this text"},
        },
        23);
    return table;
}
} // namespace

HelpPage discoverHelpPage()
{
    HelpPage page;
    page.command = "discover";
    page.usage = {"rosin discover DATASET --json OUT.json --report DIR [options]"};
    page.sections = {
        {"",
         R"(Compares a measured dataset (format rosin-measurements/1) with Rosin's baseline model, simulated trial by
trial with the nominal settings through the dataset's sensor high-pass; finds where they disagree
(features: staticFriction, jump, creep, firstSlipTime, transientPeriods, pitchCents, harmonicTilt,
steadyLevel, the regime (a category, weighed by how often the measurement disagrees with itself), and
slipFraction and loopArea where the bowed point is recorded, each normalised by the measurement's own
scatter and the model's sensitivity to 2 % changes of the settings), fits each effect of the catalog on a
training half (checkerboard over the grid) and adopts the one that removes the most held-out gap if
significant (paired sign-flip test at 1 %, Bonferroni over the candidates, and a gain of at least 20 %;
a candidate close to it is cross-fitted, fitted on each half and scored on the other); at most three
effects (--max-effects).
)"},
        {"options", "", &discoverOptionTable()},
    };
    page.examples = {"rosin discover gu-jg --json gu-jg.json --report gu-jg-report --threads 2"};
    page.exitStatus = "0 success, 1 bad dataset or value, 2 usage error";
    return page;
}

std::string discoverHelp()
{
    return helpText(discoverHelpPage());
}

DiscoverCommandLine parseDiscoverCommandLine(const std::vector<std::string>& args)
{
    DiscoverCommandLine c{std::string(), ParsedOptions({})};
    std::vector<std::string> rest = args;
    if (!rest.empty() && rest.front().rfind("-", 0) != 0)
    {
        c.folder = rest.front();
        rest.erase(rest.begin());
    }
    c.options = discoverOptionTable().parse(rest);
    if (c.options.has("--help"))
        return c;
    if (c.folder.empty())
        throw UsageError("discover needs a DATASET folder");
    if (!c.options.value("--json") || !c.options.value("--report"))
        throw UsageError("discover needs --json FILE and --report DIR");
    return c;
}

void checkDiscoverArguments(const std::vector<std::string>& args)
{
    parseDiscoverCommandLine(args);
}

int runDiscover(const std::vector<std::string>& args, std::ostream& out, std::ostream& err)
{
    const DiscoverCommandLine c = parseDiscoverCommandLine(args);
    const std::string& folder = c.folder;
    const ParsedOptions& options = c.options;
    if (options.has("--help"))
    {
        out << discoverHelp();
        return kExitOk;
    }
    std::optional<std::string> json, report;
    if (const auto* v = options.value("--json"))
        json = *v;
    if (const auto* v = options.value("--report"))
        report = *v;
    discovery::DiscoverySettings settings;
    if (const auto* v = options.value("--baseline"))
        settings.baseline = *v;
    settings.threads = static_cast<unsigned>(
        options.number("--threads", kThreads, std::max(1u, std::thread::hardware_concurrency())));
    settings.seed = static_cast<std::uint64_t>(options.number("--seed", kSeed, 0.0));
    settings.maxEffects = static_cast<std::size_t>(
        options.number("--max-effects", kMaxEffectsRange, static_cast<double>(discovery::kMaxEffects)));

    const discovery::Dataset dataset = discovery::readDatasetDescription(folder);
    if (!dataset.channelIndex("bridgeForce"))
        throw ConfigError(dataset.descriptionPath(), "channels", "a \"bridgeForce\" channel (N)",
                          "none: rosin discover compares bridge forces");
    const discovery::ScanGrid grid = discovery::findScanGrid(dataset);
    if (grid.kind != discovery::ScanKind::Guettler && grid.kind != discovery::ScanKind::Schelleng)
        throw ConfigError(dataset.descriptionPath(), "trials",
                          "valid trials of one gesture type, constant-acceleration or steady",
                          discovery::scanKindName(grid.kind));
    out << "discover " << folder << ": " << grid.summary() << "\n" << std::flush;

    std::vector<discovery::TrialFeatures> measured(dataset.trials.size());
    std::vector<double> seconds(dataset.trials.size(), 0.0);
    for (const auto& cell : grid.cells)
        for (std::size_t t : cell.trials)
        {
            const auto signals = discovery::readTrialSignals(dataset, dataset.trials[t]);
            seconds[t] = static_cast<double>(signals.frames()) / dataset.sampleRate;
            auto recorded = [&](const char* name) -> const std::vector<double>*
            { return dataset.channelIndex(name) ? &signals.channel(name) : nullptr; };
            measured[t] = discovery::computeTrialFeatures(
                signals.channel("bridgeForce"), discovery::featureContext(dataset, dataset.trials[t]),
                {recorded("bowPointVelocity"), recorded("frictionForce"), recorded("bowVelocity")});
        }

    settings.log = &out;
    const discovery::Discovery d = discovery::runDiscovery(dataset, std::move(measured), seconds, settings);

    fs::create_directories(*report);
    config::writeFileAtomically(fs::path(*report) / "maps.json",
                                discovery::discoveryMaps(d, dataset).dump(1) + "\n");
    const auto figures = makeFigures(*report, err);
    config::writeFileAtomically(fs::path(*report) / "report.md",
                                discovery::discoveryMarkdown(d, dataset, figures));
    config::writeFileAtomically(*json, discovery::discoveryJson(d, dataset).dump(2) + "\n");

    char line[200];
    std::snprintf(line, sizeof(line), "%s: gap %.3g -> %.3g", d.status.c_str(), d.gapBefore.overall,
                  d.gapAfter.overall);
    out << line;
    for (const auto& s : d.search.steps)
        out << "; " << discovery::describeEffect(*s.chosen.effect, s.chosen.values);
    std::snprintf(line, sizeof(line), " (%zu trials used, %zu skipped, %.1f s)\n", d.trialsUsed,
                  d.trialsSkipped, d.seconds);
    out << line << "wrote " << *json << " and " << (fs::path(*report) / "report.md").string() << "\n";
    return kExitOk;
}

} // namespace rosin::cli
