// Writes Resources/demo/phrase.mid, the lab's demo phrase (the golden renders and the programs' output
// levels are measured on it), and Resources/demo/melody.mid, the melody the README's first command renders
// with the default program's musical mapping. Build target rosin-make-demo-phrase; run it from the
// repository root to regenerate the committed files:
//     ./build/rosin-make-demo-phrase Resources/demo/phrase.mid Resources/demo/melody.mid
//
// The phrase: an 8.4 s cello phrase in D minor, written for Rosin to show what the lab mapping does:
//   0.0  D3 on the open D string, an expression (CC11) swell                     attack from rest
//   1.4  F3 slurred from D3 (overlapping keys, same string)                       legato finger change
//   2.2  A3 on the A string, a force (CC1) swell                                  new string, new stroke
//   3.0  A3 again (note-off and note-on at once)                                  bow change
//   3.8  F3 + D4 together                                                         double stop (D and A
//   strings) 5.6  C3 on the G string, 6.6 C2 on the open C string, fading (CC11, CC1)      lowest string
//   rings out
#include <cstdio>
#include <initializer_list>

#include <juce_audio_basics/juce_audio_basics.h>
#include <juce_core/juce_core.h>

namespace
{
constexpr int kTicksPerQuarter = 960;
constexpr double kBeatsPerSecond = 1.0; // 60 bpm: one quarter = one second, so times below are seconds

int ticks(double seconds)
{
    return static_cast<int>(seconds * kBeatsPerSecond * kTicksPerQuarter + 0.5);
}

struct Writer
{
    juce::MidiMessageSequence track;
    void add(juce::MidiMessage m, double seconds)
    {
        m.setTimeStamp(ticks(seconds));
        track.addEvent(m);
    }
    void note(int key, int velocity, double on, double off)
    {
        add(juce::MidiMessage::noteOn(1, key, static_cast<juce::uint8>(velocity)), on);
        add(juce::MidiMessage::noteOff(1, key), off);
    }
    // A controller ramp in 50 ms steps (what a player's pedal or wheel sends).
    void ramp(int cc, int from, int to, double start, double end)
    {
        const int steps = static_cast<int>((end - start) / 0.05);
        for (int i = 0; i <= steps; ++i)
        {
            const double t = start + (end - start) * i / steps;
            add(juce::MidiMessage::controllerEvent(1, cc, from + (to - from) * i / steps), t);
        }
    }
};
} // namespace

bool write(const Writer& w, const juce::File& out)
{
    juce::MidiFile file;
    file.setTicksPerQuarterNote(kTicksPerQuarter);
    file.addTrack(w.track);
    out.deleteFile();
    juce::FileOutputStream stream(out);
    if (!stream.openedOk() || !file.writeTo(stream))
    {
        std::fprintf(stderr, "error: cannot write %s\n", out.getFullPathName().toRawUTF8());
        return false;
    }
    std::printf("wrote %s: %d events\n", out.getFullPathName().toRawUTF8(), w.track.getNumEvents());
    return true;
}

// A 9 s cello melody in D minor for the musical mapping (the default program, cello-solo):
//   0.0  F3 on the D string, a crescendo (CC11 40 -> 90) and the vibrato growing (CC1 0 -> 80)
//   1.6  G3 slurred (overlapping keys): a finger placed (velocity 100)
//   2.4  A3 slurred: the open A string, reached by a string crossing under the moving bow
//   3.2  D4 slurred at velocity 30, on the A string: an audible shift, a slide of 250 ms
//   4.8  C#4 slurred, placed; 5.6 D4 on a new bow, a diminuendo (CC11 90 -> 30) that rings out
Writer melody()
{
    Writer w;
    w.add(juce::MidiMessage::tempoMetaEvent(static_cast<int>(1e6 / kBeatsPerSecond)), 0.0);
    w.add(juce::MidiMessage::textMetaEvent(3, "Rosin demo melody (cello, musical mapping)"), 0.0);
    w.add(juce::MidiMessage::controllerEvent(1, 11, 40), 0.0);
    w.add(juce::MidiMessage::controllerEvent(1, 1, 0), 0.0);
    w.ramp(11, 40, 90, 0.0, 2.4);
    w.ramp(1, 0, 80, 0.4, 1.6);
    w.note(53, 80, 0.0, 1.65);  // F3
    w.note(55, 100, 1.6, 2.45); // G3, placed
    w.note(57, 100, 2.4, 3.25); // A3, open A string
    w.note(62, 30, 3.2, 4.85);  // D4, a slide
    w.note(61, 100, 4.8, 5.6);  // C#4, placed
    w.note(62, 90, 5.6, 8.0);   // D4, new bow
    w.ramp(11, 90, 30, 5.8, 7.9);
    w.track.updateMatchedPairs();
    return w;
}

int main(int argc, char* argv[])
{
    const auto cwd = juce::File::getCurrentWorkingDirectory();
    const juce::File out = cwd.getChildFile(argc > 1 ? argv[1] : "Resources/demo/phrase.mid");
    const juce::File melodyOut = cwd.getChildFile(argc > 2 ? argv[2] : "Resources/demo/melody.mid");
    Writer w;
    w.add(juce::MidiMessage::tempoMetaEvent(static_cast<int>(1e6 / kBeatsPerSecond)), 0.0);
    w.add(juce::MidiMessage::textMetaEvent(3, "Rosin demo phrase (cello)"), 0.0);
    w.add(juce::MidiMessage::controllerEvent(1, 1, 64), 0.0);
    w.add(juce::MidiMessage::controllerEvent(1, 11, 48), 0.0);

    w.note(50, 90, 0.0, 1.5); // D3, open D string
    w.ramp(11, 48, 88, 0.0, 1.2);
    w.note(53, 90, 1.4, 2.2);  // F3 slurred (D3 still held until 1.5)
    w.note(57, 100, 2.2, 3.0); // A3, A string
    w.ramp(1, 64, 96, 2.2, 2.9);
    w.note(57, 100, 3.0, 3.8); // A3 again: bow change
    w.ramp(1, 96, 72, 3.0, 3.7);
    w.note(53, 95, 3.8, 5.6); // double stop F3 + D4
    w.note(62, 95, 3.8, 5.6);
    w.ramp(11, 88, 100, 3.8, 4.6);
    w.ramp(11, 100, 70, 4.6, 5.5);
    w.note(48, 80, 5.6, 6.6);  // C3 on the G string
    w.note(36, 110, 6.6, 8.4); // C2, open C string
    w.ramp(11, 70, 96, 6.6, 7.2);
    w.ramp(11, 96, 40, 7.2, 8.3);
    w.ramp(1, 72, 56, 7.2, 8.3);
    w.track.updateMatchedPairs();
    return write(w, out) && write(melody(), melodyOut) ? 0 : 1;
}
