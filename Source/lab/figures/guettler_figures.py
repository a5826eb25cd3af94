"""Guettler figures: one panel per beta over (acceleration across, force up).

[Galluzzo2017] Figs. 5-8 and 12 (transient length), 15-16 (mu_s, jump at first slip).
"""

import numpy as np
from matplotlib import colors
from matplotlib.lines import Line2D
from matplotlib.patches import Patch

import scan_style as style
from scan_style import plt

LEGEND_STRIP = 0.45  # inches kept free below the panels for the legend


def _panels(scan, headline, subtitle, details=True):
    fig, panels = style.panel_axes(len(scan.betas))
    height = fig.get_figheight()
    fig.get_layout_engine().set(rect=(0, LEGEND_STRIP / height, 1, 1 - LEGEND_STRIP / height))
    _, cols = style.panel_layout(len(scan.betas))
    style.label_outer(panels, cols, style.ACCEL_LABEL, style.FORCE_LABEL)
    second = " · ".join(t for t in (subtitle, details and style.run_details(scan.meta)) if t)
    style.fit_title(fig, f"{headline}: {style.describe(scan.meta)}\n{second}")
    return fig, panels


def _mesh(ax, scan, image, **kwargs):
    return ax.pcolormesh(style.edges(scan.third, False), style.edges(scan.forces, False),
                         image, shading="flat", **kwargs)


def _bottom_legend(fig, handles):
    fig.legend(handles=handles, loc="lower center", ncol=len(handles), frameon=False,
               bbox_to_anchor=(0.5, 0.0))


def _wedge(scan, beta):
    """Guettler's idealised wedge (lower, upper acceleration per newton) for beta."""
    entries = (scan.meta.get("theory") or {}).get("guettlerWedge") or []
    for entry in entries:
        if not isinstance(entry, dict) or not isinstance(entry.get("beta"), (int, float)):
            continue
        if np.isclose(entry["beta"], beta, rtol=1e-3):
            lower = entry.get("lowerAccelerationPerNewton")
            upper = entry.get("upperAccelerationPerNewton")
            if all(isinstance(v, (int, float)) and v > 0 for v in (lower, upper)):
                return lower, upper
    return None


def draw_wedge(ax, scan, beta, lw=1.3, colour=style.WEDGE_COLOUR):
    """Eq. 6.6: lower*F < a <= upper*F, i.e. force between a/upper and a/lower."""
    wedge = _wedge(scan, beta)
    if wedge is None:
        return False
    xlim, ylim = ax.get_xlim(), ax.get_ylim()
    a = np.array([0.0, xlim[1]])
    for per_newton in wedge:
        ax.plot(a, a / per_newton, color=colour, lw=lw, zorder=3)
    ax.set_xlim(xlim)
    ax.set_ylim(ylim)  # the lines run from the origin; keep the grid's view
    return True


def _transient_image(scan, i):
    """Transient length, with 'not reached' above the cap and 'no slip' below 0."""
    periods = scan.values["transientPeriods"][i]
    slipped = np.isfinite(scan.values["firstSlipTime"][i])
    image = np.where(np.isfinite(periods), periods,
                     np.where(slipped, style.TRANSIENT_CAP + 1, -1.0))
    return np.ma.masked_where(scan.regime[i] < 0, image)


def _reached(periods, ran):
    return np.count_nonzero(np.isfinite(periods) & ran) / max(np.count_nonzero(ran), 1)


def guettler_diagram(scan, path):
    reached = _reached(scan.values["transientPeriods"], scan.regime >= 0)
    fig, panels = _panels(scan, "Guettler diagrams",
                          "shade: periods from the first slip to Helmholtz motion · reached in "
                          f"{style.percent(reached)} of {np.count_nonzero(scan.regime >= 0)} cells")
    # [Galluzzo2017]'s shading: white = Helmholtz from the first slip, darker = longer, black = not reached.
    cmap = plt.get_cmap("gray_r").copy()
    cmap.set_over(style.NOT_REACHED_COLOUR)
    cmap.set_under(style.NO_SLIP_COLOUR)
    wedge_drawn = False
    for i, (ax, beta) in enumerate(zip(panels, scan.betas)):
        mesh = _mesh(ax, scan, _transient_image(scan, i), cmap=cmap, vmin=0,
                     vmax=style.TRANSIENT_CAP)
        style.hatch_blank(ax)  # only cells without a CSV row show it
        wedge_drawn |= draw_wedge(ax, scan, beta)
        reached = _reached(scan.values["transientPeriods"][i], scan.regime[i] >= 0)
        ax.set_title(f"{style.beta_text(beta)} · Helmholtz reached: {style.percent(reached)}")
    bar = fig.colorbar(mesh, ax=panels, shrink=0.85, aspect=30, pad=0.015,
                       ticks=np.arange(0, style.TRANSIENT_CAP + 1, 5))
    bar.set_label("transient length (periods after the first slip)")
    handles = [Patch(facecolor=style.NOT_REACHED_COLOUR, edgecolor="#999999",
                     label=f"not reached within {style.TRANSIENT_CAP:g} periods"),
               Patch(facecolor=style.NO_SLIP_COLOUR, edgecolor="#999999",
                     label="never slipped")]
    if scan.missing:
        handles.append(Patch(facecolor="white", edgecolor="#c0c0c0", hatch="////",
                             label="hatched: no row in scan.csv"))
    if wedge_drawn:
        handles.append(_wedge_handle())
    _bottom_legend(fig, handles)
    return style.save(fig, path)


def guettler_map(scan, path, spec):
    """One per-cell quantity per beta panel on a shared colour scale; empty cells blank."""
    values = scan.values[spec.column]
    fig, panels = _panels(scan, spec.headline, spec.definition)
    lo, hi, extend = style.robust_limits(values)
    for i, (ax, beta) in enumerate(zip(panels, scan.betas)):
        mesh = _mesh(ax, scan, np.ma.masked_invalid(values[i]), cmap=spec.cmap, vmin=lo,
                     vmax=hi)
        style.hatch_blank(ax)
        draw_wedge(ax, scan, beta, lw=0.9)
        ax.set_title(style.beta_text(beta))
    fig.colorbar(mesh, ax=panels, label=spec.bar_label, extend=extend, shrink=0.85,
                 aspect=30, pad=0.015)
    handles = [Patch(facecolor="white", edgecolor="#c0c0c0", hatch="////",
                     label="hatched: no slip (no value)")]
    if _wedge(scan, scan.betas[0]) is not None:
        handles.append(_wedge_handle())
    _bottom_legend(fig, handles)
    return style.save(fig, path)


# Cells where the two scans disagree about reaching Helmholtz at all.
LOST_COLOUR, GAINED_COLOUR, NEITHER_COLOUR = "#000000", "#e6ab02", "#d9d9d9"
COMPARE_WEDGE_COLOUR = "#1a9850"  # red would read as part of the diverging map


def guettler_compare(a, b, names, path):
    """Transient length B - A where both reach Helmholtz; categorical colours elsewhere."""
    changes = style.meta_changes(a.meta, b.meta)
    fig, panels = _panels(a, "Guettler comparison", f"transient length B − A · A: {names[0]}"
                          f" · B: {names[1]} · {style.changes_text(changes)}", details=False)
    diff = b.values["transientPeriods"] - a.values["transientPeriods"]
    span = max(1.0, float(np.nanmax(np.abs(diff)))) if np.isfinite(diff).any() else 1.0
    wedge_drawn = False
    for i, ax in enumerate(panels):
        mesh = _compare_panel(ax, a, b, i, span)
        wedge_drawn |= draw_wedge(ax, b, b.betas[i], colour=COMPARE_WEDGE_COLOUR)
    fig.colorbar(mesh, ax=panels, shrink=0.85, aspect=30, pad=0.015,
                 label="transient length B − A (periods; red: B slower)")
    handles = [Patch(facecolor=LOST_COLOUR, label="Helmholtz reached in A only"),
               Patch(facecolor=GAINED_COLOUR, label="Helmholtz reached in B only"),
               Patch(facecolor=NEITHER_COLOUR, label="reached in neither")]
    if wedge_drawn:
        handles.append(_wedge_handle(COMPARE_WEDGE_COLOUR))
    _bottom_legend(fig, handles)
    return style.save(fig, path)


def _compare_panel(ax, a, b, i, span):
    ta, tb = a.values["transientPeriods"][i], b.values["transientPeriods"][i]
    ran = (a.regime[i] >= 0) & (b.regime[i] >= 0)
    ra, rb = np.isfinite(ta), np.isfinite(tb)
    category = np.where(ra & ~rb, 0, np.where(rb & ~ra, 1, 2))
    _mesh(ax, b, np.ma.masked_where((ra & rb) | ~ran, category), vmin=-0.5, vmax=2.5,
          cmap=colors.ListedColormap([LOST_COLOUR, GAINED_COLOUR, NEITHER_COLOUR]))
    ax.set_title(f"{style.beta_text(b.betas[i])} · reached "
                 f"{style.percent(_reached(ta, ran))} → {style.percent(_reached(tb, ran))}")
    return _mesh(ax, b, np.ma.masked_where(~(ra & rb & ran), tb - ta), cmap="RdBu_r",
                 vmin=-span, vmax=span)


def _wedge_handle(colour=style.WEDGE_COLOUR):
    return Line2D([], [], color=colour, lw=1.3, label="Guettler's idealised wedge (eq. 6.6)")
