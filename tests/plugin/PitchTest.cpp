// Sustained notes across each instrument's range, at moderate force, sound within 5 cents of the MIDI note,
// measured from the rendered audio: the strongest of the first four harmonics near k f_note (Hann window,
// 2^18-point FFT, parabolic interpolation), divided by k, over 0.7..1.5 s (after the attack).
//
// The plugin plays with its default "intonation by ear" on (gesture/IntonationEar.h): like a cellist, the
// finger follows the pitch the string sounds. Without it the finger geometry alone misses 5 cents (measured:
// cello up to -6.0 cents at 0.5 N (F3), force flattening; violin up to +9 cents above G6, bending stiffness
// of short stopped lengths), which is physics, not a bug; IntonationEarTest checks the ear itself in closed
// loop.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdio>

#include "PluginTestSupport.h"
#include "gesture/StringChoice.h"
#include "support/Spectrum.h"

namespace rosin::test
{
namespace
{

constexpr double kFs = 48000.0;

struct PitchCase
{
    const char* program;
    int lowNote, highNote;
    float force;
    std::array<int, 4> openNotes;
    bool checkOpenStrings = true; ///< false near F_max: open strings flatten and have no finger to correct
};

double measuredPitchCents(const std::vector<float>& audio, int note)
{
    const std::vector<double> x(audio.begin(), audio.end());
    const std::size_t start = static_cast<std::size_t>(0.7 * kFs),
                      length = static_cast<std::size_t>(0.8 * kFs);
    const std::size_t fftSize = 1u << 18;
    const auto mag = hannSpectrum(x, start, length, fftSize);
    const double bin = kFs / static_cast<double>(fftSize);
    const double expected = gesture::noteFrequency(note);
    const double window = std::exp2(0.6 / 12.0); // +-60 cents
    Peak best;
    int bestK = 1;
    for (int k = 1; k <= 4 && k * expected * window < 0.45 * kFs; ++k)
    {
        const Peak p = findPeak(mag, bin, k * expected / window, k * expected * window);
        if (p.magnitude > best.magnitude)
            best = p, bestK = k;
    }
    return 1200.0 * std::log2(best.frequency / bestK / expected);
}

void checkRange(const PitchCase& c)
{
    double worst = 0.0, worstOpen = 0.0;
    int worstNote = -1;
    for (int note = c.lowNote; note <= c.highNote; ++note)
    {
        plugin::RosinProcessor p;
        p.setProgramByName(c.program);
        setParameter(p, plugin::ids::bowForce, c.force);
        setParameter(p, plugin::ids::bowSpeed, 0.1f);
        setParameter(p, plugin::ids::beta, 0.1f);
        setParameter(p, plugin::ids::outputLevel, 0.0f);
        const double cents = measuredPitchCents(renderHeldNote(p, note, 1.6, 0.0), note);
        const bool open = std::find(c.openNotes.begin(), c.openNotes.end(), note) != c.openNotes.end();
        if (open && std::abs(cents) > std::abs(worstOpen))
            worstOpen = cents;
        if (open && !c.checkOpenStrings)
            continue;
        EXPECT_LT(std::abs(cents), 5.0) << c.program << " note " << note << ": " << cents << " cents";
        if (std::abs(cents) > std::abs(worst))
            worst = cents, worstNote = note;
    }
    std::printf("[ figures  ] %s notes %d..%d at %.2f N: worst pitch error %+.2f cents (note %d%s); open "
                "strings worst %+.2f cents\n",
                c.program, c.lowNote, c.highNote, c.force, worst, worstNote,
                c.checkOpenStrings ? "" : ", stopped notes", worstOpen);
}

// The forces sit inside the plastic law's Helmholtz window on every string at v_b 0.1 m/s, beta 0.1 (D3 scan:
// 0.21-0.92 N; `rosin scan schelleng --friction plastic --bow-speed 0.1`). Measured: at 0.5 N the C string's
// notes 36-38 double-slip (its lower limit, ~Z0^2, is the highest of the four) and D#5 on the A string is
// raucous, so 0.6 N is the moderate force for all four; 1 N, used before the two-sided heat balance, lies
// above the upper limit at this beta (the contact runs cooler, mu_s - mu_d is larger).
TEST(PluginPitch, CelloNotesC2ToA5SoundWithinFiveCents)
{
    checkRange({"cello-plastic", 36, 81, 0.6f, {36, 43, 50, 57}});
}

// Near the upper limit (0.8 N of 0.92 N on D3): open strings flatten (A3: -6.3 cents, measured) and have no
// finger to correct, so only stopped notes are checked.
TEST(PluginPitch, CelloStoppedNotesSoundWithinFiveCentsNearTheUpperForceLimit)
{
    checkRange({"cello-plastic", 36, 81, 0.8f, {36, 43, 50, 57}, false});
}

TEST(PluginPitch, ViolinNotesG3ToE7SoundWithinFiveCents)
{
    checkRange({"violin-thermal", 55, 100, 0.3f, {55, 62, 69, 76}});
}

} // namespace
} // namespace rosin::test
