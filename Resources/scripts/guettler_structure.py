#!/usr/bin/env python3
"""Share, transient length and radial structure of Guettler scans (rosin scan guettler, one beta).

For each scan directory given, reads scan.csv and prints:
  share20   the fraction of cells that reach Helmholtz motion within 20 periods of the first slip
            (transientPeriods present: the cells [Galluzzo2017] Fig. 12 shades rather than hatches or blackens);
  median    the median transient length (periods) over those cells;
  radial    the radial anisotropy A of the transient lengths. [Galluzzo2017] sees "radial lines which contain
            apparently similar transients" with every friction curve and not with the thermal model. In the
            (force, acceleration) plane, scaled so that one grid step is one unit on both axes (rays from the
            origin stay rays), each successful cell p is compared with the cell two steps away along the ray
            through it (q_r) and two steps across it (q_t). With D_r, D_t the mean squared differences of
            ln(transient length) over pairs where both cells succeed, A = D_t / D_r: transients constant along
            rays give A >> 1, structure without a preferred direction A ~ 1. Radial lines count as present
            when A >= 1.5. The measure and the threshold were fixed before any scan was looked at with it;
  spread    how densely the successful cells cluster about the wedge's centre line ([Galluzzo2017] on the
            string without bending stiffness): the interquartile range, in degrees, of the ray angle
            atan(w / u) of the successful cells in the same scaled plane. Smaller is denser. Fixed before
            it was computed on any scan.
Usage: guettler_structure.py SCAN_DIR [SCAN_DIR ...] [--json OUT.json]
"""
import csv
import json
import math
import sys


def read_scan(directory):
    with open(f"{directory}/scan.csv", newline="") as f:
        rows = list(csv.DictReader(f))
    if not rows or "transientPeriods" not in rows[0]:
        sys.exit(f"{directory}/scan.csv: field transientPeriods: expected a Guettler scan, got none")
    forces = sorted({float(r["bowForce"]) for r in rows})
    accels = sorted({float(r["acceleration"]) for r in rows})
    betas = {r["beta"] for r in rows}
    if len(betas) != 1:
        sys.exit(f"{directory}/scan.csv: field beta: expected one beta, got {sorted(betas)}")
    grid = {}
    for r in rows:
        t = r["transientPeriods"]
        grid[(forces.index(float(r["bowForce"])), accels.index(float(r["acceleration"])))] = (
            float(t) if t else None)
    return forces, accels, grid


def step(values):
    return (values[-1] - values[0]) / (len(values) - 1) if len(values) > 1 else 1.0


def radial_anisotropy(forces, accels, grid):
    dN, da = step(forces), step(accels)
    i0, j0 = forces[0] / dN, accels[0] / da  # grid index 0 in scaled coordinates
    sums = {"r": [0.0, 0], "t": [0.0, 0]}
    for (i, j), t in grid.items():
        if t is None or t <= 0:
            continue
        u, w = i0 + i, j0 + j
        norm = math.hypot(u, w)
        ru, rw = u / norm, w / norm
        for key, (du, dw) in (("r", (ru, rw)), ("t", (-rw, ru))):
            q = (round(i + 2 * du), round(j + 2 * dw))
            tq = grid.get(q)
            if tq is None or tq <= 0:
                continue
            sums[key][0] += (math.log(t) - math.log(tq)) ** 2
            sums[key][1] += 1
    if sums["r"][1] == 0 or sums["t"][1] == 0 or sums["r"][0] == 0:
        return float("nan")
    return (sums["t"][0] / sums["t"][1]) / (sums["r"][0] / sums["r"][1])


def angular_spread(forces, accels, grid):
    dN, da = step(forces), step(accels)
    i0, j0 = forces[0] / dN, accels[0] / da
    angles = sorted(math.degrees(math.atan2(j0 + j, i0 + i)) for (i, j), t in grid.items() if t is not None)
    if len(angles) < 4:
        return float("nan")
    return angles[(3 * len(angles)) // 4] - angles[len(angles) // 4]


def summarise(directory):
    forces, accels, grid = read_scan(directory)
    lengths = sorted(t for t in grid.values() if t is not None)
    n = len(grid)
    median = lengths[len(lengths) // 2] if lengths else float("nan")
    return {"scan": directory, "cells": n, "share20": len(lengths) / n, "medianTransient": median,
            "radialAnisotropy": radial_anisotropy(forces, accels, grid),
            "angularSpread": angular_spread(forces, accels, grid), "successful": len(lengths)}


def main(argv):
    out = None
    if "--json" in argv:
        k = argv.index("--json")
        out = argv[k + 1]
        argv = argv[:k] + argv[k + 2:]
    if not argv:
        sys.exit(__doc__)
    results = [summarise(d) for d in argv]
    print(f"{'scan':40s} {'cells':>6s} {'share20':>8s} {'median':>7s} {'radial A':>9s} {'spread':>7s}")
    for r in results:
        print(f"{r['scan']:40s} {r['cells']:6d} {100 * r['share20']:7.1f}% {r['medianTransient']:7.2f} "
              f"{r['radialAnisotropy']:9.2f} {r['angularSpread']:7.2f}")
    if out:
        with open(out, "w") as f:
            json.dump(results, f, indent=1)


if __name__ == "__main__":
    main(sys.argv[1:])
