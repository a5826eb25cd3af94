"""Friction hysteresis loop: friction force against sliding speed ([Galluzzo2017] Figs. 20-21)."""

import os

import numpy as np
from matplotlib.collections import LineCollection

import scan_style as style
from scan_style import plt

FIGSIZE = (8.0, 6.0)
ARROWS = 6


def _colouring(loop):
    """Temperature when the law has one; curve laws report 0 K, so use time then."""
    temperature = loop["contactTemperature"]
    finite = temperature[np.isfinite(temperature)]
    if finite.size and np.ptp(finite) > 0:
        return temperature, "plasma", "contact temperature rise ΔT (K)"
    return loop["time"], "viridis", "time (s)"


def _arrow_indices(x, y, count, spacing=0.15):
    """Samples spread along the path's length (in axis-normalised units), so
    arrows land on the visible strokes rather than bunching where the
    trajectory dwells (sticking); candidates too close to an arrow already
    placed are skipped, since a file of several cycles retraces the loop."""
    nx = (x - x.min()) / max(np.ptp(x), 1e-30)
    ny = (y - y.min()) / max(np.ptp(y), 1e-30)
    arc = np.concatenate(([0.0], np.cumsum(np.hypot(np.diff(nx), np.diff(ny)))))
    if arc[-1] <= 0:
        return [], arc
    # Golden-ratio steps visit the whole path early, whatever its length.
    candidates = arc[-1] * np.modf(0.5 + 0.6180339887 * np.arange(20 * count))[0]
    chosen = []
    for i in np.searchsorted(arc, candidates).clip(0, len(x) - 2):
        if all(np.hypot(nx[i] - nx[j], ny[i] - ny[j]) > spacing for j in chosen):
            chosen.append(i)
        if len(chosen) == count:
            break
    return chosen, arc


def _draw_arrows(ax, x, y):
    indices, arc = _arrow_indices(x, y, ARROWS)
    for i in indices:
        # Aim a short fixed distance further along (in axis-normalised units), so
        # the head follows the curve even when the file holds many cycles.
        j = int(np.searchsorted(arc, arc[i] + 0.015))
        j = min(max(j, i + 1), len(x) - 1)
        ax.annotate("", xy=(x[j], y[j]), xytext=(x[i], y[i]), zorder=4,
                    arrowprops=dict(arrowstyle="-|>", color="#222222", lw=1.0,
                                    mutation_scale=15, shrinkA=0, shrinkB=0))


def loop_figure(loop, path, title=None, source=""):
    x, y = loop["slidingSpeed"], loop["frictionForce"]
    keep = np.isfinite(x) & np.isfinite(y)
    colour_values, cmap, colour_label = _colouring(loop)
    x, y, colour_values = x[keep], y[keep], colour_values[keep]
    fig, ax = plt.subplots(figsize=FIGSIZE, layout="constrained")
    ax.axvline(0.0, color="#999999", lw=0.8, ls=":", zorder=1)
    ax.axhline(0.0, color="#cccccc", lw=0.6, zorder=1)
    points = np.column_stack((x, y)).reshape(-1, 1, 2)
    segments = np.concatenate((points[:-1], points[1:]), axis=1)
    finite = colour_values[np.isfinite(colour_values)]
    lines = LineCollection(segments, cmap=cmap, linewidths=1.4, zorder=2)
    lines.set_array(np.nan_to_num(colour_values[:-1], nan=finite.min() if finite.size else 0))
    ax.add_collection(lines)
    ax.autoscale_view()
    ax.margins(0.05)
    _draw_arrows(ax, x, y)
    ax.plot(x[:1], y[:1], "o", color="black", ms=5, zorder=5, label="start")
    ax.plot(x[-1:], y[-1:], "s", color="black", ms=5, zorder=5, mfc="white", label="end")
    ax.plot([], [], color="#999999", lw=0.8, ls=":", label="v = v_b (sticking)")
    fig.colorbar(lines, ax=ax, label=colour_label)
    ax.set_xlabel("sliding speed v − v_b (m/s)")
    ax.set_ylabel("friction force f (N)")
    ax.legend(loc="best", frameon=False)
    t = loop["time"]
    fig.suptitle(title or "Friction force against sliding speed")
    ax.set_title(f"{os.path.basename(source)} · t = {np.nanmin(t):.4g} … {np.nanmax(t):.4g} s · "
                 f"{len(x)} samples · arrows: direction of traversal", color="#333333")
    return style.save(fig, path)
