"""Shared look of the scan figures: regime symbols, titles, grid edges, layout."""

import math
import textwrap
from collections import namedtuple

import matplotlib

matplotlib.use("Agg")  # figures are files; never open a window

import matplotlib.pyplot as plt  # noqa: E402  (after use())
import numpy as np  # noqa: E402
from matplotlib import ticker  # noqa: E402

DPI = 150
TRANSIENT_CAP = 20.0  # periods; the contract writes EMPTY beyond it

plt.rcParams.update({
    "font.size": 9,
    "axes.titlesize": 9.5,
    "axes.labelsize": 9,
    "legend.fontsize": 8,
    "figure.titlesize": 12,
    "axes.spines.top": False,
    "axes.spines.right": False,
})

# [Galluzzo2017] Fig. 3 uses one symbol per regime; Helmholtz gets the boldest one
# because the Helmholtz region is what a Schelleng diagram is read for.
# name -> (marker, colour, filled, relative size)
REGIME_STYLE = {
    "helmholtz": ("o", "#111111", True, 1.0),
    "s-motion": ("*", "#1b9e77", True, 1.3),
    "double-slipping": ("x", "#e66101", False, 0.9),
    "multiple-slipping": ("D", "#7b3294", True, 0.7),
    "raucous": ("+", "#d7191c", False, 1.1),
    "alf": ("^", "#2c7bb6", True, 0.9),
    "constant-slipping": (".", "#8c8c8c", True, 0.9),
    "no-slip": ("s", "#525252", False, 0.8),
}

# Colours when a dense grid is drawn as an image instead of symbols.
REGIME_FILL = {
    "helmholtz": "#111111", "s-motion": "#1b9e77", "double-slipping": "#fdb863",
    "multiple-slipping": "#b2abd2", "raucous": "#d7191c", "alf": "#92c5de",
    "constant-slipping": "#e0e0e0", "no-slip": "#f7f7f7",
}

NOT_REACHED_COLOUR = "black"  # Guettler cap colour, as [Galluzzo2017] Figs. 5-8: white is a perfect start
NO_SLIP_COLOUR = "#a6cee3"      # never slipped: pale blue
WEDGE_COLOUR = "#e41a1c"
MAX_LINE_COLOUR = "#c51b7d"     # Schelleng maximum force and the fitted upper edge
MIN_LINE_COLOUR = "#1a9850"     # Schelleng/Raman minimum force and the fitted lower edge

# A colour map of one per-cell CSV column: the figure's headline, the
# quantity's definition (subtitle) and the colour-bar label.
MapSpec = namedtuple("MapSpec", "column cmap headline definition bar_label")

BETA_LABEL = "relative bow position β (–)"
FORCE_LABEL = "bow force F (N)"
ACCEL_LABEL = "bow acceleration a (m/s²)"


def describe(meta):
    """'preset · friction law · string' from scan.json, skipping absent fields."""
    parts = [str(meta["preset"])] if meta.get("preset") else []
    if meta.get("friction"):
        parts.append(f"{meta['friction']} friction")
    if meta.get("string"):
        parts.append(str(meta["string"]))
    return " · ".join(parts) if parts else "unnamed scan"


def run_details(meta):
    """Sample rate, trial length and model variations: what makes runs differ."""
    parts = []
    if isinstance(meta.get("sampleRate"), (int, float)):
        parts.append(f"{meta['sampleRate'] / 1000:g} kHz")
    if isinstance(meta.get("trialSeconds"), (int, float)):
        parts.append(f"{meta['trialSeconds']:g} s trials")
    variations = meta.get("variations")
    if isinstance(variations, dict):
        parts += [f"{_words(key)} {_on_off(value)}" for key, value in variations.items()]
    return " · ".join(parts)


def meta_changes(a, b):
    """What B's scan.json changes relative to A's, e.g. 'friction classical → thermal'."""
    changes = []
    for key in ("preset", "friction", "string", "sampleRate", "trialSeconds"):
        if a.get(key) != b.get(key):
            changes.append(f"{_words(key)} {a.get(key, '–')} → {b.get(key, '–')}")
    va, vb = a.get("variations") or {}, b.get("variations") or {}
    for key in sorted(set(va) | set(vb)):
        if va.get(key) != vb.get(key):
            changes.append(f"{_words(key)} {_on_off(va.get(key, '–'))} → "
                           f"{_on_off(vb.get(key, '–'))}")
    return changes


def changes_text(changes):
    if not changes:
        return "A and B record the same settings"
    return "B differs from A in: " + " · ".join(changes)


def fit_title(fig, text):
    """Suptitle wrapped to the figure's width, so no line runs off the image."""
    size = plt.rcParams["figure.titlesize"]
    chars = int(fig.get_figwidth() * 72 / (0.55 * size))
    lines = [textwrap.fill(line, chars, break_long_words=False) for line in text.split("\n")]
    fig.suptitle("\n".join(lines))


def _words(camel):
    return "".join(" " + c.lower() if c.isupper() else c for c in camel)


def _on_off(value):
    return ("on" if value else "off") if isinstance(value, bool) else f"{value}"


def percent(fraction):
    return "–" if fraction is None or math.isnan(fraction) else f"{100 * fraction:.1f} %"


def beta_text(beta):
    return f"β = {beta:.4g}"


def edges(centres, log):
    """Cell edges around grid centres: midpoints (geometric on log axes)."""
    c = np.log(centres) if log else np.asarray(centres, dtype=float)
    if len(c) == 1:
        half = 0.1 if log else max(abs(c[0]) * 0.1, 0.5)
        e = np.array([c[0] - half, c[0] + half])
    else:
        mid = (c[1:] + c[:-1]) / 2
        e = np.concatenate(([2 * c[0] - mid[0]], mid, [2 * c[-1] - mid[-1]]))
    return np.exp(e) if log else e


def panel_layout(count):
    """(rows, columns) for one panel per beta: at most 4 across, rows balanced."""
    rows = math.ceil(count / 4)
    return rows, math.ceil(count / rows)


def panel_figsize(count):
    """Inches; never narrower than the titles and the legend strip need."""
    rows, cols = panel_layout(count)
    if count == 1:
        return (9.0, 6.0)
    return (max(cols * 3.1 + 1.5, 9.0), rows * 2.9 + 1.3)


def panel_axes(count):
    """Figure with one axes per beta (shared scales), spare axes removed."""
    rows, cols = panel_layout(count)
    fig, axes = plt.subplots(rows, cols, figsize=panel_figsize(count), sharex=True,
                             sharey=True, squeeze=False, layout="constrained")
    flat = list(axes.ravel())
    for ax in flat[count:]:
        ax.remove()
    for ax in flat[:count]:
        ax.tick_params(labelbottom=True, labelleft=True)  # spare panels hide them otherwise
    return fig, flat[:count]


def label_outer(panels, cols, xlabel, ylabel):
    """Axis labels only on the left column and the lowest panel of each column."""
    count = len(panels)
    for i, ax in enumerate(panels):
        if i % cols == 0:
            ax.set_ylabel(ylabel)
        if i + cols >= count:
            ax.set_xlabel(xlabel)


def log_ticks(ax):
    """Readable 1-2-5 tick labels on short log ranges (matplotlib labels decades only)."""
    for axis, (lo, hi) in ((ax.xaxis, ax.get_xlim()), (ax.yaxis, ax.get_ylim())):
        subs = (1.0, 2.0, 5.0) if hi / lo > 4 else tuple(range(1, 10))
        axis.set_major_locator(ticker.LogLocator(subs=subs))
        axis.set_major_formatter(ticker.FuncFormatter(lambda v, _: f"{v:g}"))
        axis.set_minor_formatter(ticker.NullFormatter())


def robust_limits(values):
    """Colour limits from the 1st-99th percentiles so one outlier cannot flatten a map."""
    finite = values[np.isfinite(values)]
    if finite.size == 0:
        return 0.0, 1.0, "neither"
    lo, hi = np.percentile(finite, [1, 99])
    if hi <= lo:
        lo, hi = lo - 0.5, hi + 0.5
    extend = {(False, False): "neither", (True, False): "min",
              (False, True): "max", (True, True): "both"}
    return lo, hi, extend[(finite.min() < lo, finite.max() > hi)]


def hatch_blank(ax):
    """Light hatching behind a colour map, so cells without a value read as empty."""
    ax.patch.set_facecolor("white")
    ax.patch.set_hatch("////")
    ax.patch.set_edgecolor("#d0d0d0")


def save(fig, path):
    fig.savefig(path, dpi=DPI)
    plt.close(fig)
    return path
