#!/usr/bin/env python3
"""Rosin's sustained notes against a recorded instrument: renders the notes with `rosin render --midi`, renders
the same MIDI through a General MIDI soundfont with fluidsynth (Debian's FluidR3: sampled recordings), and
prints, per note and over all of them:

- the spectral-envelope distance: third-octave band levels from 80 Hz to 10 kHz over the analysis interval,
  each note's levels taken about their own mean, the rms difference in dB over bands and notes (a band more
  than 50 dB below the note's loudest band in both sounds is left out);
- the harmonic profile: the power of harmonics 6-16 against that of harmonics 1-3, in dB, for both;
- the spectral centroid (power-weighted, Hz) of both.

usage: compare_sound.py ROSIN --notes C2,G2,D3,A3,D4 [--preset P] [--program 42] [--figure OUT.png]
                        [--json OUT.json] [--velocity 80] [--length 2] [--from 0.8] [--to 1.8]
                        [--soundfont SF2] [-- RENDER OPTIONS]

ROSIN may be another soundfont (a path ending in .sf2 or .sf3): then two recordings are compared, which
says how far apart two instruments of the same kind lie on these measures.

The recording is one instrument through one microphone: nothing here fits anything to it. Options after
`--` go to `rosin render` (e.g. `--output force`). Exit status: 0, or 1 when a renderer fails.
"""
import argparse
import json
import os
import subprocess
import sys
import tempfile
import warnings

import numpy as np

import smf

TICKS = 480  # per quarter note at 120 bpm: a tick is 1/960 s
SOUNDFONT = "/usr/share/sounds/sf2/FluidR3_GM.sf2"
NOTE_NAMES = {"C": 0, "D": 2, "E": 4, "F": 5, "G": 7, "A": 9, "B": 11}
BAND_CENTRES = [10.0 ** (n / 10.0) for n in range(19, 41)]  # 79.4 Hz .. 10 kHz, the nominal third octaves
BAND_FLOOR_DB = 50.0
ONSET = 0.2  # s: each note starts here


def write_midi(path, events):
    """events: (seconds, status, data1, data2) in any order (data2 None for a program change); written as
    one track at 120 bpm."""
    events = sorted(events, key=lambda e: (e[0], 0 if (e[1] & 0xF0) in (0x80, 0xB0, 0xC0) else 1))
    track = bytearray(b"\x00\xff\x51\x03\x07\xa1\x20")  # 500000 us per quarter
    now = 0
    for seconds, status, a, b in events:
        tick = int(round(seconds * 2 * TICKS))
        track += smf.encode_varlen(tick - now) + bytes([status, a] if b is None else [status, a, b])
        now = tick
    track += b"\x00\xff\x2f\x00"
    with open(path, "wb") as f:
        f.write(b"MThd" + (6).to_bytes(4, "big") + (0).to_bytes(2, "big") + (1).to_bytes(2, "big") +
                TICKS.to_bytes(2, "big"))
        f.write(b"MTrk" + len(track).to_bytes(4, "big") + track)


def note(start, length, pitch, velocity, channel=0):
    return [(start, 0x90 | channel, pitch, velocity), (start + length, 0x80 | channel, pitch, 0)]


def cc(seconds, number, value, channel=0):
    return [(seconds, 0xB0 | channel, number, value)]


def read_wav(path):
    import scipy.io.wavfile
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # rosin writes a chunk scipy does not know
        rate, x = scipy.io.wavfile.read(path)
    scale = float(np.iinfo(x.dtype).max) + 1.0 if x.dtype.kind == "i" else 1.0
    x = x.astype(float) / scale
    return (x if x.ndim == 1 else x[:, 0]), rate


def render(rosin, events, preset=None, extra=(), tail=0.5):
    """Renders `events` with `rosin render --midi`: (audio, sample rate)."""
    with tempfile.TemporaryDirectory() as d:
        mid, wav = os.path.join(d, "in.mid"), os.path.join(d, "out.wav")
        write_midi(mid, events)
        args = [rosin, "render", "--midi", mid, "--out", wav, "--tail", str(tail)]
        if preset:
            args += ["--preset", preset]
        done = subprocess.run(args + list(extra), capture_output=True, text=True)
        if done.returncode != 0:
            raise RuntimeError("rosin render failed: " + done.stderr)
        return read_wav(wav)


def render_recording(events, program=42, rate=48000, soundfont=SOUNDFONT):
    """Renders `events` with fluidsynth from the soundfont's General MIDI `program` (42 cello, 40 violin),
    reverb and chorus off."""
    with tempfile.TemporaryDirectory() as d:
        mid, wav = os.path.join(d, "in.mid"), os.path.join(d, "out.wav")
        write_midi(mid, [(0.0, 0xC0, program, None)] + list(events))
        done = subprocess.run(["fluidsynth", "-ni", "-q", "-R", "0", "-C", "0", "-r", str(rate), "-F", wav,
                               soundfont, mid], capture_output=True, text=True)
        if done.returncode != 0 or not os.path.exists(wav):
            raise RuntimeError("fluidsynth failed: " + done.stderr)
        return read_wav(wav)


def pitch_of(name):
    """MIDI note number of a name such as C2, F#3 or Bb4 (C4 = 60)."""
    letter, rest = name[0].upper(), name[1:]
    if letter not in NOTE_NAMES or not rest:
        raise ValueError("note %r: expected a letter A-G, an optional # or b and an octave" % name)
    shift = 0
    while rest and rest[0] in "#b":
        shift += 1 if rest[0] == "#" else -1
        rest = rest[1:]
    return 12 * (int(rest) + 1) + NOTE_NAMES[letter] + shift


def frequency(pitch):
    return 440.0 * 2.0 ** ((pitch - 69) / 12.0)


def power_spectrum(x, rate, start, end):
    held = x[int(start * rate):int(end * rate)]
    if len(held) < 1024:
        raise ValueError("interval %.2f-%.2f s holds only %d samples" % (start, end, len(held)))
    power = np.abs(np.fft.rfft((held - held.mean()) * np.hanning(len(held)))) ** 2
    return np.fft.rfftfreq(len(held), 1.0 / rate), power


def band_levels(frequencies, power):
    """Third-octave band levels (dB, arbitrary reference) at BAND_CENTRES."""
    edges = [(fc * 2 ** (-1 / 6), fc * 2 ** (1 / 6)) for fc in BAND_CENTRES]
    return np.array([10 * np.log10(power[(frequencies >= lo) & (frequencies < hi)].sum() + 1e-30)
                     for lo, hi in edges])


def harmonic_power(frequencies, power, f0, n):
    """Power within a quarter of f0 of harmonic n: room for vibrato's spread, none for the neighbours."""
    return power[np.abs(frequencies - n * f0) < 0.25 * f0].sum()


def measures(x, rate, f0, start, end):
    """{'bands': dB per third octave, 'upper': harmonics 6-16 against 1-3 (dB), 'centroid': Hz}."""
    frequencies, power = power_spectrum(x, rate, start, end)
    low = sum(harmonic_power(frequencies, power, f0, n) for n in range(1, 4))
    high = sum(harmonic_power(frequencies, power, f0, n) for n in range(6, 17))
    audible = (frequencies > 50.0) & (frequencies < 10000.0)
    return {"bands": band_levels(frequencies, power),
            "upper": float(10 * np.log10(high / low)),
            "centroid": float((frequencies[audible] * power[audible]).sum() / power[audible].sum())}


def envelope_differences(a, b):
    """Per-band differences (dB) of two notes' band levels, each about its own mean, over the bands that
    lie within BAND_FLOOR_DB of the loudest band in at least one of them."""
    kept = (a >= a.max() - BAND_FLOOR_DB) | (b >= b.max() - BAND_FLOOR_DB)
    return (a[kept] - a[kept].mean()) - (b[kept] - b[kept].mean()), kept


def pooled_distance(pairs):
    """The envelope distance (dB) over (ours, theirs) band-level pairs of several notes: the rms of every
    kept band's difference; nan when there are none."""
    pooled = [d for ours, theirs in pairs for d in envelope_differences(ours, theirs)[0]]
    return float(np.sqrt(np.mean(np.square(pooled)))) if pooled else float("nan")


def compare(rosin, pitches, preset=None, program=42, velocity=80, length=2.0, start=0.8, end=1.8,
            extra=(), soundfont=SOUNDFONT, keep_audio=False):
    """Per note: both sounds' measures and the envelope differences; and the overall distance (dB). The
    analysis runs from `start` to `end` seconds after the note-on."""
    notes = []
    start, end = start + ONSET, end + ONSET
    for pitch in pitches:
        events = note(ONSET, length, pitch, velocity)
        if rosin.endswith((".sf2", ".sf3")):  # two recordings compared with each other
            x, rate = render_recording(events, program, 48000, rosin)
        else:
            x, rate = render(rosin, events, preset, extra, tail=0.3)
        y, yrate = render_recording(events, program, rate, soundfont)
        f0 = frequency(pitch)
        ours, theirs = measures(x, rate, f0, start, end), measures(y, yrate, f0, start, end)
        differences, kept = envelope_differences(ours["bands"], theirs["bands"])
        entry = {"pitch": pitch, "rosin": ours, "recording": theirs, "kept": kept,
                 "distance": float(np.sqrt(np.mean(differences ** 2)))}
        if keep_audio:
            entry["audio"] = (x, y, rate)
        notes.append(entry)
    return notes, pooled_distance((n["rosin"]["bands"], n["recording"]["bands"]) for n in notes)


def name_of(pitch):
    names = ["C", "C#", "D", "D#", "E", "F", "F#", "G", "G#", "A", "A#", "B"]
    return "%s%d" % (names[pitch % 12], pitch // 12 - 1)


def draw(notes, path, start, end):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(len(notes), 1, figsize=(8, 2.2 * len(notes)), sharex=True, squeeze=False)
    for ax, n in zip(axes[:, 0], notes):
        x, y, rate = n["audio"]
        for signal, label, colour in ((y, "recording", "0.45"), (x, "Rosin", "C0")):
            f, p = power_spectrum(signal, rate, start, end)
            db = 10 * np.log10(p / p.max() + 1e-12)
            ax.semilogx(f[1:], db[1:], color=colour, linewidth=0.6, label=label)
        ax.set_ylim(-80, 3)
        ax.set_ylabel("dB re peak")
        ax.set_title("%s: envelope distance %.1f dB, harmonics 6-16 re 1-3: Rosin %+.1f, recording %+.1f dB"
                     % (name_of(n["pitch"]), n["distance"], n["rosin"]["upper"], n["recording"]["upper"]),
                     fontsize=9)
        ax.grid(True, which="both", alpha=0.3)
    axes[0, 0].legend(loc="upper right")
    axes[-1, 0].set_xlim(50, 12000)
    axes[-1, 0].set_xlabel("frequency (Hz)")
    fig.tight_layout()
    fig.savefig(path, dpi=100)


def main(argv):
    extra = []
    if "--" in argv:
        extra = argv[argv.index("--") + 1:]
        argv = argv[:argv.index("--")]
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("rosin")
    parser.add_argument("--notes", required=True, help="comma-separated note names, e.g. C2,G2,D3")
    parser.add_argument("--preset")
    parser.add_argument("--program", type=int, default=42, help="General MIDI program (42 cello, 40 violin)")
    parser.add_argument("--soundfont", default=SOUNDFONT)
    parser.add_argument("--velocity", type=int, default=80)
    parser.add_argument("--length", type=float, default=2.0, help="note length, s")
    parser.add_argument("--from", dest="start", type=float, default=0.8, help="analysis start, s")
    parser.add_argument("--to", dest="end", type=float, default=1.8, help="analysis end, s")
    parser.add_argument("--figure")
    parser.add_argument("--json")
    args = parser.parse_args(argv)
    try:
        pitches = [pitch_of(n) for n in args.notes.split(",")]
    except ValueError as e:
        parser.error(str(e))
    try:
        notes, distance = compare(args.rosin, pitches, args.preset, args.program, args.velocity, args.length,
                                  args.start, args.end, extra, args.soundfont,
                                  keep_audio=bool(args.figure))
    except (RuntimeError, ValueError) as e:
        print("compare_sound: " + str(e), file=sys.stderr)
        return 1
    print("note  distance dB  h6-16 re h1-3 dB (Rosin, recording, difference)  centroid Hz (Rosin, recording)")
    for n in notes:
        r, c = n["rosin"], n["recording"]
        print("%-4s  %11.1f  %+8.1f %+8.1f %+8.1f  %12.0f %9.0f" % (name_of(n["pitch"]), n["distance"], r["upper"],
              c["upper"], r["upper"] - c["upper"], r["centroid"], c["centroid"]))
    print("envelope distance over all notes: %.1f dB" % distance)
    if args.figure:
        draw(notes, args.figure, args.start + ONSET, args.end + ONSET)
    if args.json:
        with open(args.json, "w") as f:
            json.dump({"distance": distance, "notes": [
                {"note": name_of(n["pitch"]), "distance": n["distance"],
                 "rosin": {"upper": n["rosin"]["upper"], "centroid": n["rosin"]["centroid"],
                           "bands": n["rosin"]["bands"].tolist()},
                 "recording": {"upper": n["recording"]["upper"], "centroid": n["recording"]["centroid"],
                               "bands": n["recording"]["bands"].tolist()}} for n in notes],
                "bandCentresHz": BAND_CENTRES}, f, indent=1)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
