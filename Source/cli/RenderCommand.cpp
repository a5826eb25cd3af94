#include "cli/RenderCommand.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <optional>

#include "cli/CommandLine.h"
#include "cli/HelpPage.h"
#include "cli/ListeningOutput.h"
#include "cli/LoopOutput.h"
#include "cli/MidiRenderCommand.h"
#include "cli/OfflineRender.h"
#include "cli/OptionTable.h"
#include "cli/ProbeChannels.h"
#include "cli/RigRender.h"
#include "cli/WavWriter.h"
#include "core/config/GestureScriptLoader.h"
#include "core/config/JsonObject.h"
#include "core/config/PresetLoader.h"
#include "core/config/VoiceSetup.h"
#include "core/gesture/BuiltinGestures.h"
#include "core/gesture/GestureLimits.h"
#include "core/physics/thermal/RosinMaterial.h"

namespace rosin::cli
{

const OptionTable& renderOptionTable();

namespace
{
constexpr physics::Range kScale{0.0, 1e9, "per unit of the --output quantity", true};
constexpr double kDefaultSampleRate = 48000.0;
const char* const kDefaultOut = "rosin-render.wav";

struct RenderOptions
{
    std::string gesture = "steady";
    std::string out = kDefaultOut;
    std::optional<std::string> probe, preset, friction, body, output, rosin;
    double sampleRate = kDefaultSampleRate;
    std::optional<double> scale;
    std::optional<LoopRequest> loop;
    bool help = false;
};

RenderOptions parseRenderOptions(const std::vector<std::string>& args)
{
    RenderOptions o;
    const ParsedOptions options = renderOptionTable().parse(args);
    for (const Option& opt : options.all())
    {
        const std::string& v = opt.value.value_or("");
        if (opt.name == "--help")
            o.help = true;
        else if (opt.name == "--gesture")
            o.gesture = v;
        else if (opt.name == "--out")
            o.out = v;
        else if (opt.name == "--output")
        {
            outputQuantityFromName(v); // checked here, before any work
            o.output = v;
        }
        else if (opt.name == "--probe")
            o.probe = v;
        else if (opt.name == "--preset")
            o.preset = v;
        else if (opt.name == "--friction")
            o.friction = v;
        else if (opt.name == "--body")
            o.body = v;
        else if (opt.name == "--rosin")
            o.rosin = v;
        else if (opt.name == "--sample-rate") // WAV headers store an integer rate
            o.sampleRate = parseNumberIn(opt.name, v, physics::limits::sampleRate);
        else if (opt.name == "--loop")
            (o.loop ? *o.loop : o.loop.emplace()).figure = v;
        else if (opt.name == "--loop-interval")
            parseLoopInterval(v, o.loop ? *o.loop : o.loop.emplace());
        else if (opt.name == "--scale")
            o.scale = parseNumberIn(opt.name, v, kScale);
    }
    if (o.loop && o.loop->figure.empty())
        throw config::ConfigError("--loop", "", "a figure file name (FILE.png) with --loop-interval", "none");
    for (const std::string* path : {&o.out, o.probe ? &*o.probe : nullptr})
        if (path != nullptr && path->empty())
            throw config::ConfigError("--out/--probe", "", "a file name", "an empty string");
    const auto normal = [](const std::string& p) { return std::filesystem::absolute(p).lexically_normal(); };
    if (o.probe && normal(*o.probe) == normal(o.out))
        throw config::ConfigError("--probe", "", "a different file from --out", "\"" + *o.probe + "\"");
    return o;
}

config::Preset choosePreset(const RenderOptions& o)
{
    config::Preset preset = o.preset ? config::loadPreset(*o.preset) : config::defaultPreset();
    if (o.friction)
    {
        requireChoice("--friction", *o.friction, config::frictionNames());
        preset.friction = *o.friction;
    }
    if (o.body)
    {
        requireChoice("--body", *o.body, config::bodyNames());
        preset.body = *o.body;
    }
    if (o.rosin)
    {
        requireChoice("--rosin", *o.rosin, physics::rosinMaterialNames());
        preset.rosin = *o.rosin;
    }
    return preset;
}

gesture::GestureScript chooseGesture(const std::string& spec, const gesture::GestureStart& start)
{
    if (gesture::isBuiltinGestureSpec(spec))
    {
        try
        {
            return gesture::parseBuiltinGesture(spec);
        }
        catch (const gesture::GestureError& e)
        {
            throw config::ConfigError("--gesture " + spec, e.field(), e.expected(), e.got());
        }
    }
    std::error_code ec;
    if (!spec.ends_with(".json") && !std::filesystem::exists(spec, ec))
        throw config::ConfigError(
            "--gesture", "", "steady[:key=value,...], guettler[:key=value,...] or a gesture script FILE.json",
            "\"" + spec + "\"");
    return config::loadGestureScript(spec, start);
}

std::string probeComment()
{
    std::string text = "rosin probe, SI units, channels:";
    for (const auto& c : kProbeChannels)
        text += std::string(" ") + c.name + "[" + c.unit + "]";
    return text;
}

// Word-wraps `text` to `width` columns, every line indented by `indent` spaces.
std::string wrap(const std::string& text, std::size_t indent, std::size_t width)
{
    std::vector<std::string> words;
    for (std::size_t pos = 0; pos < text.size();)
    {
        const std::size_t space = std::min(text.find(' ', pos), text.size());
        words.push_back(text.substr(pos, space - pos));
        pos = space + 1;
    }
    return wrapWords(words, std::string(indent, ' '), indent, width);
}

} // namespace

namespace
{
// The probe's channels, one line each, for --probe's help.
std::string probeChannelLines()
{
    std::string channels;
    for (std::size_t i = 0; i < kProbeChannels.size(); ++i)
    {
        const auto& c = kProbeChannels[i];
        char line[160];
        std::snprintf(line, sizeof(line), "\n%zu %-19s %-4s %s", i + 1, c.name, c.unit, c.what);
        channels += line;
    }
    return channels;
}

std::string presetHelp()
{
    std::string presets;
    for (const auto& n : config::presetNames())
        presets += (presets.empty() ? "" : ", ") + n;
    std::string available =
        wrap("available: " + (presets.empty() ? std::string("none found") : presets), 0, 79);
    available.pop_back(); // wrap() ends with a newline
    return "instrument preset (the manual's presets page): a NAME is one of the presets beside\n"
           "rosin (share/rosin/presets; the environment's ROSIN_PRESET_DIR overrides)\n" +
           available +
           "\ndefault: the open cello D3 of the Galluzzo rig [Galluzzo2017], cello body,\nplastic friction, "
           "Galluzzo contact, beta 0.0899";
}

std::string gestureHelp()
{
    std::string builtins = gesture::builtinGestureHelp("");
    builtins.pop_back(); // it ends with a newline
    return "the bow gesture (default: steady). Built-in gestures:\n" + builtins +
           "\nor a JSON gesture script (\"format\": \"rosin-gesture/1\") of timed segments\nof force, speed "
           "or "
           "acceleration, beta and finger, each constant or a ramp;\nsee the manual's gesture-script page. "
           "Absent values in a script's first segment:\nforce 1 N, speed 0 (bow at rest), the preset's beta, "
           "finger 1.";
}
} // namespace

const OptionTable& renderOptionTable()
{
    static const OptionTable table({
        {"--gesture", "SPEC|FILE.json", gestureHelp()},
        {"--out", "FILE.wav",
         "the --output quantity, mono 32-bit float, scaled for listening\n(default: " +
             std::string(kDefaultOut) + "); the scale is printed"},
        {"--output", "WHAT",
         "radiated (default): the sound pressure the body radiates to 1 m (Pa);\nforce: the bridge force "
         "(N); "
         "velocity: the bridge velocity (m/s).\nOn a rigid bridge the string is heard through its family's "
         "body."},
        {"--scale", "S",
         "fixed scale of --out per unit of that quantity (sample = S x value);\ndefault: the peak is "
         "normalised "
         "to -1 dBFS"},
        {"--probe", "FILE.wav",
         "also write internal channels, 32-bit float, physical SI values (not\nnormalised), " +
             std::to_string(kProbeChannels.size()) + " channels in this order:" + probeChannelLines()},
        {"--preset", "NAME|FILE.json", presetHelp()},
        {"--friction", "LAW",
         "replace the preset's friction law: classical, reconstructed, plastic,\nviscous, modified-bow, "
         "modified-rod"},
        {"--body", "BODY", "replace the preset's body: cello, violin, rigid"},
        {"--rosin", "MATERIAL",
         "replace the preset's rosin: handbook (the handbook constants), calibrated\n(rho c x " +
             significant(physics::kCalibratedRosinHeatCapacityFactor, 3) +
             ", fixed by [Smith2000]'s 44 Hz stick-slip)"},
        {"--sample-rate", "HZ", physics::limits::sampleRate.describe() + ", default 48000"},
        {"--loop", "FILE.png",
         "also draw the friction/velocity hysteresis loop ([Galluzzo2017] Figs. 20-21)\nand keep its samples "
         "in "
         "FILE.csv"},
        {"--loop-interval", "A:B", "the loop's interval in seconds (default: the last 0.05 s)"},
        {"-h, --help", "", "this text"},
    });
    return table;
}

HelpPage renderHelpPage()
{
    HelpPage page;
    page.command = "render";
    page.usage = {
        "rosin render [--gesture SPEC|FILE.json] [--out FILE.wav] [--output WHAT] [--probe FILE.wav] "
        "[--preset NAME|FILE.json] [--friction LAW] [--body BODY] [--rosin MATERIAL] [--sample-rate HZ] "
        "[--scale S] "
        "[--loop FILE.png [--loop-interval A:B]]",
        midiRenderUsage()};
    page.sections = {
        {"",
         "Drives one bowed-string voice with a bow gesture and writes what a listener hears (or the lab's "
         "bridge\nforce or velocity).\n"},
        {"options", "", &renderOptionTable()},
        {"", "valid ranges: beta 0.01..0.5, force 0..20 N, speed -5..5 m/s, acceleration -50..50 m/s^2,\n"
             "finger 0.1..1 (vibrating / open length), seconds > 0 and <= 600 per segment and in total.\n"},
        {"", rigRenderHelp()},
        midiRenderSection(),
    };
    page.examples = {
        "rosin render --gesture guettler:acceleration=1.56,force=0.84 --out g.wav --probe g-probe.wav",
        "rosin render --preset schumacher-rig --gesture steady:speed=0.1,force=1.18,beta=0.127",
        "rosin render --preset cello-classical --body rigid --gesture my-gesture.json",
        "rosin render --midi Resources/demo/phrase.mid --out demo.wav",
    };
    page.exitStatus = "0 success, 1 bad value, file or preset, 2 unknown option or missing value";
    return page;
}

std::string renderHelp()
{
    return helpText(renderHelpPage());
}

void checkRenderArguments(const std::vector<std::string>& args)
{
    if (isMidiRender(args))
        checkMidiRenderArguments(args);
    else
        parseRenderOptions(args);
}

int runRender(const std::vector<std::string>& args, std::ostream& out, std::ostream& err)
{
    if (isMidiRender(args))
        return runMidiRender(args, out, err);
    const RenderOptions o = parseRenderOptions(args);
    if (o.help)
    {
        out << renderHelp();
        return kExitOk;
    }

    // Everything that can fail on input is checked before the first sample is computed.
    const config::Preset preset = choosePreset(o);
    if (preset.rig && o.body)
        throw config::ConfigError("--body", "",
                                  "no --body with a rig preset (its \"rig\" replaces string and body)",
                                  "\"" + *o.body + "\"");
    if (preset.rig && o.output && *o.output != "force")
        throw config::ConfigError("--output", "", "force with a rig preset (a rig has no body to radiate)",
                                  "\"" + *o.output + "\"");
    const config::VoiceSetup setup = config::buildVoiceSetup(preset);
    gesture::GestureStart start;
    start.beta = preset.beta;
    const std::string gestureSpec =
        preset.rig && o.gesture == "steady" ? rigSteadyGesture(*preset.rig) : o.gesture;
    const gesture::GestureScript script = chooseGesture(gestureSpec, start);
    gesture::BowGesture bow;
    bow.prepare(script, start, o.sampleRate);
    if (preset.rig) // [Smith2000]'s oscillator rig instead of the string and body
        return renderRig(preset, setup, bow, script.totalSeconds(),
                         {gestureSpec, o.sampleRate, o.out, o.probe, o.scale, o.loop}, out, err);

    std::optional<analysis::HysteresisLoop> loop;
    if (o.loop)
        loop.emplace(makeLoop(*o.loop, script.totalSeconds(), o.sampleRate));

    physics::BowedStringVoice voice;
    voice.prepare(setup.voice, physics::makeFrictionLaw(setup.friction, setup.contact), o.sampleRate);

    out << "preset " << preset.name << " (" << preset.source << "): string " << setup.voice.string.name
        << ", body " << preset.body << ", friction " << preset.friction << ", contact " << preset.contact
        << ", rosin " << preset.rosin << "\n";
    out << "gesture " << o.gesture << ": " << script.segments.size() << " segment(s), " << bow.totalSamples()
        << " samples at " << o.sampleRate << " Hz (" << significant(script.totalSeconds(), 6) << " s)\n";

    ListeningOutput listening(outputQuantityFromName(o.output.value_or("radiated")), preset, o.sampleRate);
    WavWriter audioFile(o.out, o.sampleRate, 1, "rosin " + listening.describe() + ", scaled for listening");
    std::optional<WavWriter> probeFile;
    if (o.probe)
        probeFile.emplace(*o.probe, o.sampleRate, static_cast<int>(kProbeChannels.size()), probeComment());

    std::vector<float> bridge;
    bridge.reserve(static_cast<std::size_t>(bow.totalSamples()));
    std::array<std::vector<float>, kProbeChannels.size()> probeBlock;
    const auto began = std::chrono::steady_clock::now();
    const RenderStats stats =
        renderGesture(voice, bow,
                      [&](const physics::VoiceSample* s, int n)
                      {
                          for (int i = 0; i < n; ++i)
                              bridge.push_back(static_cast<float>(listening.next(s[i].bridgeForce)));
                          for (int i = 0; loop && i < n; ++i)
                              loop->add(s[i]);
                          if (!probeFile)
                              return;
                          for (auto& channel : probeBlock)
                              channel.resize(static_cast<std::size_t>(n));
                          for (int i = 0; i < n; ++i)
                          {
                              const auto k = static_cast<std::size_t>(i);
                              probeBlock[0][k] = static_cast<float>(s[i].bridgeForce);
                              probeBlock[1][k] = static_cast<float>(s[i].bowPointVelocity);
                              probeBlock[2][k] = static_cast<float>(s[i].frictionForce);
                              probeBlock[3][k] = static_cast<float>(s[i].bowVelocity);
                              probeBlock[4][k] = static_cast<float>(s[i].contactTemperature);
                          }
                          std::array<const float*, kProbeChannels.size()> pointers{};
                          for (std::size_t c = 0; c < pointers.size(); ++c)
                              pointers[c] = probeBlock[c].data();
                          probeFile->write(pointers.data(), n);
                      });
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - began).count();

    float peak = 0.0f;
    for (float x : bridge)
        peak = std::max(peak, std::abs(x));
    const double scale = o.scale ? *o.scale : (peak > 0.0f ? kListeningPeak / peak : 1.0);
    for (float& x : bridge)
        x = static_cast<float>(x * scale);
    const float* channel = bridge.data();
    audioFile.write(&channel, static_cast<int>(bridge.size()));
    audioFile.close();
    if (probeFile)
        probeFile->close();

    out << "rendered in " << significant(wall, 3) << " s ("
        << significant(script.totalSeconds() / std::max(wall, 1e-9), 3) << " x real time); peak bridge force "
        << significant(stats.peakBridgeForce, 6) << " N";
    if (stats.maxContactTemperature > 0.0)
        out << ", peak contact temperature " << significant(stats.maxContactTemperature, 4)
            << " K above ambient";
    out << "\n";
    out << "wrote " << o.out << ": " << listening.describe() << " x " << significant(scale, 8) << " /"
        << listening.unit() << " (" << (o.scale ? "scale from --scale" : "peak normalised to -1 dBFS")
        << "), 1 channel, 32-bit float\n";
    if (probeFile)
    {
        out << "wrote " << *o.probe << ": " << kProbeChannels.size()
            << " channels, 32-bit float, SI units:\n";
        for (std::size_t i = 0; i < kProbeChannels.size(); ++i)
            out << "  " << i + 1 << " " << kProbeChannels[i].name << " [" << kProbeChannels[i].unit << "]\n";
    }
    if (loop)
        writeLoop(*loop, *o.loop, preset.name + " / " + preset.friction + " / " + o.gesture, out, err);
    if (stats.runawayRecoveries > 0 || stats.nonFiniteSamples > 0)
        err << "warning: the voice recovered from a runaway state " << stats.runawayRecoveries << " time(s); "
            << stats.nonFiniteSamples << " non-finite sample(s) written as 0\n";
    return kExitOk;
}

} // namespace rosin::cli
