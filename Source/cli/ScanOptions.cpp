#include "ScanOptions.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <optional>

#include "CommandLine.h"
#include "config/ConfigError.h"
#include "config/JsonObject.h"
#include "config/PresetLoader.h"
#include "config/VoiceSetup.h"
#include "gesture/GestureLimits.h"
#include "scan/Axis.h"
#include "scan/Variations.h"

namespace rosin::cli
{

namespace
{
using config::ConfigError;
using gesture::Range;
using scan::ScanKind;

constexpr Range kForce{0.0, 20.0, "N", true};
constexpr Range kAcceleration{0.0, 50.0, "m/s^2", true};
constexpr Range kBeta{0.01, 0.5, ""};
constexpr Range kBowSpeed{0.0, 5.0, "m/s", true};
constexpr Range kDuration{0.0, 60.0, "s", true};
constexpr Range kRamp{0.0, 60.0, "s"};
constexpr Range kSampleRate{8000.0, 384000.0, "Hz"};
constexpr Range kLayer{1e-9, 1e-3, "m"};
constexpr Range kRadius{1e-6, 0.01, "m"};

const std::vector<std::string> kValueOptions = {"--preset",         "--friction",    "--beta",
                                                "--grid",           "--force-range", "--acceleration-range",
                                                "--bow-speed",      "--beta-range",  "--ramp",
                                                "--duration",       "--sample-rate", "--threads",
                                                "--shard",          "--out",         "--layer-thickness",
                                                "--contact-radius", "--contact",     "--classify"};
const std::vector<std::string> kFlags = {
    "--help",         "-h",           "--mpi",          "--no-figures", "--no-progress", "--finger-damping",
    "--rigid-bridge", "--no-torsion", "--no-stiffness", "--full-trials"};

double number(const std::string& option, const std::string& text, const Range& range)
{
    const double v = parseNumber(option, text);
    if (!range.contains(v))
        badOptionValue(option, range.describe(), text);
    return v;
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

void requireChoice(const std::string& option, const std::string& value,
                   const std::vector<std::string>& allowed)
{
    if (std::find(allowed.begin(), allowed.end(), value) == allowed.end())
        badOptionValue(option, config::oneOfText(allowed), value);
}

// The option values by name (the last one wins, as for `rosin render`).
struct Values
{
    std::vector<Option> options;
    const std::string* get(const std::string& name) const
    {
        const std::string* found = nullptr;
        for (const auto& o : options)
            if (o.name == name)
                found = &*o.value;
        return found;
    }
    bool has(const std::string& name) const
    {
        return std::any_of(options.begin(), options.end(), [&](const Option& o) { return o.name == name; });
    }
};

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
        v.get("--preset") ? config::loadPreset(*v.get("--preset")) : config::defaultPreset();
    if (const auto* f = v.get("--friction"))
    {
        requireChoice("--friction", *f, config::frictionNames());
        preset.friction = *f;
    }
    scan::ModelSpec m = scan::modelFromPreset(preset);
    scan::ModelVariations var;
    if (const auto* t = v.get("--layer-thickness"))
        var.layerThickness = number("--layer-thickness", *t, kLayer);
    if (const auto* r = v.get("--contact-radius"))
        var.contactRadius = number("--contact-radius", *r, kRadius);
    if (const auto* c = v.get("--contact"))
    {
        requireChoice("--contact", *c, {"coulomb", "hertz"});
        var.scaling = *c == "hertz" ? physics::ContactScaling::Hertz : physics::ContactScaling::Coulomb;
    }
    var.fingerDamping = v.has("--finger-damping");
    var.rigidBridge = v.has("--rigid-bridge");
    var.noTorsion = v.has("--no-torsion");
    var.noStiffness = v.has("--no-stiffness");
    scan::applyVariations(m, var);
    return m;
}

void grid(const Values& v, scan::ScanSpec& s)
{
    const GridSize g = v.get("--grid") ? gridSize("--grid", *v.get("--grid")) : GridSize{};
    const bool log = s.kind == ScanKind::Schelleng;
    const Interval f = v.get("--force-range") ? interval("--force-range", *v.get("--force-range"), kForce)
                                              : Interval{s.forces.front(), s.forces.back()};
    s.forces = log ? scan::logAxis(f.first, f.last, g.forces) : scan::linearAxis(f.first, f.last, g.forces);
    if (const auto* list = v.get("--beta"))
    {
        if (log && g.explicitSecond)
            throw UsageError("--grid NxM sets the number of betas, which --beta already gives; use --grid N");
        s.betas = betaList("--beta", *list);
    }
    else if (log)
    {
        const Interval b = v.get("--beta-range") ? interval("--beta-range", *v.get("--beta-range"), kBeta)
                                                 : Interval{s.betas.front(), s.betas.back()};
        s.betas = scan::logAxis(b.first, b.last, g.second);
    }
    if (log)
    {
        if (const auto* speed = v.get("--bow-speed"))
            s.second = {number("--bow-speed", *speed, kBowSpeed)};
        return;
    }
    const Interval a = v.get("--acceleration-range")
                           ? interval("--acceleration-range", *v.get("--acceleration-range"), kAcceleration)
                           : Interval{s.second.front(), s.second.back()};
    s.second = scan::linearAxis(a.first, a.last, g.second);
}

void trial(const Values& v, scan::ScanSpec& s)
{
    if (const auto* d = v.get("--duration"))
        s.trialSeconds = number("--duration", *d, kDuration);
    if (const auto* r = v.get("--ramp"))
        s.rampSeconds = number("--ramp", *r, kRamp);
    if (v.has("--full-trials"))
    {
        if (s.kind != ScanKind::Guettler)
            badOptionValue("--full-trials", "a guettler scan (schelleng trials always run whole)",
                           "schelleng");
        s.trialEnd = scan::GuettlerTrialEnd::Whole;
    }
    if (const auto* c = v.get("--classify"))
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
                       "a ramp shorter than the trial (--duration " + gesture::formatNumber(s.trialSeconds) +
                           " s)",
                       gesture::formatNumber(s.rampSeconds));
    if (const auto* rate = v.get("--sample-rate"))
    {
        s.sampleRate = number("--sample-rate", *rate, kSampleRate);
        if (s.sampleRate != std::floor(s.sampleRate))
            badOptionValue("--sample-rate", "an integer in 8000..384000 (Hz)", *rate);
    }
}

void runOptions(const Values& v, ScanCommandLine& c)
{
    if (const auto* t = v.get("--threads"))
        c.run.threads = static_cast<unsigned>(integer("--threads", *t, 1, 4096, "an integer in 1..4096"));
    if (const auto* s = v.get("--shard"))
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
    const Values v{parseOptions(rest, {"--out"}, {"--help", "-h", "--no-figures"})};
    if (v.has("--help") || v.has("-h"))
        c.action = ScanCommandLine::Action::Help;
    if (const auto* o = v.get("--out"))
        c.out = *o;
    if (c.out.empty() && c.action == ScanCommandLine::Action::Merge)
        throw UsageError("rosin scan merge needs the folder of the shards: rosin scan merge DIR");
    c.run.output.figures = !v.has("--no-figures");
    return c;
}
} // namespace

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
    const Values v{parseOptions({args.begin() + 1, args.end()}, kValueOptions, kFlags)};
    ScanCommandLine c;
    if (v.has("--help") || v.has("-h"))
        return c;
    c.action = ScanCommandLine::Action::Scan;
    c.spec = scan::defaultSpec(kind == "schelleng" ? ScanKind::Schelleng : ScanKind::Guettler);
    rejectForKind(v, c.spec.kind);
    c.spec.model = model(v);
    grid(v, c.spec);
    trial(v, c.spec);
    runOptions(v, c);
    const auto* out = v.get("--out");
    if (out == nullptr)
        throw UsageError("--out DIR is required (the folder for scan.csv, scan.json and the figures)");
    if (out->empty())
        badOptionValue("--out", "a folder name", *out);
    c.out = *out;
    return c;
}

} // namespace rosin::cli
