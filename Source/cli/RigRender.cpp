// `rosin render` for [Smith2000]'s oscillator rig (RigRender.h).
#include "cli/RigRender.h"
#include "cli/CommandLine.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <vector>

#include "cli/WavWriter.h"
#include "core/config/AtomicFile.h"
#include "core/config/ConfigError.h"
#include "core/physics/rig/OscillatorRig.h"
#include "lab/scan/Figures.h"

namespace rosin::cli
{

namespace
{

struct RigChannel
{
    const char* name;
    const char* unit;
    const char* what;
};
// The rig's probe: the string probe's five channels in the same order and units (the rig's clamp standing in
// for the bridge, the contact point for the bow point, the rod for the bow), then what only a rig has.
constexpr std::array<RigChannel, 7> kRigChannels = {{
    {"supportForce", "N", "force of the oscillator on its clamp, S x + R v"},
    {"contactVelocity", "m/s", "oscillator velocity at the contact"},
    {"frictionForce", "N", "friction force of the rod on the oscillator"},
    {"rodVelocity", "m/s", "rod velocity"},
    {"contactTemperature", "K", "contact temperature above ambient (0 for curve laws)"},
    {"displacement", "m", "oscillator displacement at the contact"},
    {"acceleration", "m/s^2", "oscillator acceleration at the contact"},
}};

struct LoopRow
{
    double time, slidingSpeed, frictionForce, normalForce, contactTemperature;
};

// Writes the loop's samples; the friction coefficient mu = f / N is what [Smith2000] Figs. 2c and 6 plot.
void writeLoopCsv(const std::vector<LoopRow>& rows, const std::string& path)
{
    std::string text = "time,slidingSpeed,frictionForce,contactTemperature,normalForce,frictionCoefficient\n";
    char line[200];
    for (const LoopRow& r : rows)
    {
        const double mu = r.normalForce > 0.0 ? r.frictionForce / r.normalForce : 0.0;
        std::snprintf(line, sizeof line, "%.9g,%.9g,%.9g,%.9g,%.9g,%.9g\n", r.time, r.slidingSpeed,
                      r.frictionForce, r.contactTemperature, r.normalForce, mu);
        text += line;
    }
    config::writeFileAtomically(path, text);
}

// Signed area of the (dv, mu) loop by the shoelace formula: > 0 anticlockwise, the sense of [Smith2000] Fig.
// 2c.
double signedArea(const std::vector<LoopRow>& rows)
{
    double twice = 0.0;
    auto mu = [](const LoopRow& r) { return r.normalForce > 0.0 ? r.frictionForce / r.normalForce : 0.0; };
    for (std::size_t i = 0; i + 1 < rows.size(); ++i)
        twice += rows[i].slidingSpeed * mu(rows[i + 1]) - rows[i + 1].slidingSpeed * mu(rows[i]);
    return 0.5 * twice;
}

void drawLoop(const std::string& csv, const std::string& figure, const std::string& title, std::ostream& err)
{
    scan::runFigureScript({"rig-loop", csv, "--out", figure, "--title", title}, err,
                          "; the loop's samples are in " + csv + "\n");
}
} // namespace

std::string rigSteadyGesture(const config::RigPreset& rig)
{
    return "steady:speed=" + significant(rig.rodSpeed, 9) + ",force=" + significant(rig.normalForce, 9) +
           ",seconds=1";
}

std::string rigRenderHelp()
{
    std::string text =
        "With a rig preset (a \"rig\" object, e.g. --preset cantilever): the rig is bowed instead of "
        "the string;\n`steady` without keys uses the rig's normalForce and rodSpeed; --out is the "
        "clamp force; --probe has 7 channels:\n";
    for (std::size_t i = 0; i < kRigChannels.size(); ++i)
    {
        char line[160];
        std::snprintf(line, sizeof line, "  %zu %-19s %-6s %s\n", i + 1, kRigChannels[i].name,
                      kRigChannels[i].unit, kRigChannels[i].what);
        text += line;
    }
    return text +
           "and --loop draws the friction coefficient f/N against the sliding speed ([Smith2000] Figs. "
           "2c, 6).\n";
}

int renderRig(const config::Preset& preset, const config::VoiceSetup& setup, gesture::BowGesture& bow,
              double gestureSeconds, const RigRenderRequest& request, std::ostream& out, std::ostream& err)
{
    const config::RigPreset& rigPreset = *preset.rig;
    physics::OscillatorRig rig;
    try
    {
        rig.prepare(rigPreset.oscillator, physics::makeFrictionLaw(setup.friction, setup.contact),
                    request.sampleRate);
    }
    catch (const std::invalid_argument& e)
    {
        throw config::ConfigError(preset.source, "rig", "a valid oscillator rig", e.what());
    }
    const auto& p = rigPreset.oscillator;
    out << "preset " << preset.name << " (" << preset.source << "): oscillator rig "
        << significant(p.frequency, 6) << " Hz, Q " << significant(p.qualityFactor, 6) << ", modal mass "
        << significant(p.modalMass, 6) << " kg, friction " << preset.friction << ", contact "
        << preset.contact << ", rosin " << preset.rosin << "\n";
    out << "gesture " << request.gesture << ": " << bow.totalSamples() << " samples at " << request.sampleRate
        << " Hz (" << significant(gestureSeconds, 6) << " s)\n";

    double loopFrom = 0.0, loopTo = 0.0;
    if (request.loop)
    {
        (void)makeLoop(*request.loop, gestureSeconds, request.sampleRate); // validates the interval
        loopTo = request.loop->to.value_or(gestureSeconds);
        loopFrom = request.loop->from.value_or(std::max(0.0, gestureSeconds - LoopRequest::kDefaultSeconds));
    }
    WavWriter audioFile(request.out, request.sampleRate, 1, "rosin rig clamp force, scaled for listening");
    std::optional<WavWriter> probeFile;
    if (request.probe)
    {
        std::string comment = "rosin rig probe, SI units, channels:";
        for (const auto& c : kRigChannels)
            comment += std::string(" ") + c.name + "[" + c.unit + "]";
        probeFile.emplace(*request.probe, request.sampleRate, static_cast<int>(kRigChannels.size()), comment);
    }

    const auto total = static_cast<std::size_t>(bow.totalSamples());
    std::vector<float> audio;
    audio.reserve(total);
    std::array<std::vector<float>, kRigChannels.size()> probe;
    std::vector<LoopRow> loopRows;
    double peak = 0.0, hottest = 0.0;
    int recoveries = 0;
    for (std::size_t k = 0; !bow.finished(); ++k)
    {
        const physics::BowInput in = bow.next();
        const physics::RigSample s = rig.step({in.bowForce, in.bowVelocity});
        recoveries += rig.recoveredFromRunaway() ? 1 : 0;
        peak = std::max(peak, std::abs(s.supportForce));
        hottest = std::max(hottest, s.contactTemperature);
        audio.push_back(static_cast<float>(s.supportForce));
        const double t = static_cast<double>(k) / request.sampleRate;
        if (request.loop && t >= loopFrom && t < loopTo)
            loopRows.push_back({t, s.slidingSpeed, s.frictionForce, s.normalForce, s.contactTemperature});
        if (!probeFile)
            continue;
        const std::array<double, kRigChannels.size()> values = {
            s.supportForce,       s.velocity,     s.frictionForce, s.rodVelocity,
            s.contactTemperature, s.displacement, s.acceleration};
        for (std::size_t c = 0; c < values.size(); ++c)
            probe[c].push_back(static_cast<float>(values[c]));
    }

    const double scale = request.scale ? *request.scale : (peak > 0.0 ? kListeningPeak / peak : 1.0);
    for (float& x : audio)
        x = static_cast<float>(x * scale);
    const float* channel = audio.data();
    audioFile.write(&channel, static_cast<int>(audio.size()));
    audioFile.close();
    out << "peak clamp force " << significant(peak, 6) << " N";
    if (hottest > 0.0)
        out << ", peak contact temperature " << significant(hottest, 4) << " K above ambient";
    out << "\nwrote " << request.out << ": clamp force x " << significant(scale, 8) << " /N ("
        << (request.scale ? "scale from --scale" : "peak normalised to -1 dBFS")
        << "), 1 channel, 32-bit float\n";
    if (probeFile)
    {
        std::array<const float*, kRigChannels.size()> pointers{};
        for (std::size_t c = 0; c < pointers.size(); ++c)
            pointers[c] = probe[c].data();
        probeFile->write(pointers.data(), static_cast<int>(probe[0].size()));
        probeFile->close();
        out << "wrote " << *request.probe << ": " << kRigChannels.size()
            << " channels, 32-bit float, SI units:\n";
        for (std::size_t i = 0; i < kRigChannels.size(); ++i)
            out << "  " << i + 1 << " " << kRigChannels[i].name << " [" << kRigChannels[i].unit << "]\n";
    }
    if (request.loop)
    {
        const std::string csv =
            std::filesystem::path(request.loop->figure).replace_extension(".csv").string();
        writeLoopCsv(loopRows, csv);
        const auto stuck = std::count_if(loopRows.begin(), loopRows.end(),
                                         [](const LoopRow& r) { return r.slidingSpeed == 0.0; });
        out << "wrote " << csv << ": " << loopRows.size()
            << " samples of the friction-coefficient/velocity loop ("
            << (loopRows.empty() ? 0 : static_cast<int>(100.0 * stuck / loopRows.size() + 0.5))
            << " % sticking, enclosed area " << signedArea(loopRows)
            << " m/s in (dv, mu), > 0 anticlockwise)\n";
        out.flush(); // the script writes to the same terminal
        drawLoop(csv, request.loop->figure, preset.name + " / " + preset.friction + " / " + request.gesture,
                 err);
    }
    if (recoveries > 0)
        err << "warning: the rig recovered from a runaway state " << recoveries << " time(s)\n";
    return 0;
}

} // namespace rosin::cli
