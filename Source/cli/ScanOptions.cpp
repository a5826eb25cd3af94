#include "cli/ScanOptions.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <optional>

#include "cli/CommandLine.h"
#include "core/config/ConfigError.h"
#include "core/config/JsonObject.h"
#include "core/config/PresetLoader.h"
#include "core/config/VoiceSetup.h"
#include "core/gesture/GestureLimits.h"
#include "lab/scan/Axis.h"
#include "lab/scan/Variations.h"

namespace rosin::cli
{

namespace
{
using config::ConfigError;
using physics::Range;
using scan::ScanKind;

constexpr Range kForce{0.0, 20.0, "N", true};
constexpr Range kAcceleration{0.0, 50.0, "m/s^2", true};
constexpr Range kBeta{0.01, 0.5, ""};
constexpr Range kBowSpeed{0.0, 5.0, "m/s", true};
constexpr Range kDuration{0.0, 60.0, "s", true};
constexpr Range kRamp{0.0, 60.0, "s"};
constexpr Range kLayer{1e-9, 1e-3, "m"};
constexpr Range kRadius{1e-6, 0.01, "m"};

double number(const std::string& option, const std::string& text, const Range& range)
{
    return parseNumberIn(option, text, range);
}

// `whole` is the option's full value, quoted in the message (a part of "20x400" is not what the user typed).
std::size_t integer(const std::string& option, const std::string& text, std::size_t lo, std::size_t hi,
                    const std::string& expected, const std::string& whole = {})
{
    std::size_t v = 0;
    const char* last = text.data() + text.size();
    const auto r = std::from_chars(text.data(), last, v);
    if (text.empty() || r.ec != std::errc() || r.ptr != last || v < lo || v > hi)
        badOptionValue(option, expected, whole.empty() ? text : whole);
    return v;
}

struct Interval
{
    double first = 0.0, last = 0.0;
};

Interval interval(const std::string& option, const std::string& text, const Range& range)
{
    const auto colon = text.find(':');
    const std::string expected = "FIRST:LAST, FIRST < LAST, each " + range.describe();
    if (colon == std::string::npos)
        badOptionValue(option, expected, text);
    Interval i;
    try
    {
        i = {number(option, text.substr(0, colon), range), number(option, text.substr(colon + 1), range)};
    }
    catch (const ConfigError&)
    {
        badOptionValue(option, expected, text);
    }
    if (!(i.first < i.last))
        badOptionValue(option, expected, text);
    return i;
}

std::vector<double> betaList(const std::string& option, const std::string& text)
{
    std::vector<double> betas;
    std::size_t begin = 0;
    while (begin <= text.size())
    {
        const std::size_t comma = std::min(text.find(',', begin), text.size());
        const std::string item = text.substr(begin, comma - begin);
        const double v = parseNumber(option, item);
        if (!kBeta.contains(v))
            badOptionValue(option, "comma-separated betas, each " + kBeta.describe(), text);
        betas.push_back(v);
        begin = comma + 1;
    }
    if (betas.size() > kMaxGridSide)
        badOptionValue(option, "at most " + std::to_string(kMaxGridSide) + " betas", text);
    return betas;
}

struct GridSize
{
    std::size_t forces = 20, second = 20;
    bool explicitSecond = false;
};

GridSize gridSize(const std::string& option, const std::string& text)
{
    const std::string expected =
        "N or NxM (forces x " + std::string("second axis), each 1..") + std::to_string(kMaxGridSide);
    const auto x = text.find('x');
    GridSize g;
    g.forces = integer(option, text.substr(0, x), 1, kMaxGridSide, expected, text);
    g.explicitSecond = x != std::string::npos;
    g.second =
        g.explicitSecond ? integer(option, text.substr(x + 1), 1, kMaxGridSide, expected, text) : g.forces;
    return g;
}

scan::ShardId shard(const std::string& option, const std::string& text)
{
    const std::string expected = "K/N with N >= 1 and K in 0..N-1 (e.g. 0/4)";
    const auto slash = text.find('/');
    if (slash == std::string::npos)
        badOptionValue(option, expected, text);
    const std::size_t n = integer(option, text.substr(slash + 1), 1, 1000000, expected, text);
    const std::size_t k = integer(option, text.substr(0, slash), 0, n - 1, expected, text);
    return {k, n};
}

// The option values by name (the last one wins, as for `rosin render`).
using Values = ParsedOptions;

void rejectForKind(const Values& v, ScanKind kind)
{
    const std::vector<std::string> only =
        kind == ScanKind::Guettler ? std::vector<std::string>{"--bow-speed", "--beta-range", "--ramp"}
                                   : std::vector<std::string>{"--acceleration-range"};
    for (const auto& name : only)
        if (v.has(name))
            throw UsageError(name + " applies to " + (kind == ScanKind::Guettler ? "schelleng" : "guettler") +
                             " scans only");
}

scan::ModelSpec model(const Values& v)
{
    config::Preset preset =
        v.value("--preset") ? config::loadPreset(*v.value("--preset")) : config::defaultPreset();
    if (const auto* f = v.value("--friction"))
    {
        requireChoice("--friction", *f, config::frictionNames());
        preset.friction = *f;
    }
    scan::ModelSpec m = scan::modelFromPreset(preset);
    scan::ModelVariations var;
    if (const auto* t = v.value("--layer-thickness"))
        var.layerThickness = number("--layer-thickness", *t, kLayer);
    if (const auto* r = v.value("--contact-radius"))
        var.contactRadius = number("--contact-radius", *r, kRadius);
    if (const auto* c = v.value("--contact"))
    {
        requireChoice("--contact", *c, {"coulomb", "hertz"});
        var.scaling = *c == "hertz" ? physics::ContactScaling::Hertz : physics::ContactScaling::Coulomb;
    }
    var.fingerDamping = v.has("--finger-damping");
    var.rigidBridge = v.has("--rigid-bridge");
    var.noTorsion = v.has("--no-torsion");
    var.noStiffness = v.has("--no-stiffness");
    if (const auto* w = v.value("--bow-width"))
        var.bowWidth = number("--bow-width", *w, physics::limits::bowWidth);
    var.horsehair = v.has("--horsehair");
    scan::applyVariations(m, var);
    return m;
}

void grid(const Values& v, scan::ScanSpec& s)
{
    const GridSize g = v.value("--grid") ? gridSize("--grid", *v.value("--grid")) : GridSize{};
    const bool log = s.kind == ScanKind::Schelleng;
    const Interval f = v.value("--force-range") ? interval("--force-range", *v.value("--force-range"), kForce)
                                                : Interval{s.forces.front(), s.forces.back()};
    s.forces = log ? scan::logAxis(f.first, f.last, g.forces) : scan::linearAxis(f.first, f.last, g.forces);
    if (const auto* list = v.value("--beta"))
    {
        if (log && g.explicitSecond)
            throw UsageError("--grid NxM sets the number of betas, which --beta already gives; use --grid N");
        s.betas = betaList("--beta", *list);
    }
    else if (log)
    {
        const Interval b = v.value("--beta-range") ? interval("--beta-range", *v.value("--beta-range"), kBeta)
                                                   : Interval{s.betas.front(), s.betas.back()};
        s.betas = scan::logAxis(b.first, b.last, g.second);
    }
    if (log)
    {
        if (const auto* speed = v.value("--bow-speed"))
            s.second = {number("--bow-speed", *speed, kBowSpeed)};
        return;
    }
    const Interval a = v.value("--acceleration-range")
                           ? interval("--acceleration-range", *v.value("--acceleration-range"), kAcceleration)
                           : Interval{s.second.front(), s.second.back()};
    s.second = scan::linearAxis(a.first, a.last, g.second);
}

void trial(const Values& v, scan::ScanSpec& s)
{
    if (const auto* d = v.value("--duration"))
        s.trialSeconds = number("--duration", *d, kDuration);
    if (const auto* r = v.value("--ramp"))
        s.rampSeconds = number("--ramp", *r, kRamp);
    if (v.has("--full-trials"))
    {
        if (s.kind != ScanKind::Guettler)
            badOptionValue("--full-trials", "a guettler scan (schelleng trials always run whole)",
                           "schelleng");
        s.trialEnd = scan::GuettlerTrialEnd::Whole;
    }
    if (const auto* c = v.value("--classify"))
    {
        if (*c != "state" && *c != "bridge-force")
            badOptionValue("--classify", "state or bridge-force", *c);
        s.classification =
            *c == "bridge-force" ? scan::Classification::BridgeForce : scan::Classification::State;
        if (s.classification == scan::Classification::BridgeForce &&
            s.trialEnd == scan::GuettlerTrialEnd::WhenDecided)
            s.trialEnd = scan::GuettlerTrialEnd::AfterWindow;
    }
    if (s.kind == ScanKind::Schelleng && !(s.rampSeconds < s.trialSeconds))
        badOptionValue("--ramp",
                       "a ramp shorter than the trial (--duration " + physics::formatNumber(s.trialSeconds) +
                           " s)",
                       physics::formatNumber(s.rampSeconds));
    s.sampleRate = v.number("--sample-rate", physics::limits::sampleRate, s.sampleRate);
}

void runOptions(const Values& v, ScanCommandLine& c)
{
    if (const auto* t = v.value("--threads"))
        c.run.threads = static_cast<unsigned>(integer("--threads", *t, 1, 4096, "an integer in 1..4096"));
    if (const auto* s = v.value("--shard"))
        c.run.shard = shard("--shard", *s);
    c.mpi = v.has("--mpi");
    if (c.mpi && c.run.shard)
        throw UsageError("--shard and --mpi are two ways to split a scan: use one");
    c.run.output.figures = !v.has("--no-figures");
    c.run.progress = !v.has("--no-progress");
}

ScanCommandLine merge(const std::vector<std::string>& args)
{
    ScanCommandLine c;
    c.action = ScanCommandLine::Action::Merge;
    std::vector<std::string> rest;
    for (const auto& a : args)
        if (a.rfind("-", 0) != 0 && c.out.empty())
            c.out = a;
        else
            rest.push_back(a);
    const Values v =
        OptionTable({{"--out", "DIR", ""}, {"-h, --help", "", ""}, {"--no-figures", "", ""}}).parse(rest);
    if (v.has("--help"))
        c.action = ScanCommandLine::Action::Help;
    if (const auto* o = v.value("--out"))
        c.out = *o;
    if (c.out.empty() && c.action == ScanCommandLine::Action::Merge)
        throw UsageError("rosin scan merge needs the folder of the shards: rosin scan merge DIR");
    c.run.output.figures = !v.has("--no-figures");
    return c;
}
} // namespace

const OptionTable& scanOptionTable()
{
    static const OptionTable table({
        {"", "", "model:"},
        {"--preset", "NAME|FILE.json",
         "instrument preset (default galluzzo-rig: cello D3 on the cello body, plastic)"},
        {"--friction", "LAW", "classical, reconstructed, plastic, viscous, modified-bow, modified-rod"},
        {"--sample-rate", "HZ", physics::limits::sampleRate.describe() + ", default 48000"},
        {"", "", "variations ([Galluzzo2017] Figs. 9-12):"},
        {"--layer-thickness", "M",
         "rosin layer of the steady-sliding (calibration) contact (default 10e-6; Fig. 9: 15e-6)"},
        {"--contact-radius", "M",
         "radius of the calibration contact at 3 N (default 500e-6; Fig. 10: 700e-6)"},
        {"--contact", "coulomb|hertz", "contact area ~ N (default) or ~ N^(2/3) (Fig. 11)"},
        {"--finger-damping", "", "the string's intrinsic damping of a finger-stopped note (Fig. 12c)"},
        {"--rigid-bridge", "", "no body: a rigid bridge (Fig. 12d)"},
        {"--no-torsion", "", "no torsional modes (Fig. 12e)"},
        {"--no-stiffness", "", "no bending stiffness (Fig. 12f)"},
        {"--bow-width", "M",
         "width of the hair ribbon on the string (0..0.03; default the preset's, 0: a point)"},
        {"--horsehair", "",
         "compliant horsehair instead of the preset's hair (default: rigid, the seeds' rod)"},
        {"", "", "grid (defaults: [Galluzzo2017]):"},
        {"--grid", "N | NxM",
         "N forces x M betas (schelleng) or x M accelerations (guettler); each 1..300;\ndefault 20x20"},
        {"--force-range", "A:B", "N (default schelleng 0.1:3, guettler 0.4:3.2)"},
        {"--beta", "LIST",
         "comma-separated betas (0.01..0.5); guettler default: the eight of Fig. "
         "5,\n0.0357,0.0449,0.0566,0.0714,"
         "0.0899,0.1133,0.1428,0.18"},
        {"--beta-range", "A:B", "schelleng only (default 0.02:0.18)"},
        {"--acceleration-range", "A:B", "guettler only, m/s^2 (default 0.08:3.2)"},
        {"--bow-speed", "V", "schelleng only, m/s (default 0.05)"},
        {"", "", "trial:"},
        {"--duration", "S", "seconds per trial (default schelleng 1, guettler 0.5)"},
        {"--ramp", "S", "schelleng only: time to reach the bow speed (default 0.1)"},
        {"--full-trials", "",
         "guettler only: run every trial to --duration; by default a trial ends once its\ntransient is "
         "decided "
         "(44 periods after the first full flyback, or as soon as\nHelmholtz motion can no longer start "
         "within "
         "20 periods), and the regime column\nis then that of the 20 periods before that point"},
        {"--classify", "state|bridge-force",
         "how slips are found for the regime and the transient: from the solver's state\n(default: full "
         "flybacks "
         "of the bowed point) or from the bridge force alone, as\n[Galluzzo2017] treats measured and "
         "simulated "
         "trials "
         "alike (guettler trials then end\nwith their transient window at the latest)"},
        {"", "", "running:"},
        {"--out", "DIR", "output folder (required; created if missing)"},
        {"--threads", "N", "threads (default: every core)"},
        {"--shard", "K/N",
         "compute only the cells with index % N == K (Slurm arrays: K = $SLURM_ARRAY_TASK_ID);\nwrites "
         "DIR/scan.shard-K-of-N.csv; then: rosin scan merge DIR"},
        {"--mpi", "", "under mpirun -np R: cells spread over the ranks, rank 0 writes the files"},
        {"--no-figures", "", "do not run the figure script"},
        {"--no-progress", "", "no progress line on stderr"},
        {"-h, --help", "", "this text"},
    });
    return table;
}

ScanCommandLine parseScanCommandLine(const std::vector<std::string>& args)
{
    if (args.empty())
        throw UsageError(
            "expected a scan kind: rosin scan schelleng|guettler [options] --out DIR, or rosin scan "
            "merge DIR");
    const std::string& kind = args.front();
    if (kind == "--help" || kind == "-h" || kind == "help")
        return {};
    if (kind == "merge")
        return merge({args.begin() + 1, args.end()});
    if (kind != "schelleng" && kind != "guettler")
        throw UsageError("unknown scan \"" + kind + "\": expected schelleng, guettler or merge");
    const Values v = scanOptionTable().parse({args.begin() + 1, args.end()});
    ScanCommandLine c;
    if (v.has("--help"))
        return c;
    c.action = ScanCommandLine::Action::Scan;
    c.spec = scan::defaultSpec(kind == "schelleng" ? ScanKind::Schelleng : ScanKind::Guettler);
    rejectForKind(v, c.spec.kind);
    c.spec.model = model(v);
    grid(v, c.spec);
    trial(v, c.spec);
    runOptions(v, c);
    const auto* out = v.value("--out");
    if (out == nullptr)
        throw UsageError("--out DIR is required (the folder for scan.csv, scan.json and the figures)");
    if (out->empty())
        badOptionValue("--out", "a folder name", *out);
    c.out = *out;
    return c;
}

} // namespace rosin::cli
