#include "cli/SynthDataOptions.h"

#include <algorithm>
#include <charconv>
#include <limits>

#include "cli/CommandLine.h"
#include "cli/ScanOptions.h"
#include "core/config/ConfigError.h"
#include "core/config/JsonObject.h"
#include "core/config/PresetLoader.h"
#include "core/gesture/GestureLimits.h"
#include "lab/discovery/independent/GeneratorMember.h"
#include "lab/scan/ModelSpec.h"

namespace rosin::cli
{

namespace
{
using config::ConfigError;
using discovery::Effect;
using discovery::EffectRequest;

// The grid options, passed on to rosin scan's parser unchanged (its checks, its messages).
const std::vector<std::string> kGridOptions = {
    "--beta",     "--grid",        "--force-range", "--acceleration-range", "--bow-speed", "--beta-range",
    "--duration", "--sample-rate", "--threads"};

bool contains(const std::vector<std::string>& list, const std::string& value)
{
    return std::find(list.begin(), list.end(), value) != list.end();
}

std::optional<std::string> optionalValue(const ParsedOptions& options, const std::string& name)
{
    const std::string* v = options.value(name);
    return v == nullptr ? std::nullopt : std::optional<std::string>(*v);
}

std::string effectChoices()
{
    std::vector<std::string> names{"none"};
    for (const auto& n : discovery::effectNames())
        names.push_back(n);
    return config::oneOfText(names);
}

// "name=value" for one parameter of `effect`: a number in its range, or one of its choices by name.
void parameterValue(const Effect& effect, const std::string& item, const std::string& whole,
                    EffectRequest& request)
{
    const auto eq = item.find('=');
    std::vector<std::string> names;
    for (const auto& p : effect.parameters)
        names.push_back(p.name);
    const std::string expected =
        effect.parameters.empty()
            ? effect.name + " without parameters"
            : effect.name + " parameters as NAME=VALUE, NAME " + config::oneOfText(names);
    const auto it = std::find(names.begin(), names.end(), item.substr(0, eq));
    if (eq == std::string::npos || it == names.end())
        badOptionValue("--effect", expected, whole);
    const std::size_t index = static_cast<std::size_t>(it - names.begin());
    const auto& p = effect.parameters[index];
    const std::string text = item.substr(eq + 1);
    double v = 0.0;
    if (!p.choices.empty())
    {
        const auto choice = std::find(p.choices.begin(), p.choices.end(), text);
        if (choice == p.choices.end())
            badOptionValue("--effect", p.name + " " + config::oneOfText(p.choices), whole);
        v = static_cast<double>(choice - p.choices.begin());
    }
    else
    {
        v = parseNumber("--effect", text);
        if (!(v >= p.min && v <= p.max))
            badOptionValue("--effect",
                           p.name + " in " + physics::formatNumber(p.min) + ".." +
                               physics::formatNumber(p.max) + (p.unit.empty() ? "" : " (" + p.unit + ")"),
                           whole);
    }
    request.fixed[index] = v;
}

// "NAME" or "NAME:param=value,param=value".
EffectRequest effectRequest(const std::string& text)
{
    const auto colon = text.find(':');
    const Effect* effect = discovery::findEffect(text.substr(0, colon));
    if (effect == nullptr)
        badOptionValue("--effect", effectChoices(), text);
    EffectRequest request{effect, std::vector<std::optional<double>>(effect->parameters.size())};
    if (colon == std::string::npos)
        return request;
    const std::string list = text.substr(colon + 1);
    std::size_t begin = 0;
    while (begin <= list.size())
    {
        const std::size_t comma = std::min(list.find(',', begin), list.size());
        parameterValue(*effect, list.substr(begin, comma - begin), text, request);
        begin = comma + 1;
    }
    return request;
}

std::vector<EffectRequest> effects(const std::vector<std::string>& texts)
{
    if (texts.empty())
        throw UsageError("--effect NAME|none is required (" + effectChoices() +
                         "; repeat it to hide several)");
    if (texts.size() > 1 && contains(texts, "none"))
        badOptionValue("--effect", "none alone, or one or more effects", "none");
    if (texts.front() == "none")
        return {};
    std::vector<EffectRequest> requests;
    for (const auto& text : texts)
    {
        requests.push_back(effectRequest(text));
        for (std::size_t i = 0; i + 1 < requests.size(); ++i)
            if (requests[i].effect == requests.back().effect)
                throw ConfigError("--effect", "", "each effect once",
                                  "\"" + requests.back().effect->name + "\" twice");
    }
    return requests;
}

std::uint64_t seed(const std::string& text)
{
    std::uint64_t v = 0;
    const char* end = text.data() + text.size();
    const auto r = std::from_chars(text.data(), end, v);
    if (text.empty() || r.ec != std::errc() || r.ptr != end)
        badOptionValue("--seed",
                       "an integer in 0.." + std::to_string(std::numeric_limits<std::uint64_t>::max()), text);
    return v;
}

unsigned memberNumber(const std::string& text)
{
    constexpr unsigned kMaxMember = 1000000;
    unsigned v = 0;
    const char* end = text.data() + text.size();
    const auto r = std::from_chars(text.data(), end, v);
    if (text.empty() || r.ec != std::errc() || r.ptr != end || v > kMaxMember)
        badOptionValue("--member", "an integer in 0.." + std::to_string(kMaxMember), text);
    return v;
}

// rosin scan's parser on the grid options, behind synth-data's defaults (the last value of an option wins).
ScanCommandLine scanGrid(const std::string& kind, const ParsedOptions& options)
{
    std::vector<std::string> args{
        kind,     "--duration",     kSynthDefaultDuration, "--sample-rate", kSynthDefaultSampleRate,
        "--grid", kSynthDefaultGrid};
    if (kind == "guettler")
        args.insert(args.end(), {"--beta", kSynthDefaultBeta});
    else
        args.insert(args.end(), {"--ramp", "0"}); // "steady" in the dataset format: the speed from t = 0
    for (const auto& o : options.all())
        if (contains(kGridOptions, o.name))
            args.insert(args.end(), {o.name, *o.value});
    args.insert(args.end(), {"--out", "unused", "--no-progress", "--no-figures"});
    return parseScanCommandLine(args);
}
} // namespace

const OptionTable& synthDataOptionTable()
{
    static const OptionTable table({
        {"", "", "scan and grid (as rosin scan; defaults differ where noted):"},
        {"--scan", "guettler|schelleng",
         "constant-acceleration starts over (force, acceleration) at each beta, or\nsteady bowing (speed "
         "from t = "
         "0) over (force, beta)"},
        {"--grid", "N | NxM", "forces x accelerations (guettler) or x betas (schelleng); default 10"},
        {"--beta", "LIST", "comma-separated betas; guettler default 0.0899"},
        {"--force-range", "A:B", "N (default guettler 0.4:3.2, schelleng 0.1:3)"},
        {"--acceleration-range", "A:B", "guettler only, m/s^2 (default 0.08:3.2)"},
        {"--beta-range", "A:B", "schelleng only (default 0.02:0.18)"},
        {"--bow-speed", "V", "schelleng only, m/s (default 0.05)"},
        {"--duration", "S", "seconds per trial (default 0.4)"},
        {"", "", "model and recording:"},
        {"--effect", "NAME|none", "an effect above to hide (required); repeat it to hide several"},
        {"--preset", "NAME|FILE.json",
         "the rig's instrument (default galluzzo-rig: cello D3 on the cello body, plastic)"},
        {"--sample-rate", "HZ", physics::limits::sampleRate.describe() + ", default 44100"},
        {"--channels", "basic|all",
         "basic (default): bridgeForce (N) and bowVelocity (m/s), as a laboratory\nrecords them; all: also "
         "frictionForce (N) and bowPointVelocity (m/s)"},
        {"--generator", "rosin|independent",
         "rosin (default): Rosin's own stepper, the catalog's effect formulas; independent:\ndata Rosin's "
         "stepper "
         "did not make, to test rosin discover on: a waveguide string\n(transverse + torsion) with its own "
         "finite-difference heat balance, each effect in\nits own form (not the catalog's formula), the "
         "rig's "
         "constants off nominal within a\nlab's tolerances and an unstated anti-aliasing low-pass, gain "
         "error "
         "and start\ndelay (all drawn from the seed; --truth records them)"},
        {"--member", "K",
         "independent generator only: member K of its family (0, the default: its nominal\ndesign; 1-99 the "
         "tuning split; from 100 the sealed split, which tests only score):\nother numerics, constants "
         "within their priors, chain and rig (--truth records them)"},
        {"", "", "output:"},
        {"--seed", "S", "integer 0..2^64-1; the same seed and options give byte-identical files"},
        {"--out", "DIR", "the dataset folder: new or empty; built in DIR.tmp and renamed when complete"},
        {"--truth", "FILE", "the truth as JSON (effects, actual settings, faults); must lie outside DIR"},
        {"--threads", "N", "threads (default: every core)"},
        {"-h, --help", "", "this text"},
    });
    return table;
}

SynthDataCommandLine parseSynthDataCommandLine(const std::vector<std::string>& args)
{
    const ParsedOptions options = synthDataOptionTable().parse(args);
    SynthDataCommandLine c;
    if (options.has("--help"))
    {
        c.help = true;
        return c;
    }
    const auto kind = optionalValue(options, "--scan");
    if (!kind)
        throw UsageError("--scan guettler|schelleng is required");
    if (*kind != "guettler" && *kind != "schelleng")
        badOptionValue("--scan", "one of guettler, schelleng", *kind);
    auto& s = c.settings;
    s.effects = effects(options.values("--effect"));

    const ScanCommandLine grid = scanGrid(*kind, options);
    s.scan = grid.spec;
    c.threads = grid.run.threads;
    if (s.scan.trialSeconds < kSynthMinDuration)
        badOptionValue("--duration", "at least " + physics::formatNumber(kSynthMinDuration) + " s",
                       physics::formatNumber(s.scan.trialSeconds));
    s.preset = optionalValue(options, "--preset") ? config::loadPreset(*optionalValue(options, "--preset"))
                                                  : config::defaultPreset();
    s.scan.model = scan::modelFromPreset(s.preset);

    const auto seedText = optionalValue(options, "--seed");
    if (!seedText)
        throw UsageError("--seed S is required (the same seed gives the same dataset)");
    s.seed = seed(*seedText);
    if (const auto channels = optionalValue(options, "--channels"))
    {
        if (*channels != "basic" && *channels != "all")
            badOptionValue("--channels", "one of basic, all", *channels);
        s.allChannels = *channels == "all";
    }
    if (const auto generator = optionalValue(options, "--generator"))
    {
        if (*generator != "rosin" && *generator != "independent")
            badOptionValue("--generator", "one of rosin, independent", *generator);
        c.generator = *generator;
    }
    if (const auto member = optionalValue(options, "--member"))
    {
        if (c.generator != "independent")
            throw UsageError("--member K needs --generator independent (the family is the independent "
                             "generator's)");
        s.generatorMember = memberNumber(*member);
        discovery::applyMemberRig(discovery::generatorMember(s.generatorMember), s.preset);
        s.scan.model = scan::modelFromPreset(s.preset);
    }
    const auto out = optionalValue(options, "--out");
    if (!out)
        throw UsageError("--out DIR is required (the dataset folder)");
    if (out->empty())
        badOptionValue("--out", "a folder name", *out);
    c.out = *out;
    c.truth = optionalValue(options, "--truth");
    if (c.truth && c.truth->empty())
        badOptionValue("--truth", "a file name", *c.truth);
    return c;
}

} // namespace rosin::cli
