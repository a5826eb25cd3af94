#!/usr/bin/env python3
"""Side-by-side maps for `rosin discover`: measured / baseline / baseline + calibration (/ + adopted
effects, when any was adopted) of every feature that disagrees before any effect or that an adopted effect changed, one figure per
feature and beta, over the (bow force, acceleration or bow speed) grid. Both axes and the colour scale carry
their quantity and unit.

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


def draw(maps, name, beta):
    """One feature at one beta; returns the figure, or None when no trial has the feature there."""
    import matplotlib.pyplot as plt
    import numpy as np

    trials = maps["trials"]
    forces = sorted({t["force"] for t in trials})
    motions = sorted({t["motion"] for t in trials})
    panels = ["measured", "baseline"] + (["calibrated"] if "calibrated" in trials[0] else []) + (
        ["final"] if maps.get("adoptedEffects", 0) > 0 else [])
    grids = {}
    for key in panels:
        g = np.full((len(forces), len(motions)), np.nan)
        for t in trials:
            if t["beta"] == beta and t[key].get(name) is not None:
                g[forces.index(t["force"]), motions.index(t["motion"])] = t[key][name]
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
        mesh = ax.pcolormesh(range(len(motions) + 1), range(len(forces) + 1), grids[key], vmin=lo, vmax=hi,
                             cmap="viridis", shading="flat")
        ax.set_title(titles[key])
        ax.set_xticks([i + 0.5 for i in range(len(motions))])
        ax.set_xticklabels([f"{m:.3g}" for m in motions], rotation=60, fontsize=7)
        ax.set_xlabel(maps["motionAxis"])
    axes[0].set_yticks([i + 0.5 for i in range(len(forces))])
    axes[0].set_yticklabels([f"{v:.3g}" for v in forces], fontsize=7)
    axes[0].set_ylabel("bow force (N)")
    fig.colorbar(mesh, ax=list(axes), label=feature_label(maps, name))
    fig.suptitle(f"{name} at beta {beta:g}")
    return fig


def main():
    if len(sys.argv) != 2:
        sys.exit("usage: plot_discovery.py DIR")
    _import_matplotlib()
    import matplotlib.pyplot as plt

    folder = sys.argv[1]
    with open(os.path.join(folder, "maps.json")) as f:
        maps = json.load(f)
    betas = sorted({t["beta"] for t in maps["trials"]})
    for name in mapped_features(maps):
        for beta in betas:
            fig = draw(maps, name, beta)
            if fig is None:
                continue
            out = os.path.join(folder, f"map-{name}-b{beta:g}.png")
            fig.savefig(out, dpi=90)
            plt.close(fig)
            print("wrote", out)


if __name__ == "__main__":
    main()
