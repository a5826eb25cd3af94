"""Schelleng figures: regime diagram, colour maps and the A/B comparison.

Axes are log-log (beta across, bow force up), as in [Galluzzo2017] Fig. 3.
"""

import numpy as np
from matplotlib import colors
from matplotlib.lines import Line2D
from matplotlib.patches import Patch

import scan_style as style
from scan_io import REGIMES
from scan_style import plt

FIGSIZE = (10.0, 6.4)
# Beyond this many cells across, symbols would be specks: draw regime colours.
MAX_SYMBOL_CELLS = 40


def bow_speed_text(scan):
    speed = (scan.meta.get("theory") or {}).get("bowSpeed")
    if not isinstance(speed, (int, float)):
        speeds = scan.values["bowSpeed"][np.isfinite(scan.values["bowSpeed"])]
        speed = speeds[0] if speeds.size and np.all(speeds == speeds[0]) else None
    return f"v_b = {speed:g} m/s" if speed is not None else "v_b varies"


def _new_axes(scan, headline, subtitle="", details=True):
    fig, ax = plt.subplots(figsize=FIGSIZE, layout="constrained")
    ax.set_xscale("log")
    ax.set_yscale("log")
    x = style.edges(scan.betas, log=True)
    y = style.edges(scan.forces, log=True)
    ax.set_xlim(x[0], x[-1])
    ax.set_ylim(y[0], y[-1])
    ax.set_xlabel(style.BETA_LABEL)
    ax.set_ylabel(style.FORCE_LABEL)
    second = " · ".join(t for t in (subtitle, details and style.run_details(scan.meta)) if t)
    style.fit_title(fig, f"{headline}: {style.describe(scan.meta)} · {bow_speed_text(scan)}"
                    + (f"\n{second}" if second else ""))
    style.log_ticks(ax)
    return fig, ax


def _helmholtz_fraction(scan):
    ran = scan.regime >= 0
    return np.count_nonzero(scan.regime == 0) / max(np.count_nonzero(ran), 1)


def symbol_size(scan):
    """Marker size (points) that fills about half of a cell's width."""
    cells = max(len(scan.betas), len(scan.forces))
    return float(np.clip(0.5 * 6.5 * 72 / cells, 2.5, 11.0))


def draw_regime_symbols(ax, scan, regime, mask=None, alpha=1.0):
    """One scatter per regime so each gets its own legend entry."""
    beta, force = np.meshgrid(scan.betas, scan.forces, indexing="ij")
    size = symbol_size(scan)
    handles = []
    for index, name in enumerate(REGIMES):
        marker, colour, filled, scale = style.REGIME_STYLE[name]
        chosen = regime == index if mask is None else (regime == index) & mask
        s = (size * scale) ** 2
        kwargs = dict(marker=marker, s=s, alpha=alpha, linewidths=0.6 + size / 10)
        if filled:
            kwargs.update(facecolors=colour, edgecolors="white" if marker != "." else colour)
            kwargs["linewidths"] = 0.3
        elif marker == "s":
            kwargs.update(facecolors="none", edgecolors=colour)
        else:
            kwargs.update(c=colour)
        ax.scatter(beta[chosen], force[chosen], zorder=3, **kwargs)
        count = np.count_nonzero(regime == index)
        handles.append(ax.scatter([], [], label=f"{name} ({count})", **kwargs))
    return handles


def draw_regime_image(ax, scan, regime):
    """Dense grids: each cell filled with its regime colour; returns legend patches."""
    palette = colors.ListedColormap([style.REGIME_FILL[name] for name in REGIMES])
    image = np.ma.masked_less(regime, 0).astype(float)
    ax.pcolormesh(style.edges(scan.betas, True), style.edges(scan.forces, True), image.T,
                  cmap=palette, vmin=-0.5, vmax=len(REGIMES) - 0.5, shading="flat")
    return [Patch(facecolor=style.REGIME_FILL[name], edgecolor="#999999",
                  label=f"{name} ({np.count_nonzero(regime == i)})")
            for i, name in enumerate(REGIMES)]


def draw_theory(ax, scan, outline=False):
    """Eqs. 6.2/6.3 as solid lines and the scan's fitted edges dashed; outlined
    in white over colour maps, where a bare line can vanish into the colours."""
    theory = scan.meta.get("theory") or {}
    beta = np.geomspace(*ax.get_xlim(), 200)
    lines = []
    for key, label, colour, dash in (
            ("fmaxCoefficient", "Schelleng max (eq. 6.2)", style.MAX_LINE_COLOUR, "-"),
            ("fminTotalCoefficient", "Schelleng min, body + string losses (eq. 6.5)",
             style.MIN_LINE_COLOUR, "-"),
            ("fminCoefficient", "Schelleng/Raman min, body only (eq. 6.5)", style.MIN_LINE_COLOUR, ":")):
        coefficient = theory.get(key)
        if isinstance(coefficient, (int, float)) and coefficient > 0:
            power = 1 if key == "fmaxCoefficient" else 2
            lines += ax.plot(beta, coefficient / beta ** power, dash, color=colour, lw=1.8,
                             label=f"{label}: {coefficient:.3g}/β" + ("²" if power == 2 else ""))
    boundaries = scan.meta.get("boundaries") or {}
    for key, colour in (("upper", style.MAX_LINE_COLOUR), ("lower", style.MIN_LINE_COLOUR)):
        fit = boundaries.get(key) if isinstance(boundaries, dict) else None
        if isinstance(fit, dict) and all(isinstance(fit.get(k), (int, float))
                                         for k in ("slope", "intercept")):
            force = 10 ** (fit["intercept"] + fit["slope"] * np.log10(beta))
            points = f", {fit['points']} pts" if "points" in fit else ""
            lines += ax.plot(beta, force, "--", color=colour, lw=1.6,
                             label=f"fitted {key} edge: slope {fit['slope']:.2f}{points}")
    if outline:
        for line in lines:
            ax.plot(*line.get_data(), color="white", lw=3.6, alpha=0.8,
                    zorder=line.get_zorder() - 0.1, solid_capstyle="butt")
    return lines


def _draw_regimes(ax, scan, regime):
    if max(len(scan.betas), len(scan.forces)) <= MAX_SYMBOL_CELLS:
        return draw_regime_symbols(ax, scan, regime)
    return draw_regime_image(ax, scan, regime)


def schelleng_diagram(scan, path):
    fig, ax = _new_axes(scan, "Schelleng diagram")
    handles = _draw_regimes(ax, scan, scan.regime)
    lines = draw_theory(ax, scan)
    helmholtz = np.count_nonzero(scan.regime == 0)
    ax.set_title(f"Helmholtz motion in {helmholtz} of {np.count_nonzero(scan.regime >= 0)} "
                 f"cells ({style.percent(_helmholtz_fraction(scan))})", color="#333333")
    ax.legend(handles=handles + lines, loc="upper left", bbox_to_anchor=(1.01, 1.0),
              title="steady regime (cells)", frameon=False, borderaxespad=0)
    return style.save(fig, path)


def schelleng_map(scan, path, spec):
    """Colour map of one per-cell quantity over (beta, force); empty cells stay blank."""
    fig, ax = _new_axes(scan, spec.headline, spec.definition)
    values = scan.values[spec.column]
    lo, hi, extend = style.robust_limits(values)
    mesh = ax.pcolormesh(style.edges(scan.betas, True), style.edges(scan.forces, True),
                         np.ma.masked_invalid(values).T, cmap=spec.cmap, vmin=lo, vmax=hi)
    style.hatch_blank(ax)
    fig.colorbar(mesh, ax=ax, label=spec.bar_label, extend=extend, shrink=0.9, pad=0.02)
    lines = draw_theory(ax, scan, outline=True)
    if lines:
        ax.legend(handles=lines, loc="lower left", fontsize=7, framealpha=0.85)
    blank = np.count_nonzero(~np.isfinite(values))
    ax.set_title(f"hatched: {blank} cells without a slip", color="#333333")
    return style.save(fig, path)


def schelleng_compare(a, b, names, path):
    """[Galluzzo2017] Figs. 9-11: where Helmholtz motion is found in A, B, both, neither;
    B's regime symbol on each cell, ringed where the regime changed."""
    changes = style.meta_changes(a.meta, b.meta)
    fig, ax = _new_axes(a, "Schelleng comparison", style.changes_text(changes), details=False)
    h_a, h_b = a.regime == 0, b.regime == 0
    category = np.where(h_a & h_b, 0, np.where(h_a, 1, np.where(h_b, 2, 3)))
    category = np.ma.masked_where((a.regime < 0) | (b.regime < 0), category)
    fills = ("#8fbf7f", "#f1a340", "#6baed6", "#ffffff")
    labels = ("Helmholtz in both", f"Helmholtz only in A ({names[0]})",
              f"Helmholtz only in B ({names[1]})", "Helmholtz in neither")
    ax.pcolormesh(style.edges(b.betas, True), style.edges(b.forces, True), category.T,
                  cmap=colors.ListedColormap(fills), vmin=-0.5, vmax=3.5)
    patches = [Patch(facecolor=f, edgecolor="#999999",
                     label=f"{t} ({np.count_nonzero(category == i)})")
               for i, (f, t) in enumerate(zip(fills, labels))]
    changed = (a.regime != b.regime) & (a.regime >= 0) & (b.regime >= 0)
    handles = _draw_changes(ax, b, changed)
    fa, fb = _helmholtz_fraction(a), _helmholtz_fraction(b)
    ax.set_title(f"Helmholtz fraction {style.percent(fa)} (A) → {style.percent(fb)} (B), "
                 f"{100 * (fb - fa):+.1f} points · {np.count_nonzero(changed)} cells "
                 "changed regime",
                 color="#333333")
    ax.legend(handles=patches + handles, loc="upper left", bbox_to_anchor=(1.01, 1.0),
              frameon=False, borderaxespad=0, title=f"A: {names[0]}\nB: {names[1]}")
    return style.save(fig, path)


def _draw_changes(ax, b, changed):
    """Symbols of B: bold and ringed where the regime changed, faint elsewhere."""
    if max(len(b.betas), len(b.forces)) > MAX_SYMBOL_CELLS:
        beta, force = np.meshgrid(b.betas, b.forces, indexing="ij")
        ax.scatter(beta[changed], force[changed], s=4, c="#d7191c", lw=0, zorder=3)
        return [Line2D([], [], ls="", marker="o", ms=3, color="#d7191c",
                       label="regime changed (A → B)")]
    handles = draw_regime_symbols(ax, b, b.regime, mask=changed)
    draw_regime_symbols(ax, b, b.regime, mask=~changed, alpha=0.25)
    beta, force = np.meshgrid(b.betas, b.forces, indexing="ij")
    ring = (1.75 * symbol_size(b)) ** 2
    ax.scatter(beta[changed], force[changed], s=ring, facecolors="none",
               edgecolors="#d7191c", linewidths=0.9, zorder=4)
    ring_handle = Line2D([], [], ls="", marker="o", ms=9, mfc="none", mec="#d7191c",
                         mew=0.9, label="regime changed (symbol: B)")
    for h in handles:  # counts in the legend refer to B
        h.set_label(h.get_label().replace("(", "(B: ", 1))
    return [ring_handle] + handles
