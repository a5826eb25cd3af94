#!/usr/bin/env python3
"""Side-by-side maps for `rosin discover`: measured / baseline / baseline + adopted effects of every feature
whose gap changed, one figure per feature and beta, over the (bow force, acceleration or bow speed) grid.

Usage: plot_discovery.py DIR      reads DIR/maps.json (written by rosin discover), writes DIR/map-*.png
"""

import json
import os
import sys


def main():
    if len(sys.argv) != 2:
        sys.exit("usage: plot_discovery.py DIR")
    folder = sys.argv[1]
    try:
        import matplotlib

        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        import numpy as np
    except ImportError as error:
        system = "/usr/bin/python3"
        if os.path.exists(system) and os.path.realpath(sys.executable) != os.path.realpath(system):
            os.execv(system, [system, os.path.abspath(__file__)] + sys.argv[1:])
        sys.exit(f"plot_discovery: error: {error}")
    with open(os.path.join(folder, "maps.json")) as f:
        maps = json.load(f)
    trials = maps["trials"]
    betas = sorted({t["beta"] for t in trials})
    forces = sorted({t["force"] for t in trials})
    motions = sorted({t["motion"] for t in trials})
    for name in maps["changed"]:
        for beta in betas:
            grids = {}
            for key in ("measured", "baseline", "final"):
                g = np.full((len(forces), len(motions)), np.nan)
                for t in trials:
                    if t["beta"] == beta and t[key][name] is not None:
                        g[forces.index(t["force"]), motions.index(t["motion"])] = t[key][name]
                grids[key] = g
            finite = np.concatenate([g[np.isfinite(g)] for g in grids.values()])
            if finite.size == 0:
                continue
            lo, hi = np.percentile(finite, 2), np.percentile(finite, 98)
            fig, axes = plt.subplots(1, 3, figsize=(12, 3.8), sharey=True)
            titles = {"measured": "measured", "baseline": "baseline model", "final": "baseline + effect(s)"}
            for ax, key in zip(axes, ("measured", "baseline", "final")):
                mesh = ax.pcolormesh(range(len(motions) + 1), range(len(forces) + 1), grids[key], vmin=lo,
                                     vmax=hi, cmap="viridis", shading="flat")
                ax.set_title(titles[key])
                ax.set_xticks([i + 0.5 for i in range(len(motions))])
                ax.set_xticklabels([f"{m:.3g}" for m in motions], rotation=60, fontsize=7)
                ax.set_xlabel(maps["motionAxis"])
            axes[0].set_yticks([i + 0.5 for i in range(len(forces))])
            axes[0].set_yticklabels([f"{v:.3g}" for v in forces], fontsize=7)
            axes[0].set_ylabel("bow force (N)")
            fig.colorbar(mesh, ax=axes, label=name)
            fig.suptitle(f"{name} at beta {beta:g}")
            out = os.path.join(folder, f"map-{name}-b{beta:g}.png")
            fig.savefig(out, dpi=90)
            plt.close(fig)
            print("wrote", out)


if __name__ == "__main__":
    main()
