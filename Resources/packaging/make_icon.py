#!/usr/bin/env python3
"""Draws Rosin's application icon (rosin.png, 256 x 256, and rosin.svg): a bow hair crossing a string, whose
Helmholtz corner runs along it, on a dark amber ground. Run from this folder: python3 make_icon.py"""
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
from matplotlib.patches import FancyBboxPatch

fig = plt.figure(figsize=(2.56, 2.56), dpi=100)
ax = fig.add_axes([0, 0, 1, 1])
ax.set_xlim(0, 1)
ax.set_ylim(0, 1)
ax.axis("off")
ax.add_patch(FancyBboxPatch((0.04, 0.04), 0.92, 0.92, boxstyle="round,pad=0,rounding_size=0.18",
                            facecolor="#3b2414", edgecolor="#c98b3c", linewidth=4))
# The string at its Helmholtz moment: two straight segments meeting at the corner.
ax.plot([0.14, 0.62, 0.86], [0.30, 0.50, 0.70], color="#f3e2c0", linewidth=6, solid_capstyle="round")
# The bow: stick and hair, crossing the string near the bridge end.
ax.plot([0.16, 0.84], [0.80, 0.20], color="#c98b3c", linewidth=10, solid_capstyle="round")
ax.plot([0.20, 0.86], [0.84, 0.26], color="#f8f1dc", linewidth=3, solid_capstyle="round")
# The rosin at the contact.
ax.add_patch(plt.Circle((0.585, 0.485), 0.045, color="#e8a33d", zorder=5))
fig.savefig("rosin.png", dpi=100, transparent=True)
fig.savefig("rosin.svg", transparent=True, metadata={"Date": None})
