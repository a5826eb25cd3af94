#!/usr/bin/env python3
"""The measures that compare Rosin with recordings (Resources/scripts/compare_sound.py), checked where the
answer is known:

- On synthetic tones whose spectra are written down: the harmonic profile (harmonics 6-16 against 1-3) of
  a sawtooth (amplitudes 1/n) and of a flat-spectrum pulse train equals the sums of their harmonics'
  powers, and the envelope distance of the two equals the one computed from their harmonics band by band.
- A sound against itself: 0 dB, and a fluidsynth render is the same twice.
- Two recordings of the cello from different sample sets (Debian's FluidR3 and MuseScore General Lite)
  are told apart (more than 3 dB) without being worlds apart (less than 12 dB); printed beside it, how far
  one set lies from itself a semitone up, each note against its neighbour: the measure's floor for one
  instrument.

Usage: recordings_test.py [ROSIN]
"""
import os
import sys
import unittest

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "support"))
import debian_python  # noqa: E402

debian_python.ensure("numpy", "scipy")

import numpy as np  # noqa: E402

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "..", "Resources",
                                "scripts"))
import compare_sound as cs  # noqa: E402

RATE = 48000
MUSESCORE = "/usr/share/sounds/sf3/MuseScore_General_Lite.sf3"


def tone(f0, amplitude, seconds=1.0):
    t = np.arange(int(seconds * RATE)) / RATE
    return sum(amplitude(n) * np.sin(2 * np.pi * n * f0 * t) for n in range(1, int(10000 / f0)))


def band_levels_of_harmonics(f0, amplitude):
    """Third-octave levels computed from the harmonics themselves (power a^2 / 2 each)."""
    levels = []
    for fc in cs.BAND_CENTRES:
        lo, hi = fc * 2 ** (-1 / 6), fc * 2 ** (1 / 6)
        power = sum(amplitude(n) ** 2 / 2 for n in range(1, int(10000 / f0)) if lo <= n * f0 < hi)
        levels.append(10 * np.log10(power + 1e-30))
    return np.array(levels)


class SyntheticTones(unittest.TestCase):
    F0 = 110.0
    SAW = staticmethod(lambda n: 1.0 / n)
    FLAT = staticmethod(lambda n: 0.1)

    def test_harmonic_profile_is_the_sum_of_the_harmonics(self):
        for amplitude in (self.SAW, self.FLAT):
            expected = 10 * np.log10(sum(amplitude(n) ** 2 for n in range(6, 17)) /
                                     sum(amplitude(n) ** 2 for n in range(1, 4)))
            measured = cs.measures(tone(self.F0, amplitude), RATE, self.F0, 0.0, 1.0)["upper"]
            self.assertAlmostEqual(measured, expected, delta=0.1)

    def test_envelope_distance_is_the_band_by_band_difference(self):
        saw = cs.measures(tone(self.F0, self.SAW), RATE, self.F0, 0.0, 1.0)["bands"]
        flat = cs.measures(tone(self.F0, self.FLAT), RATE, self.F0, 0.0, 1.0)["bands"]
        measured, _ = cs.envelope_differences(saw, flat)
        expected, _ = cs.envelope_differences(band_levels_of_harmonics(self.F0, self.SAW),
                                              band_levels_of_harmonics(self.F0, self.FLAT))
        print("[ figures  ] sawtooth against a flat spectrum: %.2f dB (from the harmonics: %.2f dB)" % (
            np.sqrt(np.mean(measured ** 2)), np.sqrt(np.mean(expected ** 2))))
        # A Hann window leaks a little of a harmonic next to a band edge into the neighbouring band.
        self.assertAlmostEqual(np.sqrt(np.mean(measured ** 2)), np.sqrt(np.mean(expected ** 2)), delta=0.5)
        self.assertGreater(np.sqrt(np.mean(expected ** 2)), 5.0)  # the two really differ


class Recordings(unittest.TestCase):
    CELLO = [cs.pitch_of(n) for n in ("C2", "G2", "D3", "A3", "D4")]

    def test_a_recording_against_itself_is_zero(self):
        notes, distance = cs.compare(cs.SOUNDFONT, self.CELLO[:2])
        self.assertEqual(distance, 0.0)
        self.assertTrue(all(n["rosin"]["upper"] == n["recording"]["upper"] for n in notes))

    def test_two_sample_sets_of_one_instrument_differ_moderately(self):
        _, between = cs.compare(MUSESCORE, self.CELLO)
        # One set against itself a semitone away (each note from its neighbour's sample, transposed).
        within = []
        for pitch in self.CELLO:
            x, rate = cs.render_recording(cs.note(cs.ONSET, 2.0, pitch, 80))
            y, _ = cs.render_recording(cs.note(cs.ONSET, 2.0, pitch + 1, 80))
            a = cs.measures(x, rate, cs.frequency(pitch), 1.0, 2.0)["bands"]
            b = cs.measures(y, rate, cs.frequency(pitch + 1), 1.0, 2.0)["bands"]
            within.extend(cs.envelope_differences(a, b)[0])
        within = float(np.sqrt(np.mean(np.square(within))))
        print("[ figures  ] cello C2-D4: FluidR3 against MuseScore General %.1f dB; FluidR3 against itself a "
              "semitone up %.1f dB" % (between, within))
        self.assertGreater(between, 3.0)
        self.assertLess(between, 12.0)


if __name__ == "__main__":
    if len(sys.argv) > 1 and not sys.argv[1].startswith("-"):
        sys.argv.pop(1)  # the rosin binary: not needed by these checks
    unittest.main(verbosity=2)
