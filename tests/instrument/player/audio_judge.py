"""Judging rendered notes from the audio alone: MIDI files written for `rosin render --midi`, a pitch track,
and the playability verdict of a note (clean = periodic at the note's period in its lowest 8 harmonics;
playable = clean from at most 150 ms after its onset to its end, at a median pitch within 25 cents of the
note).

Used by the acceptance tests beside it; runnable as a script to print the grid table of the manual's
playing page (Resources/docs/playing.md, "How playable it is").
"""
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "..", "Resources",
                                "scripts"))
from compare_sound import (cc, frequency, note, read_wav, render, render_recording,  # noqa: E402,F401
                           write_midi)


def periodicity(x, rate, f0, cents=60.0):
    """(best normalised autocorrelation, its frequency) of frame x at lags within +-cents of 1/f0."""
    x = x - x.mean()
    lo = int(np.floor(rate / (f0 * 2 ** (cents / 1200))))
    hi = int(np.ceil(rate / (f0 * 2 ** (-cents / 1200))))
    n = len(x) - hi - 1
    if n < lo or not np.any(x):
        return 0.0, f0
    a = x[:n]
    ea = np.dot(a, a)
    best, lag = -1.0, lo
    scores = []
    for k in range(lo - 1, hi + 2):
        b = x[k:k + n]
        s = np.dot(a, b) / np.sqrt(ea * np.dot(b, b) + 1e-30)
        scores.append(s)
    scores = np.array(scores)
    i = int(np.argmax(scores[1:-1])) + 1
    best = scores[i]
    denom = scores[i - 1] - 2 * scores[i] + scores[i + 1]
    shift = 0.5 * (scores[i - 1] - scores[i + 1]) / denom if denom < 0 else 0.0
    lag = lo - 1 + i + shift
    return float(best), rate / lag


def pitch_track(x, rate, f0, start, end, hop=0.005, periods=2.2, cents=60.0):
    """Times, frequencies and periodicity of frames from `start` to `end` seconds near f0. A frame holds
    `periods` periods, so each period is compared with the next: vibrato (the pitch moves by at most a few
    cents in a period) keeps a Helmholtz note periodic, a scratch is not."""
    length = int(periods * rate / f0 * 2 ** (cents / 1200)) + 2
    times, freqs, scores = [], [], []
    t = start
    while t + length / rate <= end:
        i = int(t * rate)
        s, f = periodicity(x[i:i + length], rate, f0, cents)
        times.append(t + 0.5 * length / rate)
        freqs.append(f)
        scores.append(s)
        t += hop
    return np.array(times), np.array(freqs), np.array(scores)


def low_partials_cents(x, rate, f0, start, end, partials=6):
    """Pitch in cents against f0 from the frequencies of harmonics 1..partials between `start` and `end`
    seconds, each f_n / n weighted by its amplitude. A stiff string's free partials are stretched (the
    cello D3's 15th lies 11 cents sharp), and the ear takes the pitch of such a tone from its lower
    harmonics (the dominance region, Ritsma 1967: harmonics 3-5), whereas an autocorrelation over two
    periods is pulled sharp by the upper ones. A bowed note's partials are locked harmonic: there both agree."""
    seg = x[int(start * rate):int(end * rate)]
    seg = (seg - seg.mean()) * np.hanning(len(seg))
    size = 1 << 20
    spectrum = np.abs(np.fft.rfft(seg, size))
    bin_hz = rate / size
    weighted = weights = 0.0
    for n in range(1, partials + 1):
        lo, hi = int(n * f0 * 0.97 / bin_hz), int(n * f0 * 1.03 / bin_hz)
        k = lo + int(np.argmax(spectrum[lo:hi]))
        a, b, c = np.log(spectrum[k - 1:k + 2] + 1e-30)
        fn = (k + 0.5 * (a - c) / (a - 2 * b + c)) * bin_hz
        weighted += spectrum[k] * 1200 * np.log2(fn / (n * f0))
        weights += spectrum[k]
    return weighted / weights


CLEAN = 0.9  # normalised autocorrelation at the period: Helmholtz motion scores > 0.97, a scratch < 0.8
# The harmonics a note's steadiness is heard in: the ear resolves a complex tone's first 5-8 partials and takes
# its pitch from them (Plomp 1964; the dominance region, harmonics 3-5, Ritsma 1967); above them the bow's
# noise, which a recorded cello has too, is heard as noise, not as an unsteady note. On the FluidR3 cello the
# period-to-period test passes 44 of 44 notes on harmonics 1-5 or 1-8, 40 on 1-10, 36 on the whole band.
HEARD_HARMONICS = 8


def heard(x, rate, f0):
    """x through a zero-phase 4th-order Butterworth low-pass at HEARD_HARMONICS f0."""
    from scipy.signal import butter, sosfiltfilt
    sos = butter(4, min(HEARD_HARMONICS * f0, 0.45 * rate), fs=rate, output="sos")
    return sosfiltfilt(sos, x)


def judge(x, rate, pitch, onset, offset, settle=0.15):
    """{'playable', 'clean_from' (s after onset, None if never), 'cents' (median)} of one note, judged on the
    harmonics it is heard in (heard())."""
    f0 = frequency(pitch)
    times, freqs, scores = pitch_track(heard(x, rate, f0), rate, f0, onset, offset, hop=0.01)
    if len(times) == 0:
        return {"playable": False, "clean_from": None, "cents": float("nan")}
    clean = scores > CLEAN
    clean_from = None
    for i in range(len(clean)):
        if clean[i:].all():
            clean_from = times[i] - onset
            break
    held = clean if clean.any() else np.ones_like(clean)
    cents = float(np.median(1200 * np.log2(freqs[held] / f0)))
    playable = clean_from is not None and clean_from <= settle and abs(cents) <= 25
    return {"playable": playable, "clean_from": clean_from, "cents": cents}


GRID_PITCHES = list(range(36, 68, 3))  # every minor third from C2 to G4: 11 notes
GRID_VELOCITIES = (30, 64, 100, 127)
NOTE_SECONDS = 0.8


RECORDING = "--recording"  # in place of the rosin binary: the FluidR3 cello


def judge_note(rosin, pitch, velocity, controllers=(), preset=None, extra=(), settle=0.15):
    """One detached note rendered on its own (a string left ringing by an earlier note would make the next
    one aperiodic), after `controllers` ((number, value), ...) at t = 0."""
    events = [e for number, value in controllers for e in cc(0.0, number, value)]
    events += note(0.2, NOTE_SECONDS, pitch, velocity)
    if rosin == RECORDING:
        x, rate = render_recording(events)
    else:
        x, rate = render(rosin, events, preset, extra, tail=0.1)
    return judge(x, rate, pitch, 0.2, 0.2 + NOTE_SECONDS, settle)


def judge_grid(rosin, controllers=(), preset=None, extra=(), jobs=2, pitches=GRID_PITCHES, settle=0.15):
    """The 44 detached notes with these controllers: list of (pitch, velocity, verdict)."""
    from concurrent.futures import ThreadPoolExecutor
    cases = [(p, v) for v in GRID_VELOCITIES for p in pitches]
    with ThreadPoolExecutor(jobs) as pool:
        verdicts = pool.map(lambda c: judge_note(rosin, c[0], c[1], controllers, preset, extra, settle), cases)
        return [(p, v, j) for (p, v), j in zip(cases, verdicts)]


if __name__ == "__main__":
    # audio_judge.py ROSIN [render options]: the grid table; audio_judge.py --recording: the same judge on
    # the FluidR3 cello's recording (one sample set per note, so every velocity plays the same).
    rosin = sys.argv[1]
    settings = [(), ((11, 20),), ((11, 110),), ((1, 20),), ((1, 110),), ((1, 110), (11, 30)),
                ((1, 30), (11, 30)), ((1, 100), (11, 100))]
    if os.environ.get("ROSIN_SETTINGS") == "no-vibrato":
        settings = [((1, 0),), ((1, 0), (11, 20)), ((1, 0), (11, 64)), ((1, 0), (11, 110))]
    if rosin == RECORDING:
        settings = [()]  # a sample player's CC1 and CC11 are not a bow
    for controllers in settings:
        preset = os.environ.get("ROSIN_PRESET")
        lowest = int(os.environ.get("ROSIN_LOWEST", GRID_PITCHES[0]))
        verdicts = judge_grid(rosin, controllers, preset=preset, extra=sys.argv[2:],
                              pitches=[lowest + 3 * i for i in range(len(GRID_PITCHES))])
        good = sum(1 for _, _, j in verdicts if j["playable"])
        bad = ["%d/%d(%s,%+.0fc)" % (p, v, "-" if j["clean_from"] is None else "%.2f" % j["clean_from"],
                                    j["cents"]) for p, v, j in verdicts if not j["playable"]]
        print("%s: %d of %d playable; not: %s" % (" ".join("CC%d %d" % c for c in controllers) or "reset", good, len(verdicts), " ".join(bad)))
