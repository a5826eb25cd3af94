#!/usr/bin/env python3
"""Tests of Source/lab/figures/plot_scan.py on synthetic scans (unittest).

Synthetic data follow Resources/docs/scan-format.md: a Schelleng grid whose
Helmholtz cells lie between d/beta^2 and c/beta, and Guettler grids whose
transient lengths come from a wedge-shaped formula, with empty cells.
"""

import json
import math
import os
import subprocess
import sys
import tempfile
import unittest


sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "support"))
import debian_python  # noqa: E402

debian_python.ensure("matplotlib")

import numpy as np  # noqa: E402
from matplotlib import image  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__)))))
FIGURES = os.path.join(ROOT, "Source", "lab", "figures")
SCRIPT = os.path.join(FIGURES, "plot_scan.py")
sys.path.insert(0, FIGURES)

import scan_style  # noqa: E402

HEADER = ("cell,beta,bowForce,{third},regime,transientPeriods,muStatic,jump,"
          "firstSlipTime,slipsPerPeriod,pitchCents,failure")
SEED_BETAS = [0.0357, 0.0449, 0.0566, 0.0714, 0.0899, 0.1133, 0.1428, 0.18]
FMAX_C, FMIN_D = 0.068, 0.0015


def fmt(value):
    return "" if value is None or (isinstance(value, float) and math.isnan(value)) \
        else f"{value:.9g}"


def write_scan(directory, kind, rows, meta):
    os.makedirs(directory, exist_ok=True)
    third = "bowSpeed" if kind == "schelleng" else "acceleration"
    with open(os.path.join(directory, "scan.csv"), "w", encoding="utf-8") as out:
        out.write(HEADER.format(third=third) + "\n")
        for row in rows:
            out.write(",".join(v if isinstance(v, str) else fmt(v) for v in row) + "\n")
    with open(os.path.join(directory, "scan.json"), "w", encoding="utf-8") as out:
        json.dump(meta, out, indent=2)


def schelleng_regime(beta, force, shift):
    """Helmholtz between the theory lines; the other regimes around them."""
    fmax, fmin = FMAX_C * shift / beta, FMIN_D * shift / beta ** 2
    if fmin < force < fmax:
        return "s-motion" if force > 0.8 * fmax else "helmholtz"
    if force >= fmax:
        return "alf" if beta > 0.1 and force > 2 * fmax else "raucous"
    if force < fmin / 6:
        return "no-slip" if beta < 0.04 else "constant-slipping"
    return "multiple-slipping" if force < fmin / 3 else "double-slipping"


def make_schelleng(directory, n_beta=20, n_force=20, shift=1.0):
    betas = list(np.geomspace(0.02, 0.18, n_beta))
    forces = list(np.geomspace(0.1, 3.0, n_force))
    rows, helmholtz = [], 0
    for ib, beta in enumerate(betas):
        for i_f, force in enumerate(forces):
            regime = schelleng_regime(beta, force, shift)
            helmholtz += regime == "helmholtz"
            slipped = regime != "no-slip"
            mu = 1.2 - 0.15 * math.log10(force / 0.1) + 0.3 * beta if slipped else None
            jump = 0.2 + 0.25 * math.log10(force / 0.1) if slipped else None
            rows.append([ib * n_force + i_f, beta, force, 0.05, regime,
                         2.0 if regime == "helmholtz" else None, mu, jump,
                         0.01 if slipped else None, 1 if regime == "helmholtz" else None,
                         -3.0 if regime == "helmholtz" else None,
                         "none" if slipped else ""])
    cells = n_beta * n_force
    meta = base_meta("schelleng", {"betas": betas, "forces": forces, "bowSpeeds": [0.05]},
                     cells, helmholtz)
    meta["theory"].update(bowSpeed=0.05, fmaxCoefficient=FMAX_C, fminCoefficient=FMIN_D)
    meta["boundaries"] = {
        "upper": {"slope": -1.05, "intercept": math.log10(FMAX_C * 0.8), "points": 14},
        "lower": {"slope": -1.9, "intercept": math.log10(FMIN_D * 1.1), "points": 12}}
    write_scan(directory, "schelleng", rows, meta)


def guettler_wedge(beta, mu_s=1.2, mu_d=0.35, pz0=3.73e-3):
    """[Notes] eq. 6.6: acceleration per newton at the wedge's lower and upper edge."""
    k = beta * (1 - beta) / pz0
    lower = k * (3 * mu_s - mu_d - 2 * math.sqrt(2 * mu_s ** 2 - mu_s * mu_d))
    upper = k * ((3 - 4 * beta) * mu_s - mu_d - 2 * math.sqrt(
        (1 - 2 * beta) * (2 * (1 - beta) * mu_s ** 2 - mu_s * mu_d))) / (1 - 2 * beta)
    return lower, upper


def guettler_cell(beta, force, accel, shift):
    """(transientPeriods or None, slipped): short inside a widened wedge, longer at its edges."""
    lower, upper = guettler_wedge(beta)
    ratio = accel / force / shift
    centre, half = math.sqrt(lower * upper), 0.9 * math.log(upper / lower) + 0.35
    distance = abs(math.log(ratio / centre)) / half
    if accel < 0.2 and force > 2.5:
        return None, False  # synthetic "never slipped" corner
    if distance >= 1.0:
        return None, True
    return 19.0 * distance ** 2 + 0.5 * (force - 0.4), True


def make_guettler(directory, betas=None, n_force=20, n_accel=20, shift=1.0):
    betas = list(betas or SEED_BETAS)
    forces = list(np.linspace(0.4, 3.2, n_force))
    accels = list(np.linspace(0.08, 3.2, n_accel))
    rows, helmholtz, reached = [], 0, 0
    for ib, beta in enumerate(betas):
        for i_f, force in enumerate(forces):
            for ia, accel in enumerate(accels):
                periods, slipped = guettler_cell(beta, force, accel, shift)
                regime = "helmholtz" if periods is not None else (
                    "raucous" if slipped else "no-slip")
                helmholtz += regime == "helmholtz"
                reached += periods is not None
                mu = 1.3 - 0.15 * accel if slipped else None
                jump = 0.1 + 0.12 * force - 0.03 * accel if slipped else None
                failure = "none" if periods is not None else (
                    "prolonged-sticking" if accel / force < 1.5 else "multiple-slipping")
                rows.append([(ib * n_force + i_f) * n_accel + ia, beta, force, accel, regime,
                             periods, mu, jump, 0.1 if slipped else None, None, None,
                             failure if slipped else ""])
    cells = len(betas) * n_force * n_accel
    meta = base_meta("guettler", {"betas": betas, "forces": forces, "accelerations": accels},
                     cells, helmholtz)
    meta["reachedFraction"] = reached / cells
    meta["theory"]["guettlerWedge"] = [
        {"beta": b, "lowerAccelerationPerNewton": guettler_wedge(b)[0],
         "upperAccelerationPerNewton": guettler_wedge(b)[1]} for b in betas]
    write_scan(directory, "guettler", rows, meta)


def base_meta(kind, grid, cells, helmholtz):
    names = ["schelleng.png"] if kind == "schelleng" else ["guettler.png"]
    return {"format": "rosin-scan/1", "kind": kind, "preset": "galluzzo-rig",
            "friction": "classical", "string": "cello-D3", "sampleRate": 48000,
            "trialSeconds": 0.5, "variations": {"torsion": True, "bendingStiffness": True,
                                                "rigidBridge": False},
            "grid": grid, "cells": cells, "helmholtzCells": helmholtz,
            "helmholtzFraction": helmholtz / cells,
            "theory": {"Z0": 0.63, "bridgeResistance": 100.0, "muStatic": 1.2,
                       "muDynamic": 0.35, "periodSeconds": 0.00681},
            "figures": names + ["mu-static.png", "jump.png"]}


def make_loop(path, thermal=True, periods=3, samples_per_period=660):
    """Stick (force rising, creep just before release), then slip: the force falls
    as the string speeds up and recovers lower on the way back, anticlockwise.
    The contact heats while slipping and cools while sticking."""
    rows = []
    for n in range(periods * samples_per_period):
        phase = (n % samples_per_period) / samples_per_period
        if phase < 0.85:
            s = phase / 0.85
            v, f = -0.02 * s ** 8, 0.3 + 0.65 * s - 0.05 * s ** 10
            temperature = 8 + 17 * math.exp(-4 * s)
        else:
            s = (phase - 0.85) / 0.15
            v = -0.02 * (1 - s) - 0.5 * math.sin(math.pi * s) ** 0.8
            f = 0.9 - 0.6 * s - 0.35 * math.sin(math.pi * s) * (1 - 0.5 * s)
            temperature = 8 + 17 * s
        rows.append(f"{n / 48000:.9g},{v:.9g},{f:.9g},{temperature if thermal else 0.0:.9g}")
    with open(path, "w", encoding="utf-8") as out:
        out.write("time,slidingSpeed,frictionForce,contactTemperature\n")
        out.write("\n".join(rows) + "\n")


def run(*args):
    return subprocess.run([sys.executable, SCRIPT, *args], capture_output=True, text=True,
                          timeout=600)


class FiguresTest(unittest.TestCase):
    def setUp(self):
        self._tmp = tempfile.TemporaryDirectory(prefix="rosin-figures-")
        self.tmp = self._tmp.name

    def tearDown(self):
        self._tmp.cleanup()

    def path(self, *parts):
        return os.path.join(self.tmp, *parts)

    def assert_ok(self, result, written):
        self.assertEqual(result.returncode, 0, result.stderr)
        self.assertEqual(result.stdout.split("\n")[:-1], [f"wrote {p}" for p in written])

    def assert_png(self, path, figsize):
        """Valid PNG of the figure's size at 150 dpi, and not blank."""
        self.assertTrue(os.path.isfile(path), path)
        with open(path, "rb") as stream:
            self.assertEqual(stream.read(8), b"\x89PNG\r\n\x1a\n", path)
        pixels = image.imread(path)
        height, width = pixels.shape[:2]
        self.assertAlmostEqual(width, figsize[0] * scan_style.DPI, delta=1, msg=path)
        self.assertAlmostEqual(height, figsize[1] * scan_style.DPI, delta=1, msg=path)
        self.assertGreater(float(pixels[..., :3].var()), 0.0, path)

    def assert_error(self, result, *words):
        self.assertEqual(result.returncode, 2, result.stdout + result.stderr)
        for word in words:
            self.assertIn(word, result.stderr)

    def test_schelleng_figures(self):
        for n_beta, n_force in ((20, 20), (2, 2), (60, 45)):  # symbols, tiny, dense image
            with self.subTest(grid=(n_beta, n_force)):
                scan = self.path(f"schelleng-{n_beta}x{n_force}")
                make_schelleng(scan, n_beta, n_force)
                names = ("schelleng.png", "mu-static.png", "jump.png")
                written = [os.path.join(scan, name) for name in names]
                self.assert_ok(run(scan), written)
                for path in written:
                    self.assert_png(path, (10.0, 6.4))

    def test_guettler_figures_for_any_number_of_betas(self):
        for count, n_force, n_accel in ((8, 20, 20), (1, 2, 2), (5, 5, 7), (9, 6, 6)):
            with self.subTest(betas=count):
                scan = self.path(f"guettler-{count}")
                make_guettler(scan, SEED_BETAS[:count] if count <= 8 else
                              list(np.geomspace(0.03, 0.2, count)), n_force, n_accel)
                names = ("guettler.png", "mu-static.png", "jump.png")
                written = [os.path.join(scan, name) for name in names]
                self.assert_ok(run(scan), written)
                for path in written:
                    self.assert_png(path, scan_style.panel_figsize(count))

    def test_large_guettler_grid(self):
        scan = self.path("guettler-300")
        make_guettler(scan, [0.0899], 300, 300)
        self.assert_ok(run(scan), [os.path.join(scan, n)
                                   for n in ("guettler.png", "mu-static.png", "jump.png")])

    def test_compare_guettler(self):
        make_guettler(self.path("a"), SEED_BETAS[:4], 12, 12)
        make_guettler(self.path("b"), SEED_BETAS[:4], 12, 12, shift=1.3)
        out = self.path("cmp")
        self.assert_ok(run("compare", self.path("a"), self.path("b"), "--out", out),
                       [os.path.join(out, "compare.png")])
        self.assert_png(os.path.join(out, "compare.png"), scan_style.panel_figsize(4))

    def test_compare_schelleng(self):
        make_schelleng(self.path("a"))
        make_schelleng(self.path("b"), shift=1.4)
        out = self.path("cmp")
        self.assert_ok(run("compare", self.path("a"), self.path("b"), "--out", out),
                       [os.path.join(out, "compare.png")])
        self.assert_png(os.path.join(out, "compare.png"), (10.0, 6.4))

    def test_compare_rejects_mismatched_grids(self):
        make_schelleng(self.path("a"), 20, 20)
        make_schelleng(self.path("b"), 20, 10)
        result = run("compare", self.path("a"), self.path("b"), "--out", self.path("cmp"))
        self.assert_error(result, os.path.join(self.path("a"), "scan.json"),
                          os.path.join(self.path("b"), "scan.json"), "grid.forces")
        make_guettler(self.path("g"), SEED_BETAS[:2], 20, 20)
        result = run("compare", self.path("a"), self.path("g"), "--out", self.path("cmp"))
        self.assert_error(result, "kinds differ")
        self.assertFalse(os.path.exists(self.path("cmp", "compare.png")))

    def test_loop(self):
        for thermal in (True, False):  # coloured by temperature, then by time
            with self.subTest(thermal=thermal):
                csv_path, png = self.path(f"loop-{thermal}.csv"), self.path(f"out/{thermal}.png")
                make_loop(csv_path, thermal)
                self.assert_ok(run("loop", csv_path, "--out", png, "--title", "test loop"),
                               [png])
                self.assert_png(png, (8.0, 6.0))

    def test_missing_column_names_the_column(self):
        scan = self.path("broken")
        make_schelleng(scan, 4, 4)
        csv_path = os.path.join(scan, "scan.csv")
        with open(csv_path, encoding="utf-8") as stream:
            lines = [line.split(",") for line in stream.read().splitlines()]
        column = lines[0].index("muStatic")
        with open(csv_path, "w", encoding="utf-8") as stream:
            stream.write("\n".join(",".join(f[:column] + f[column + 1:]) for f in lines) + "\n")
        self.assert_error(run(scan), "muStatic", csv_path)

    def test_bad_inputs_name_file_and_field(self):
        scan = self.path("bad")
        self.assert_error(run(scan), os.path.join(scan, "scan.json"))
        make_guettler(scan, SEED_BETAS[:1], 3, 3)
        csv_path = os.path.join(scan, "scan.csv")
        with open(csv_path, encoding="utf-8") as stream:
            text = stream.read()
        with open(csv_path, "w", encoding="utf-8") as stream:
            stream.write(text.replace(",helmholtz,", ",wobbling,", 1))
        self.assert_error(run(scan), csv_path, "regime", "wobbling")
        with open(os.path.join(scan, "scan.json"), "w", encoding="utf-8") as stream:
            json.dump({"format": "rosin-scan/1", "kind": "guettler", "grid": {}}, stream)
        self.assert_error(run(scan), "grid.betas")
        loop = self.path("loop.csv")
        with open(loop, "w", encoding="utf-8") as stream:
            stream.write("time,slidingSpeed,frictionForce\n0,0,1\n1,0,2\n")
        self.assert_error(run("loop", loop, "--out", self.path("l.png")),
                          "contactTemperature", loop)


if __name__ == "__main__":
    unittest.main(verbosity=2)
