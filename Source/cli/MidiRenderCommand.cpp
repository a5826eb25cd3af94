#include "cli/MidiRenderCommand.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <optional>

#include "cli/CommandLine.h"
#include "cli/HelpPage.h"
#include "cli/ListeningOutput.h"
#include "cli/OptionTable.h"
#include "cli/RenderCommand.h"
#include "cli/WavWriter.h"
#include "core/config/ConfigError.h"
#include "core/config/PresetLoader.h"
#include "instrument/engine/MidiInput.h"
#include "instrument/engine/OfflineInstrument.h"

namespace rosin::cli
{

namespace
{
struct MidiOptions
{
    std::string midi, out = "rosin-midi.wav";
    std::string preset = engine::kDefaultProgramName;
    std::string automation;
    engine::OutputChoice output = engine::OutputChoice::RadiatedSound;
    std::string bodyResponse; ///< a measured body response (WAV), empty: the modal body
    bool dcBlocker = true;
    engine::ModelQuality quality = engine::ModelQuality::Full;
    double sampleRate = 48000.0;
    int blockSize = 512;
    double tail = 2.0;
    bool help = false;
};

/// --output takes the words of `rosin render --gesture` (ListeningOutput.h) and sets the plugin's choice.
engine::OutputChoice outputChoice(const std::string& v)
{
    switch (outputQuantityFromName(v))
    {
    case OutputQuantity::Force:
        return engine::OutputChoice::BridgeForce;
    case OutputQuantity::Velocity:
        return engine::OutputChoice::BridgeVelocity;
    case OutputQuantity::Radiated:
        break;
    }
    return engine::OutputChoice::RadiatedSound;
}

constexpr physics::Range kBlockSize{1.0, 65536.0, "samples", false, false, true};
constexpr physics::Range kTail{0.0, 60.0, "s"};

const OptionTable& midiOptionTable()
{
    static const OptionTable table({
        {"--midi", "FILE.mid", "standard MIDI file; all tracks are merged (the manual's MIDI map)"},
        {"--preset", "NAME|FILE.json",
         std::string("a factory program (default ") + engine::kDefaultProgramName +
             "): one of the presets/ names,\nor a program file (a preset; fit_body.py writes one)"},
        {"--automation", "FILE.json",
         "parameter lanes, \"format\": \"rosin-automation/1\" (the manual's\n"
         "rendering page)"},
        {"--out", "FILE.wav", "default rosin-midi.wav"},
        {"--output", "WHAT",
         "the plugin's Output parameter: radiated (the sound the body radiates to a\nlistener at 1 m, "
         "default), "
         "force or velocity (at the bridge)"},
        {"--dc-blocker", "on|off", "the plugin's DC blocker on the force and velocity outputs (default on)"},
        {"--body-response", "FILE",
         "a measured body response (WAV, AIFF or FLAC): bridge force (N) to sound\npressure (Pa), heard "
         "instead "
         "of the modal body's radiation"},
        {"--quality", "full|live",
         "the plugin's Quality parameter: the full model (default), or live, whose\nstrings and body stop at "
         "10 kHz (the manual's benchmarks page)"},
        {"--sample-rate", "HZ", physics::limits::sampleRate.describe() + ", default 48000"},
        {"--block-size", "N",
         "host block size, " + kBlockSize.describe() + ", default 512; the output\ndoes not depend on it"},
        {"--tail", "SECONDS", "rendered after the last event (default 2)"},
        {"-h, --help", "", "this text"},
    });
    return table;
}

MidiOptions parseMidiOptions(const std::vector<std::string>& args)
{
    MidiOptions o;
    const ParsedOptions options = midiOptionTable().parse(args);
    o.help = options.has("--help");
    for (const Option& opt : options.all())
    {
        const std::string& v = opt.value.value_or("");
        if (opt.name == "--midi")
            o.midi = v;
        else if (opt.name == "--out")
            o.out = v;
        else if (opt.name == "--preset")
            o.preset = v;
        else if (opt.name == "--automation")
            o.automation = v;
        else if (opt.name == "--output")
            o.output = outputChoice(v);
        else if (opt.name == "--body-response")
            o.bodyResponse = v;
        else if (opt.name == "--dc-blocker")
        {
            if (v != "on" && v != "off")
                throw config::ConfigError(opt.name, "", "on or off", "\"" + v + "\"");
            o.dcBlocker = v == "on";
        }
        else if (opt.name == "--quality")
        {
            if (v != "full" && v != "live")
                throw config::ConfigError(opt.name, "", "full or live", "\"" + v + "\"");
            o.quality = v == "live" ? engine::ModelQuality::Live : engine::ModelQuality::Full;
        }
        else if (opt.name == "--sample-rate")
            o.sampleRate = parseNumberIn(opt.name, v, physics::limits::sampleRate);
        else if (opt.name == "--block-size")
            o.blockSize = static_cast<int>(parseNumberIn(opt.name, v, kBlockSize));
        else if (opt.name == "--tail")
            o.tail = parseNumberIn(opt.name, v, kTail);
    }
    if (o.help)
        return o;
    if (o.midi.empty())
        throw config::ConfigError("--midi", "", "a MIDI file name", "an empty string");
    if (o.out.empty())
        throw config::ConfigError("--out", "", "a file name", "an empty string");
    return o;
}

} // namespace

bool isMidiRender(const std::vector<std::string>& args)
{
    for (const auto& a : args)
        if (a == "--midi" || a.rfind("--midi=", 0) == 0)
            return true;
    return false;
}

std::string midiRenderUsage()
{
    return "rosin render --midi FILE.mid [--preset NAME] [--automation FILE.json] [--out FILE.wav] "
           "[--output radiated|force|velocity] [--dc-blocker on|off] [--body-response FILE] "
           "[--quality full|live] [--sample-rate HZ] [--block-size N] [--tail SECONDS]";
}

HelpSection midiRenderSection()
{
    return {
        "with --midi",
        "Plays a MIDI file through the instrument's engine, as the plugin plays it (the cello or violin of "
        "the\npreset, the gesture controller, the output level), and writes what the plugin would output, "
        "mono\n32-bit float.\n",
        &midiOptionTable()};
}

void checkMidiRenderArguments(const std::vector<std::string>& args)
{
    parseMidiOptions(args);
}

namespace
{
/// The factory program of that name, or the program file NAME.json (a preset file, such as fit_body.py
/// writes); ConfigError listing the programs if there is none.
engine::FactoryProgram chooseProgram(const std::vector<engine::FactoryProgram>& programs,
                                     const std::string& name)
{
    if (name.size() > 5 && name.compare(name.size() - 5, 5, ".json") == 0)
    {
        const config::Preset preset = config::loadPreset(name);
        return {preset.name, preset};
    }
    std::string names;
    for (const engine::FactoryProgram& p : programs)
    {
        if (p.name == name)
            return p;
        names += (names.empty() ? "" : ", ") + p.name;
    }
    throw config::ConfigError("--preset", "",
                              "a factory program (one of " + names + ") or a program file NAME.json",
                              "\"" + name + "\"");
}

juce::File fromWorkingDirectory(const std::string& path)
{
    return juce::File::getCurrentWorkingDirectory().getChildFile(path);
}
} // namespace

int runMidiRender(const std::vector<std::string>& args, std::ostream& out, std::ostream& err)
{
    const MidiOptions o = parseMidiOptions(args);
    if (o.help)
    {
        out << renderHelp();
        return kExitOk;
    }
    const juce::File midiFile = fromWorkingDirectory(o.midi);
    if (!midiFile.existsAsFile())
        throw config::ConfigError("--midi", "", "an existing MIDI file", "\"" + o.midi + "\"");
    const juce::MidiMessageSequence sequence = engine::readMidiFile(midiFile);
    std::optional<engine::AutomationLanes> automation;
    if (!o.automation.empty())
        automation = engine::loadAutomation(o.automation);

    engine::OfflineInstrument instrument;
    instrument.setProgram(chooseProgram(engine::loadFactoryPrograms(), o.preset));
    if (!o.bodyResponse.empty())
    {
        try
        {
            instrument.useBodyResponse(engine::readBodyResponse(fromWorkingDirectory(o.bodyResponse)));
        }
        catch (const engine::BodyResponseError& e)
        {
            throw config::ConfigError("--body-response", "",
                                      "a readable impulse response (" + std::string(e.what()) + ")",
                                      "\"" + o.bodyResponse + "\"");
        }
    }
    instrument.parameters().set(engine::ids::output, static_cast<float>(o.output));
    instrument.parameters().set(engine::ids::dcBlocker, o.dcBlocker ? 1.0f : 0.0f);
    instrument.parameters().set(engine::ids::quality, static_cast<float>(o.quality));
    engine::MidiRenderSettings settings;
    settings.sampleRate = o.sampleRate;
    settings.blockSize = o.blockSize;
    settings.tailSeconds = o.tail;

    const auto began = std::chrono::steady_clock::now();
    const engine::MidiRenderResult result =
        instrument.render(sequence, settings, automation ? &*automation : nullptr);
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - began).count();

    WavWriter wav(o.out, o.sampleRate, 1,
                  "rosin plugin output (" +
                      engine::outputChoiceNames()[static_cast<int>(o.output)].toStdString() + "), program " +
                      o.preset);
    const float* channel = result.audio.data();
    wav.write(&channel, static_cast<int>(result.audio.size()));
    wav.close();

    const double seconds = static_cast<double>(result.audio.size()) / o.sampleRate;
    out << "program " << o.preset << ", " << sequence.getNumEvents() << " MIDI events, "
        << (automation ? automation->lanes.size() : 0u) << " automation lane(s), block size " << o.blockSize
        << "\n";
    out << "rendered " << significant(seconds, 6) << " s at " << o.sampleRate << " Hz in "
        << significant(wall, 3) << " s (" << significant(seconds / std::max(wall, 1e-9), 3)
        << " x real time); peak " << significant(result.peak, 6) << " ("
        << significant(20.0 * std::log10(std::max(1e-12f, result.peak)), 4) << " dBFS)\n";
    out << "wrote " << o.out << ": 1 channel, 32-bit float\n";
    if (result.runawayResets > 0 || result.nonFiniteSamples > 0)
        err << "warning: " << result.runawayResets << " runaway voice reset(s), " << result.nonFiniteSamples
            << " non-finite sample(s) written as 0\n";
    return kExitOk;
}

} // namespace rosin::cli
