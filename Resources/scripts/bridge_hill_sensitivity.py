#!/usr/bin/env python3
"""How far the bridge hill moves Rosin's sound against a recording: renders the notes as compare_sound.py does,
then moves the statistical body's bridge hill (BodyParameters.cpp: the skeleton's Re Y follows Woodhouse's
bridge-rocking model, Resources/docs/physics.md "The bridge hill") to other frequencies with the same bridge
mass, to first order: the statistical modes radiate a power that follows the skeleton's Re Y, so the radiated
spectrum above the crossover is scaled by sqrt(S_new / S_old), S = 1 / ((1 - x^2)^2 + x^2 / Q^2), x = f / f_h,
Q = 1 / (2 pi f_h m_b Y_v). Prints the envelope distance and the upper partials' difference from the recording
for each hill frequency. The string's own change (the admittance it sees) is left out: a sensitivity, not a
model.

usage: bridge_hill_sensitivity.py ROSIN --body cello|violin --hills 1600,1200,1000,800
"""
import argparse
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import compare_sound as cs  # noqa: E402

# The bodies' statistical recipes (BodyParameters.cpp): crossover Hz, hill Hz, hill Q, skeleton Re Y (s/kg),
# with the notes, program and General MIDI instrument compare_sound.py is run with in the manual.
BODIES = {
    "cello": {"crossover": 550.0, "hill": 1600.0, "q": 1.3, "y": 0.015, "notes": "C2,G2,D3,A3,D4",
              "preset": None, "program": 42},
    "violin": {"crossover": 750.0, "hill": 2600.0, "q": 1.5, "y": 0.035, "notes": "G3,D4,A4,E5",
               "preset": "violin-thermal", "program": 40},
}


def hill_shape(f, hill, q):
    x = f / hill
    return 1.0 / ((1.0 - x * x) ** 2 + x * x / (q * q))


def moved(notes, body, hill):
    """The notes' measures with the hill at `hill` Hz (the same bridge mass): (distance, upper differences)."""
    mass = 1.0 / (2 * np.pi * body["hill"] * body["q"] * body["y"])
    q = 1.0 / (2 * np.pi * hill * mass * body["y"])
    start, end = 0.8 + cs.ONSET, 1.8 + cs.ONSET
    pairs, upper = [], []
    for n in notes:
        x, _, rate = n["audio"]
        f = np.fft.rfftfreq(len(x), 1.0 / rate)
        gain = np.where(f > body["crossover"], np.sqrt(hill_shape(f, hill, q) / hill_shape(f, body["hill"], body["q"])), 1.0)
        ours = cs.measures(np.fft.irfft(np.fft.rfft(x) * gain, len(x)), rate, cs.frequency(n["pitch"]), start, end)
        pairs.append((ours["bands"], n["recording"]["bands"]))
        upper.append(ours["upper"] - n["recording"]["upper"])
    return cs.pooled_distance(pairs), upper, q, mass


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("rosin")
    parser.add_argument("--body", choices=sorted(BODIES), default="cello")
    parser.add_argument("--hills", required=True, help="comma-separated hill frequencies, Hz")
    parser.add_argument("--soundfont", default=cs.SOUNDFONT)
    args = parser.parse_args(argv)
    body = BODIES[args.body]
    try:
        hills = [float(h) for h in args.hills.split(",")]
        notes, distance = cs.compare(args.rosin, [cs.pitch_of(n) for n in body["notes"].split(",")],
                                     body["preset"], body["program"], soundfont=args.soundfont, keep_audio=True)
    except (RuntimeError, ValueError) as e:
        print("bridge_hill_sensitivity: " + str(e), file=sys.stderr)
        return 1
    print("%s (%s) against the recording: %.1f dB with the body's hill at %.0f Hz" %
          (args.body, body["notes"], distance, body["hill"]))
    print("hill Hz   Q     distance dB   h6-16 re h1-3, Rosin minus recording, per note (dB)")
    for hill in hills:
        d, upper, q, _ = moved(notes, body, hill)
        print("%7.0f  %4.2f  %11.1f   %s" % (hill, q, d, " ".join("%+6.1f" % u for u in upper)))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
