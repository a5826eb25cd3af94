#!/usr/bin/env python3
"""Side-by-side maps for `rosin discover`: measured / baseline / baseline + calibration (/ + adopted
effects, when any was adopted) of every feature that disagrees before any effect or that an adopted effect
changed. A Guettler scan gets one figure per feature and beta over its (bow force, acceleration) grid; a
Schelleng scan (one bow speed, several betas) one figure per feature over (bow force, beta), the plane of its
diagram. Both axes and the colour scale carry their quantity and unit.

Usage: plot_discovery.py DIR      reads DIR/maps.json (written by rosin discover), writes DIR/map-*.png
"""

import json
import os
import sys


def _import_matplotlib():
    """Debian's python3-matplotlib is for /usr/bin/python3: re-run under it when this python lacks it."""
    try:
        import matplotlib

        matplotlib.use("Agg")
        import matplotlib.pyplot  # noqa: F401
        import numpy  # noqa: F401
    except ImportError as error:
        system = "/usr/bin/python3"
        if os.path.exists(system) and os.path.realpath(sys.executable) != os.path.realpath(system):
            os.execv(system, [system, os.path.abspath(__file__)] + sys.argv[1:])
        sys.exit(f"plot_discovery: error: {error}")


def mapped_features(maps):
    """The features to draw, in the order maps.json lists them: the disagreeing ones, then the changed."""
    names = list(maps.get("disagreeing", []))
    return names + [n for n in maps.get("changed", []) if n not in names]


def feature_label(maps, name):
    unit = maps.get("units", {}).get(name, "")
    return f"{name} ({unit})" if unit else f"{name} (dimensionless)"


def is_schelleng(maps):
    """One bow speed and several betas: the scan's plane is (beta, bow force)."""
    trials = maps["trials"]
    return len({t["motion"] for t in trials}) == 1 and len({t["beta"] for t in trials}) > 1


def draw(maps, name, beta=None):
    """One feature at one beta over (motion, force), or, with beta None, over (beta, force) at the scan's one
    bow speed; returns the figure, or None when no trial has the feature there."""
    import matplotlib.pyplot as plt
    import numpy as np

    trials = maps["trials"]
    if beta is None:
        x_key, x_label = "beta", "relative bow position beta (dimensionless)"
        quantity, _, unit = maps["motionAxis"].partition(" (")
        title = f"{name} at {quantity} {trials[0]['motion']:g} {unit.rstrip(')')}".rstrip()
    else:
        trials = [t for t in trials if t["beta"] == beta]
        x_key, x_label, title = "motion", maps["motionAxis"], f"{name} at beta {beta:g}"
    forces = sorted({t["force"] for t in trials})
    xs = sorted({t[x_key] for t in trials})
    panels = ["measured", "baseline"] + (["calibrated"] if "calibrated" in trials[0] else []) + (
        ["final"] if maps.get("adoptedEffects", 0) > 0 else [])
    grids = {}
    for key in panels:
        g = np.full((len(forces), len(xs)), np.nan)
        for t in trials:
            if t[key].get(name) is not None:
                g[forces.index(t["force"]), xs.index(t[x_key])] = t[key][name]
        grids[key] = g
    finite = np.concatenate([g[np.isfinite(g)] for g in grids.values()])
    if finite.size == 0:
        return None
    lo, hi = np.percentile(finite, 2), np.percentile(finite, 98)
    fig, axes = plt.subplots(1, len(panels), figsize=(4 * len(panels), 4.2), sharey=True,
                             constrained_layout=True)
    titles = {"measured": "measured", "baseline": "baseline model", "calibrated": "baseline, calibrated",
              "final": "calibrated + adopted effect(s)"}
    mesh = None
    for ax, key in zip(axes, panels):
        mesh = ax.pcolormesh(range(len(xs) + 1), range(len(forces) + 1), grids[key], vmin=lo, vmax=hi,
                             cmap="viridis", shading="flat")
        ax.set_title(titles[key])
        ax.set_xticks([i + 0.5 for i in range(len(xs))])
        ax.set_xticklabels([f"{x:.3g}" for x in xs], rotation=60, fontsize=7)
        ax.set_xlabel(x_label)
    axes[0].set_yticks([i + 0.5 for i in range(len(forces))])
    axes[0].set_yticklabels([f"{v:.3g}" for v in forces], fontsize=7)
    axes[0].set_ylabel("bow force (N)")
    fig.colorbar(mesh, ax=list(axes), label=feature_label(maps, name))
    fig.suptitle(title)
    return fig


def main():
    if len(sys.argv) != 2:
        sys.exit("usage: plot_discovery.py DIR")
    _import_matplotlib()
    import matplotlib.pyplot as plt

    folder = sys.argv[1]
    with open(os.path.join(folder, "maps.json")) as f:
        maps = json.load(f)
    betas = [None] if is_schelleng(maps) else sorted({t["beta"] for t in maps["trials"]})
    for name in mapped_features(maps):
        for beta in betas:
            fig = draw(maps, name, beta)
            if fig is None:
                continue
            out = os.path.join(folder, f"map-{name}.png" if beta is None else f"map-{name}-b{beta:g}.png")
            fig.savefig(out, dpi=90)
            plt.close(fig)
            print("wrote", out)


if __name__ == "__main__":
    main()
