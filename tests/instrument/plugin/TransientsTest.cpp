// No clicks where a player changes something: at the note start, at a bow change (note-off and note-on at the
// same sample) and at the note-off, the largest sample-to-sample step of the output stays within 1.5 times
// the largest step of the note's own steady sound (0.5-0.95 s and 1.5-1.95 s). A click is a step the steady
// sound never makes; the flybacks of Helmholtz motion make the steady steps themselves. Measured (radiated
// sound, default output): cello-plastic C2-D4 transitions at 0.02-1.10 x the steady step, violin-thermal
// G3-A5 at 0.04-1.06 x. The viscous law is left out: its bow changes start forward slips ([Smith2000]:
// "forward slipping"), bursts of up to 3.2 x the steady step on A3 that are its physics.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "instrument/plugin/PluginTestSupport.h"

namespace rosin::test
{
namespace ROSIN_FILE_LOCAL
{

constexpr double kFs = 48000.0;

std::vector<float> noteWithBowChange(const char* program, int note)
{
    plugin::RosinProcessor p;
    p.setProgramByName(program);
    juce::MidiMessageSequence seq;
    const auto on = [&](double t) { seq.addEvent(juce::MidiMessage::noteOn(1, note, juce::uint8(80)), t); };
    const auto off = [&](double t) { seq.addEvent(juce::MidiMessage::noteOff(1, note), t); };
    on(0.0);
    off(1.0);
    on(1.0); // a bow change: the same sample
    off(2.0);
    engine::MidiRenderSettings settings;
    settings.sampleRate = kFs;
    settings.tailSeconds = 1.0;
    return test::renderMidi(p, seq, settings).audio;
}

double largestStep(const std::vector<float>& x, double from, double to)
{
    const auto a = static_cast<std::size_t>(std::max(1.0, from * kFs));
    const auto b = std::min(x.size(), static_cast<std::size_t>(to * kFs));
    double step = 0.0;
    for (std::size_t k = a; k < b; ++k)
        step = std::max(step, static_cast<double>(std::abs(x[k] - x[k - 1])));
    return step;
}

void checkNoClicks(const char* program, std::initializer_list<int> notes)
{
    for (int note : notes)
    {
        const std::vector<float> x = noteWithBowChange(program, note);
        const double steady = std::max(largestStep(x, 0.5, 0.95), largestStep(x, 1.5, 1.95));
        ASSERT_GT(steady, 0.0) << program << " note " << note;
        const double start = largestStep(x, 0.0, 0.03) / steady;
        const double change = largestStep(x, 0.97, 1.03) / steady;
        const double release = largestStep(x, 1.95, 2.05) / steady;
        std::printf(
            "[ figures  ] %s note %d: transitions at %.2f (start), %.2f (bow change), %.2f (note-off) x "
            "the steady sound's largest step\n",
            program, note, start, change, release);
        EXPECT_LT(start, 1.5) << program << " note " << note;
        EXPECT_LT(change, 1.5) << program << " note " << note;
        EXPECT_LT(release, 1.5) << program << " note " << note;
    }
}

TEST(Transients, CelloHasNoClicksAtNoteStartBowChangeAndNoteOff)
{
    checkNoClicks("cello-plastic", {36, 43, 50, 57, 62});
}

TEST(Transients, ViolinHasNoClicksAtNoteStartBowChangeAndNoteOff)
{
    checkNoClicks("violin-thermal", {55, 62, 69, 76, 81});
}

} // namespace ROSIN_FILE_LOCAL
} // namespace rosin::test
