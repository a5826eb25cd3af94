// Sustained notes across each instrument's range, at moderate force, sound within 5 cents of the MIDI note,
// measured from the rendered audio: each of the first four harmonics' peak near k f_note (Hann window,
// 2^18-point FFT, parabolic interpolation), divided by k, over 0.7..1.5 s (after the attack); the note's
// pitch is their median. One harmonic alone can be pulled off by a body resonance that the slip noise rings
// beside it (measured: the violin's D#6, whose fundamental reads +6.9 cents and its second and fourth
// harmonics +0.04), as a pitch heard across the harmonics is not.
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
#include <vector>

#include "instrument/player/StringChoice.h"
#include "instrument/plugin/PluginTestSupport.h"
#include "support/Spectrum.h"

namespace rosin::test
{
namespace ROSIN_FILE_LOCAL
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
    const double expected = player::noteFrequency(note);
    const double window = std::exp2(0.6 / 12.0); // +-60 cents
    std::vector<double> cents;
    for (int k = 1; k <= 4 && k * expected * window < 0.45 * kFs; ++k)
    {
        const Peak p = findPeak(mag, bin, k * expected / window, k * expected * window);
        cents.push_back(1200.0 * std::log2(p.frequency / k / expected));
    }
    std::sort(cents.begin(), cents.end());
    const std::size_t n = cents.size();
    return n % 2 == 1 ? cents[n / 2] : 0.5 * (cents[n / 2 - 1] + cents[n / 2]);
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

// The Bow force parameter is the cello C string's; each string gets it times Z0 / Z0 of the C string
// (engine::bowForceShare): at the default 1 N the C, G, D and A strings are bowed with 1.0, 0.63, 0.42 and
// 0.35 N, the violin's G, D, A and E with 0.27, 0.17, 0.13 and 0.13 N. The plastic law's Helmholtz window on
// D3 at v_b 0.1 m/s, beta 0.1 is 0.21-0.92 N (`rosin scan schelleng --friction plastic --bow-speed 0.1`); its
// upper limit scales as Z0 and its lower one about as Z0^2, so 0.42 N sits near the window's middle (on a log
// scale) on the D string, every string sits at the same fraction of its upper limit, and the thinner ones
// further above their lower limits than the thicker. Before the shares, one force for every string put the
// default 1 N above the D string's upper limit (open A3 20 cents flat) and the tests bowed at 0.6 N.
TEST(PluginPitch, CelloNotesC2ToA5SoundWithinFiveCents)
{
    checkRange({"cello-plastic", 36, 81, 1.0f, {36, 43, 50, 57}});
}

// Near the upper limit (the D string at 0.8 N of 0.92 N): open strings flatten and have no finger to correct,
// so only stopped notes are checked.
TEST(PluginPitch, CelloStoppedNotesSoundWithinFiveCentsNearTheUpperForceLimit)
{
    checkRange({"cello-plastic", 36, 81, 1.9f, {36, 43, 50, 57}, false});
}

TEST(PluginPitch, ViolinNotesG3ToE7SoundWithinFiveCents)
{
    checkRange({"violin-thermal", 55, 100, 1.0f, {55, 62, 69, 76}});
}

} // namespace ROSIN_FILE_LOCAL
} // namespace rosin::test
