#!/usr/bin/env python3
"""The output figure of Resources/docs/playing.md: the spectrum of one sustained note as the plugin sends it (radiated sound)
against the bridge force it comes from.

usage: output_spectrum.py RADIATED.wav FORCE.wav OUT.png --f0 HZ [--from S] [--to S] [--title TEXT]

Both files are 32-bit float WAVs from `rosin render --midi ... --output radiated|force`. Each spectrum is a
Hann-windowed FFT over the interval, in dB relative to its own strongest component, so the figure compares
shapes (what the body adds), not levels. The harmonics (the strongest bin within 3 % of k f0) are joined by
a line; the full spectra are drawn faintly behind them.
"""
import argparse
import struct
import sys

import numpy as np


def read_float_wav(path):
    data = open(path, "rb").read()
    if data[:4] != b"RIFF" or data[8:12] != b"WAVE":
        sys.exit(f"{path}: not a WAV file")
    i, rate = 12, None
    while i + 8 <= len(data):
        cid, size = data[i:i + 4], struct.unpack("<I", data[i + 4:i + 8])[0]
        if cid == b"fmt ":
            fmt, channels, rate = struct.unpack("<HHI", data[i + 8:i + 16])
            if fmt != 3:
                sys.exit(f"{path}: expected 32-bit float samples (format 3), found format {fmt}")
        elif cid == b"data":
            if rate is None:
                sys.exit(f"{path}: data chunk before fmt chunk")
            return np.frombuffer(data[i + 8:i + 8 + size], dtype="<f4")[::channels].astype(float), rate
        i += 8 + size + (size & 1)
    sys.exit(f"{path}: no data chunk")


def spectrum_db(x, rate, start, stop):
    segment = x[int(start * rate):int(stop * rate)]
    if len(segment) < 1024:
        sys.exit(f"interval {start}-{stop} s holds only {len(segment)} samples")
    magnitude = np.abs(np.fft.rfft(segment * np.hanning(len(segment))))
    frequency = np.fft.rfftfreq(len(segment), 1.0 / rate)
    return frequency, 20.0 * np.log10(np.maximum(magnitude / magnitude.max(), 1e-9))


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("radiated")
    parser.add_argument("force")
    parser.add_argument("out")
    parser.add_argument("--from", dest="start", type=float, default=0.8)
    parser.add_argument("--to", dest="stop", type=float, default=1.8)
    parser.add_argument("--title", default="")
    parser.add_argument("--f0", type=float, required=True, help="the note's fundamental, Hz")
    args = parser.parse_args()
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(8, 4))
    for path, label, style in ((args.force, "bridge force (what the string does to the body)", "0.6"),
                               (args.radiated, "radiated sound at 1 m (what the plugin sends)", "C0")):
        x, rate = read_float_wav(path)
        f, db = spectrum_db(x, rate, args.start, args.stop)
        ax.semilogx(f[1:], db[1:], color=style, linewidth=0.5, alpha=0.35)
        harmonics, levels = [], []
        k = 1
        while k * args.f0 * 1.03 < min(12000.0, rate / 2):
            band = (f > k * args.f0 / 1.03) & (f < k * args.f0 * 1.03)
            harmonics.append(k * args.f0)
            levels.append(db[band].max())
            k += 1
        ax.semilogx(harmonics, levels, "o-", color=style, markersize=3, linewidth=1.2, label=label)
    ax.set_xlim(20, 12000)
    ax.set_ylim(-90, 5)
    ax.set_xlabel("frequency (Hz)")
    ax.set_ylabel("level re strongest component (dB)")
    ax.set_title(args.title)
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(loc="lower left")
    fig.tight_layout()
    fig.savefig(args.out, dpi=110)


if __name__ == "__main__":
    main()
