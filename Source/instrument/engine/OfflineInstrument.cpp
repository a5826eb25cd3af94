#include "instrument/engine/OfflineInstrument.h"

#include <algorithm>
#include <cmath>
#include <iostream>

#include "instrument/engine/BlockPlayer.h"
#include "instrument/engine/MidiInput.h"

namespace rosin::engine
{

namespace
{
std::int64_t toSample(double seconds, double sampleRate)
{
    return static_cast<std::int64_t>(std::llround(std::max(0.0, seconds) * sampleRate));
}

std::int64_t totalSamples(const juce::MidiMessageSequence& sequence, const MidiRenderSettings& settings,
                          const AutomationLanes* automation)
{
    double lastSeconds = sequence.getNumEvents() > 0 ? sequence.getEndTime() : 0.0;
    if (automation != nullptr)
        for (const auto& lane : automation->lanes)
            lastSeconds = std::max(lastSeconds, lane.points.back().seconds);
    return toSample(lastSeconds + settings.tailSeconds, settings.sampleRate);
}

// The sequence's events stamped before `end`, from index `next` on, into `midi` at their block offsets.
void collectEvents(const juce::MidiMessageSequence& sequence, int& next, std::int64_t position,
                   std::int64_t end, double sampleRate, juce::MidiBuffer& midi)
{
    midi.clear();
    for (; next < sequence.getNumEvents(); ++next)
    {
        const auto& m = sequence.getEventPointer(next)->message;
        const std::int64_t at = eventSample(m.getTimeStamp(), sampleRate);
        if (at >= end)
            break;
        midi.addEvent(m, static_cast<int>(std::max<std::int64_t>(0, at - position)));
    }
}
} // namespace

std::int64_t eventSample(double seconds, double sampleRate)
{
    // The margin keeps a time that is a whole sample, such as 0.05 s at 44.1 kHz, from landing one early on a
    // product that comes out as 2204.9999999.
    return static_cast<std::int64_t>(std::floor(std::max(0.0, seconds) * sampleRate + 1e-6));
}

bool applyAutomation(ParameterSet& parameters, const AutomationLanes& automation, std::int64_t sample,
                     double sampleRate)
{
    bool changed = false;
    for (const AutomationLane& lane : automation.lanes)
        changed = parameters.set(lane.parameterId,
                                 static_cast<float>(lane.valueAt(static_cast<double>(sample) / sampleRate)),
                                 true) ||
                  changed;
    return changed;
}

void OfflineInstrument::setProgram(const FactoryProgram& program)
{
    const config::Preset& preset = program.preset;
    extras_.preset = preset;
    for (const auto& [id, value] : programParameterValues(preset))
        parameters_.set(id, value);
    if (!preset.bodyResponse)
    {
        response_.reset();
        return;
    }
    try
    {
        response_ = readBodyResponse(juce::File(*preset.bodyResponse));
    }
    catch (const BodyResponseError& e)
    {
        std::cerr << "rosin: program " << preset.name << ": " << e.what() << "\n";
    }
}

void OfflineInstrument::useBodyResponse(BodyResponseFile response)
{
    response_ = std::move(response);
}

MidiRenderResult OfflineInstrument::render(const juce::MidiMessageSequence& sequence,
                                           const MidiRenderSettings& settings,
                                           const AutomationLanes* automation)
{
    const double fs = settings.sampleRate;
    const int blockSize = std::max(1, settings.blockSize);
    const int grid = std::max(1, settings.controlInterval);
    const std::int64_t total = totalSamples(sequence, settings, automation);
    if (automation != nullptr)
        applyAutomation(parameters_, *automation, 0, fs);

    long serial = 1;
    InstrumentKey builtKey = instrumentKeyOf(parameters_.raw());
    std::unique_ptr<Engine> engine = buildEngine(builtKey, extras_, 0, serial++, fs);
    BlockPlayer player;
    if (response_)
        player.output().measured().use(juce::AudioBuffer<float>(response_->samples), response_->sampleRate);
    player.prepare(*engine, fs, blockSize);

    MidiRenderResult result;
    result.audio.resize(static_cast<std::size_t>(total));
    juce::MidiBuffer midi;
    int next = 0;
    for (std::int64_t position = 0; position < total;)
    {
        // Automation moves only on grid points: a block ends at the next grid point where a value may change,
        // and a changed instrument key rebuilds the instrument there (the plugin's builder does the same).
        std::int64_t end = std::min<std::int64_t>(position + blockSize, total);
        if (automation != nullptr)
        {
            if (position % grid == 0 && applyAutomation(parameters_, *automation, position, fs))
                if (const InstrumentKey key = instrumentKeyOf(parameters_.raw()); !(key == builtKey))
                {
                    builtKey = key;
                    engine = buildEngine(key, extras_, 0, serial++, fs);
                }
            end = std::min(end, (position / grid + 1) * grid);
        }
        const int n = static_cast<int>(end - position);
        collectEvents(sequence, next, position, end, fs, midi);

        juce::ScopedNoDenormals noDenormals; // as in the plugin's processBlock
        float* out = result.audio.data() + position;
        player.follow(*engine);
        const ParameterSnapshot snapshot = snapshotOf(parameters_.raw(), engine->instrument.stringCount());
        player.beginBlock(snapshot);
        MidiBufferEvents events(midi);
        const BlockPlayer::BlockResult block = player.play(*engine, events, snapshot.output, out, n);
        result.runawayResets += block.runawayResets;
        result.nonFiniteSamples += block.nonFinite;
        position = end;
    }
    for (float x : result.audio)
        result.peak = std::max(result.peak, std::abs(x));
    return result;
}

} // namespace rosin::engine
