"""Friction-coefficient hysteresis loop of the oscillator rig ([Smith2000] Figs. 2c and 6), for
`plot_scan.py rig-loop`.

The CSV is written by `rosin render --preset cantilever --loop loop.png`:
time,slidingSpeed,frictionForce,contactTemperature,normalForce,frictionCoefficient.
The friction coefficient mu = f / N is drawn against the sliding speed v - v_rod,
coloured by contact temperature (by time for the curve laws, which have none),
with the steady-sliding curve of [Smith2000] eq. 2 dashed, as in Fig. 2c.
"""

import csv

import matplotlib.pyplot as plt
import numpy as np
from matplotlib.collections import LineCollection

COLUMNS = ("time", "slidingSpeed", "frictionCoefficient", "contactTemperature")


def read_rig_loop(path):
    with open(path, newline="", encoding="utf-8") as f:
        rows = list(csv.DictReader(f))
    if len(rows) < 2:
        raise ValueError(f"{path}: needs at least 2 data rows to draw a loop, has {len(rows)}")
    missing = [c for c in COLUMNS if c not in rows[0]]
    if missing:
        raise ValueError(f"{path}: missing column(s) {', '.join(missing)}")
    return {c: np.array([float(r[c]) for r in rows]) for c in COLUMNS}


def steady_curve(speed):
    """[Smith2000] eq. 2, the traditional steady-sliding curve, opposing the sliding."""
    v = np.abs(speed)
    return -np.sign(speed) * (0.4 * np.exp(-v / 0.01) + 0.45 * np.exp(-v / 0.1) + 0.35)


def rig_loop_figure(loop, out, title):
    x, y = loop["slidingSpeed"], loop["frictionCoefficient"]
    temperature = loop["contactTemperature"]
    thermal = np.ptp(temperature) > 0
    colour = temperature if thermal else loop["time"]
    fig, ax = plt.subplots(figsize=(8.0, 6.0), layout="constrained")
    ax.axvline(0.0, color="#999999", lw=0.8, ls=":")
    ax.axhline(0.0, color="#cccccc", lw=0.6)
    lo, hi = min(x.min(), -1e-3), max(x.max(), 1e-3)
    grid = np.concatenate((np.linspace(lo, -1e-6, 300), np.linspace(1e-6, hi, 300) if hi > 1e-3 else []))
    ax.plot(grid, steady_curve(grid), "--", color="#555555", lw=1.0, label="steady sliding, eq. 2")
    points = np.column_stack((x, y)).reshape(-1, 1, 2)
    lines = LineCollection(np.concatenate((points[:-1], points[1:]), axis=1),
                           cmap="plasma" if thermal else "viridis", linewidths=1.4)
    lines.set_array(colour[:-1])
    ax.add_collection(lines)
    # A few arrows along the last part of the record show the sense of traversal.
    for i in np.linspace(len(x) // 2, len(x) - 3, 6).astype(int):
        if (x[i + 2], y[i + 2]) != (x[i], y[i]):
            ax.annotate("", xy=(x[i + 2], y[i + 2]), xytext=(x[i], y[i]),
                        arrowprops=dict(arrowstyle="-|>", color="#222222", lw=1.0, mutation_scale=14))
    ax.autoscale_view()
    ax.margins(0.05)
    fig.colorbar(lines, ax=ax, label="contact temperature rise (K)" if thermal else "time (s)")
    ax.set_xlabel("sliding speed v − v_rod (m/s)")
    ax.set_ylabel("friction coefficient μ = f / N")
    ax.legend(loc="best", frameon=False)
    fig.suptitle(title or "Friction coefficient against sliding speed")
    ax.set_title(f"t = {loop['time'].min():.4g} … {loop['time'].max():.4g} s · {len(x)} samples · "
                 "[Smith2000] Fig. 2c runs anticlockwise", color="#333333", fontsize=9)
    fig.savefig(out, dpi=150)
    plt.close(fig)
    return out
