#!/usr/bin/env python3
"""Figures for `rosin scan` output (contract: Resources/docs/scan-format.md).

Usage:
  plot_scan.py DIR                             figures of DIR/scan.csv + DIR/scan.json, into DIR
  plot_scan.py compare DIR_A DIR_B --out DIR   compare.png: scan B against scan A (same grid)
  plot_scan.py loop LOOP.csv --out loop.png [--title T]
                                               friction hysteresis loop
  plot_scan.py rig-loop LOOP.csv --out loop.png [--title T]
                                               the oscillator rig's mu against sliding speed
Prints "wrote PATH" for every figure written. Exit status 2 on bad input.
"""

import argparse
import os
import sys


def _ensure_matplotlib():
    """The figures need Debian's python3-matplotlib; a python3 earlier on PATH
    (pyenv, a venv) may lack it, so hand over to the system interpreter."""
    try:
        import matplotlib  # noqa: F401
        import numpy  # noqa: F401
    except ImportError as error:
        system = "/usr/bin/python3"
        if os.path.exists(system) and os.path.realpath(sys.executable) != os.path.realpath(system):
            os.execv(system, [system, os.path.abspath(__file__)] + sys.argv[1:])
        sys.exit(f"plot_scan: error: {error}; install python3-matplotlib and python3-numpy")


_ensure_matplotlib()

# The figure modules live beside this script.
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

import guettler_figures  # noqa: E402
import schelleng_figures  # noqa: E402
from loop_figure import loop_figure  # noqa: E402
from rig_loop_figure import read_rig_loop, rig_loop_figure  # noqa: E402
from scan_io import ScanError, check_same_grid, read_loop, read_scan  # noqa: E402
from scan_style import MapSpec  # noqa: E402

MAPS = {
    "mu-static.png": MapSpec(
        "muStatic", "viridis", "Limiting static friction at the first slip",
        "μ_s = bridge force before the first slip / ((1 − β) F)", "μ_s (–)"),
    "jump.png": MapSpec(
        "jump", "magma", "Bridge-force jump at the first slip",
        "jump = (bridge force before − after the first slip) / F", "jump / F (–)"),
}


# kind -> (main figure file, its drawing function, colour-map drawing function)
FIGURES = {
    "schelleng": ("schelleng.png", schelleng_figures.schelleng_diagram,
                  schelleng_figures.schelleng_map),
    "guettler": ("guettler.png", guettler_figures.guettler_diagram,
                 guettler_figures.guettler_map),
}


def plot_scan(directory):
    """Writes the scan kind's figures into its directory; returns their paths."""
    scan = read_scan(directory)
    _note_missing(scan)
    name, diagram, colour_map = FIGURES[scan.kind]
    paths = [diagram(scan, os.path.join(directory, name))]
    for file_name, spec in MAPS.items():
        paths.append(colour_map(scan, os.path.join(directory, file_name), spec))
    return paths


def _note_missing(scan):
    """A partial scan still plots, but say so: its blank cells are not results."""
    if scan.missing:
        total = scan.missing + int((scan.regime >= 0).sum())
        print(f"plot_scan: note: {scan.csv_path} has no row for {scan.missing} of {total} "
              "grid cells; they are drawn blank", file=sys.stderr)


def _scan_name(directory, other):
    """Directory name for titles; the whole path when both names would be equal."""
    name = os.path.basename(os.path.normpath(directory))
    if name == os.path.basename(os.path.normpath(other)):
        return os.path.normpath(directory)
    return name


def plot_compare(dir_a, dir_b, out_dir):
    a, b = read_scan(dir_a), read_scan(dir_b)
    check_same_grid(a, b)
    _note_missing(a)
    _note_missing(b)
    os.makedirs(out_dir, exist_ok=True)
    names = (_scan_name(dir_a, dir_b), _scan_name(dir_b, dir_a))
    path = os.path.join(out_dir, "compare.png")
    if a.kind == "schelleng":
        return [schelleng_figures.schelleng_compare(a, b, names, path)]
    return [guettler_figures.guettler_compare(a, b, names, path)]


def plot_loop(csv_path, out_path, title):
    loop = read_loop(csv_path)
    parent = os.path.dirname(out_path)
    if parent:
        os.makedirs(parent, exist_ok=True)
    return [loop_figure(loop, out_path, title, source=csv_path)]


def plot_rig_loop(csv_path, out_path, title):
    try:
        loop = read_rig_loop(csv_path)
    except (OSError, ValueError) as error:
        raise ScanError(str(error)) from error
    return [rig_loop_figure(loop, out_path, title)]


def _parse(argv):
    if argv and argv[0] == "compare":
        parser = argparse.ArgumentParser(prog="plot_scan.py compare",
                                         description="Difference of two scans of one grid.")
        parser.add_argument("dir_a", help="scan A (the base case)")
        parser.add_argument("dir_b", help="scan B (the modified case)")
        parser.add_argument("--out", required=True, help="directory for compare.png")
    elif argv and argv[0] in ("loop", "rig-loop"):
        parser = argparse.ArgumentParser(prog="plot_scan.py " + argv[0],
                                         description="Friction hysteresis loop.")
        parser.add_argument("csv", help="CSV: time,slidingSpeed,frictionForce,contactTemperature")
        parser.add_argument("--out", required=True, help="PNG file to write")
        parser.add_argument("--title", help="figure title")
    else:
        parser = argparse.ArgumentParser(prog="plot_scan.py", description=__doc__,
                                         formatter_class=argparse.RawDescriptionHelpFormatter)
        parser.add_argument("dir", help="directory holding scan.csv and scan.json")
        return "scan", parser.parse_args(argv)
    return argv[0], parser.parse_args(argv[1:])


def main(argv):
    command, args = _parse(argv)
    try:
        if command == "compare":
            paths = plot_compare(args.dir_a, args.dir_b, args.out)
        elif command == "loop":
            paths = plot_loop(args.csv, args.out, args.title)
        elif command == "rig-loop":
            paths = plot_rig_loop(args.csv, args.out, args.title)
        else:
            paths = plot_scan(args.dir)
    except ScanError as error:
        print(f"plot_scan: error: {error}", file=sys.stderr)
        return 2
    for path in paths:
        print(f"wrote {path}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
