#include "instrument/plugin/HostRender.h"

#include <algorithm>
#include <cmath>

namespace rosin::test
{

namespace
{
std::int64_t toSample(double seconds, double sampleRate)
{
    return static_cast<std::int64_t>(std::llround(std::max(0.0, seconds) * sampleRate));
}

// Sets every automated parameter to its value at `sample` as a host's automation does; true if any changed.
bool applyAutomation(plugin::RosinProcessor& processor, const engine::AutomationLanes& automation,
                     std::int64_t sample, double sampleRate)
{
    bool changed = false;
    for (const engine::AutomationLane& lane : automation.lanes)
        if (auto* p = processor.parameters().getParameter(lane.parameterId))
            changed =
                engine::setPlainValue(
                    *p, static_cast<float>(lane.valueAt(static_cast<double>(sample) / sampleRate)), true) ||
                changed;
    return changed;
}
} // namespace

engine::MidiRenderResult renderMidi(plugin::RosinProcessor& processor,
                                    const juce::MidiMessageSequence& sequence,
                                    const engine::MidiRenderSettings& settings,
                                    const engine::AutomationLanes* automation)
{
    const double fs = settings.sampleRate;
    const int blockSize = std::max(1, settings.blockSize);
    const int grid = std::max(1, settings.controlInterval);
    double lastSeconds = sequence.getNumEvents() > 0 ? sequence.getEndTime() : 0.0;
    if (automation != nullptr)
        for (const auto& lane : automation->lanes)
            lastSeconds = std::max(lastSeconds, lane.points.back().seconds);
    const std::int64_t total = toSample(lastSeconds + settings.tailSeconds, fs);

    processor.setNonRealtime(true);
    processor.setPlayConfigDetails(0, 2, fs, blockSize);
    if (automation != nullptr)
        applyAutomation(processor, *automation, 0, fs);
    processor.prepareToPlay(fs, blockSize);

    engine::MidiRenderResult result;
    result.audio.reserve(static_cast<std::size_t>(total));
    juce::AudioBuffer<float> buffer(2, blockSize);
    juce::MidiBuffer midi;
    int next = 0;
    std::int64_t position = 0;
    while (position < total)
    {
        // Automation moves only on grid points: a block ends at the next grid point where a value changes. A
        // changed instrument is built by the block itself, as in a host's offline render (isNonRealtime).
        std::int64_t end = std::min<std::int64_t>(position + blockSize, total);
        if (automation != nullptr)
        {
            if (position % grid == 0)
                applyAutomation(processor, *automation, position, fs);
            const std::int64_t nextGrid = (position / grid + 1) * grid;
            if (nextGrid < end)
                end = nextGrid;
        }
        const int n = static_cast<int>(end - position);
        midi.clear();
        for (; next < sequence.getNumEvents(); ++next)
        {
            const auto& m = sequence.getEventPointer(next)->message;
            const std::int64_t at = engine::eventSample(m.getTimeStamp(), fs);
            if (at >= end)
                break;
            midi.addEvent(m, static_cast<int>(std::max<std::int64_t>(0, at - position)));
        }
        buffer.setSize(2, n, false, false, true);
        processor.processBlock(buffer, midi);
        const float* out = buffer.getReadPointer(0);
        for (int i = 0; i < n; ++i)
        {
            result.audio.push_back(out[i]);
            result.peak = std::max(result.peak, std::abs(out[i]));
        }
        position = end;
    }
    result.runawayResets = processor.runawayResets();
    result.nonFiniteSamples = processor.nonFiniteSamples();
    processor.releaseResources();
    return result;
}

} // namespace rosin::test
