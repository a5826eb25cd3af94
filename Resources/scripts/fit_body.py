#!/usr/bin/env python3
"""Fits the body's radiated levels to a recording of your own instrument and writes a program the plugin loads.

usage: fit_body.py ROSIN --notes C2,D3,D4 (--recording C2=c2.wav ... | --soundfont SF2 [--program 42])
                   --out fitted.json [--base PRESET.json] [--hold-out G2,A3] [--iterations 4]
                   [--from 0.8] [--to 1.8] [--velocity 80]

Each recording is one sustained note (a WAV file, analysed from --from to --to seconds into the file); with
--soundfont the notes are rendered by fluidsynth instead. Rosin plays the same notes with the base program
(`rosin render --midi`). What is fitted is a gain curve on the body modes' radiation residues (the program's
"radiationGains", Resources/docs/presets.md): the modes' frequencies, damping and admittance, and so what the
strings feel, stay the modelled body's. The curve is a calibration to that one recording, not physics.

How: per third octave, the recording's level minus Rosin's, each note's levels about their own mean, over the
bands that hold a harmonic of the note (the bands between low harmonics carry the room and the bow noise,
which no radiation gain should chase); averaged over the notes with a shrinkage c / (c + 1) for a band seen by
c notes, smoothed over neighbouring bands (1/4, 1/2, 1/4), limited to +-20 dB, and taken about its mean so the
program's level stays. A mode radiates into the bands above it too, so the fit repeats (--iterations).
Printed: the envelope distance (compare_sound.py's measure) before and after, on the fitted notes and on the
held-out ones. Exit status 0, or 1 when a renderer or a file fails.
"""
import argparse
import json
import os
import sys
import tempfile

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import compare_sound as cs  # noqa: E402

DEFAULT_BASE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "presets", "cello-solo.json")
LIMIT_DB = 20.0


def harmonic_bands(f0):
    """True for the third octaves that hold at least one harmonic of f0."""
    return np.array([any(lo <= k * f0 < hi for k in range(1, int(hi / f0) + 2))
                     for lo, hi in ((fc * 2 ** (-1 / 6), fc * 2 ** (1 / 6)) for fc in cs.BAND_CENTRES)])


def recording_bands(args, pitches):
    """Band levels of the recording of each note."""
    levels = {}
    files = dict(r.split("=", 1) for r in args.recording or [])
    for pitch in pitches:
        name = cs.name_of(pitch)
        if args.soundfont:
            x, rate = cs.render_recording(cs.note(cs.ONSET, args.length, pitch, args.velocity), args.program,
                                          48000, args.soundfont)
            start, end = args.start + cs.ONSET, args.end + cs.ONSET
        elif name in files:
            x, rate = cs.read_wav(files[name])
            start, end = args.start, args.end
        else:
            raise RuntimeError("no recording of %s: give --recording %s=FILE.wav" % (name, name))
        levels[pitch] = cs.measures(x, rate, cs.frequency(pitch), start, end)["bands"]
    return levels


def program(base, gains):
    p = dict(base)
    p["name"] = base.get("name", "program") + "-fitted"
    p["description"] = "radiation fitted to a recording (fit_body.py): a calibration"
    p["radiationGains"] = [{"hz": round(fc, 2), "db": round(float(g), 2)} for fc, g in zip(cs.BAND_CENTRES, gains)]
    return p


def rosin_bands(args, pitches, preset_path):
    out = {}
    for pitch in pitches:
        x, rate = cs.render(args.rosin, cs.note(cs.ONSET, args.length, pitch, args.velocity), preset_path,
                            tail=0.3)
        out[pitch] = cs.measures(x, rate, cs.frequency(pitch), args.start + cs.ONSET, args.end + cs.ONSET)["bands"]
    return out


def distance(ours, theirs, pitches):
    return cs.pooled_distance((ours[pitch], theirs[pitch]) for pitch in pitches)


def step(ours, theirs, pitches):
    """The gain change per band (dB) from one comparison."""
    total, count = np.zeros(len(cs.BAND_CENTRES)), np.zeros(len(cs.BAND_CENTRES))
    for pitch in pitches:
        kept = harmonic_bands(cs.frequency(pitch))
        a, b = theirs[pitch], ours[pitch]
        kept &= (a >= a.max() - cs.BAND_FLOOR_DB) & (b >= b.max() - cs.BAND_FLOOR_DB)
        if not kept.any():
            continue
        residual = (a[kept] - a[kept].mean()) - (b[kept] - b[kept].mean())
        total[kept] += residual
        count[kept] += 1
    mean = np.where(count > 0, total / np.maximum(count, 1), 0.0) * count / (count + 1.0)
    smooth = np.convolve(np.pad(mean, 1, mode="edge"), [0.25, 0.5, 0.25], mode="valid")
    return smooth


def fit(args):
    pitches = [cs.pitch_of(n) for n in args.notes.split(",")]
    held = [cs.pitch_of(n) for n in args.hold_out.split(",")] if args.hold_out else []
    with open(args.base) as f:
        base = json.load(f)
    base.pop("radiationGains", None)
    recorded = recording_bands(args, pitches + held)
    gains = np.zeros(len(cs.BAND_CENTRES))
    with tempfile.TemporaryDirectory() as d:
        path = os.path.join(d, "program.json")

        def render_with(g, notes):
            with open(path, "w") as f:
                json.dump(program(base, g), f)
            return rosin_bands(args, notes, path)

        ours = render_with(gains, pitches + held)
        before = (distance(ours, recorded, pitches), distance(ours, recorded, held))
        for _ in range(args.iterations):
            gains = np.clip(gains + step(ours, recorded, pitches), -LIMIT_DB, LIMIT_DB)
            gains -= gains.mean()
            ours = render_with(gains, pitches)
        ours.update(render_with(gains, held) if held else {})
        after = (distance(ours, recorded, pitches), distance(ours, recorded, held))
    with open(args.out, "w") as f:
        json.dump(program(base, gains), f, indent=2)
        f.write("\n")
    return before, after, gains


def parse(argv):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("rosin")
    parser.add_argument("--notes", required=True)
    parser.add_argument("--recording", action="append", help="NOTE=FILE.wav, one per fitted or held-out note")
    parser.add_argument("--soundfont")
    parser.add_argument("--program", type=int, default=42)
    parser.add_argument("--base", default=DEFAULT_BASE, help="the program to start from (a preset JSON file)")
    parser.add_argument("--out", required=True)
    parser.add_argument("--hold-out", default="")
    parser.add_argument("--iterations", type=int, default=4)
    parser.add_argument("--velocity", type=int, default=80)
    parser.add_argument("--length", type=float, default=2.0)
    parser.add_argument("--from", dest="start", type=float, default=0.8)
    parser.add_argument("--to", dest="end", type=float, default=1.8)
    args = parser.parse_args(argv)
    if not args.soundfont and not args.recording:
        parser.error("give --recording NOTE=FILE.wav for each note, or --soundfont")
    return args


def main(argv):
    args = parse(argv)
    try:
        (fit_before, held_before), (fit_after, held_after), gains = fit(args)
    except (RuntimeError, ValueError, OSError) as e:
        print("fit_body: " + str(e), file=sys.stderr)
        return 1
    print("envelope distance, fitted notes: %.1f -> %.1f dB" % (fit_before, fit_after))
    if args.hold_out:
        print("envelope distance, held-out notes: %.1f -> %.1f dB" % (held_before, held_after))
    print("gains (dB) at " + " ".join("%.0f:%+.1f" % (fc, g) for fc, g in zip(cs.BAND_CENTRES, gains)))
    print("wrote " + args.out)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
