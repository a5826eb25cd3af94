#!/usr/bin/env python3
"""Tests of Source/lab/figures/plot_discovery.py on a synthetic maps.json (unittest): maps are drawn for
every disagreeing feature whatever the verdict, with both axes and the colour scale labelled."""

import json
import os
import subprocess
import sys
import tempfile
import unittest


sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "support"))
import debian_python  # noqa: E402

debian_python.ensure("matplotlib")
import matplotlib  # noqa: E402

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

SCRIPT = os.path.join(os.path.dirname(__file__), "..", "..", "..", "Source", "lab", "figures", "plot_discovery.py")
sys.path.insert(0, os.path.dirname(SCRIPT))
import plot_discovery  # noqa: E402


def schelleng_maps():
    """One bow speed, three betas, two forces: a Schelleng scan's grid."""
    trials = [{"id": f"b{b}f{f}", "beta": beta, "force": force, "motion": 0.05,
               "measured": {"pitchCents": 1.0 + b}, "baseline": {"pitchCents": 0.5 * b},
               "calibrated": {"pitchCents": 0.8 * b}}
              for b, beta in enumerate((0.02, 0.06, 0.18)) for f, force in enumerate((0.1, 1.0))]
    return {"motionAxis": "bow speed (m/s)", "changed": [], "disagreeing": ["pitchCents"],
            "units": {"pitchCents": "cents"}, "adoptedEffects": 0, "trials": trials}


def synthetic_maps(adopted, disagreeing, changed):
    trials = []
    for i, force in enumerate((0.4, 0.8, 1.2)):
        for j, motion in enumerate((0.5, 1.0)):
            values = {"jump": 0.1 * i + 0.01 * j, "staticFriction": 1.0 + 0.1 * j}
            trials.append({"id": f"t{i}{j}", "beta": 0.0899, "force": force, "motion": motion,
                           "measured": values, "baseline": {k: v * 0.5 for k, v in values.items()},
                           "calibrated": {k: v * 0.8 for k, v in values.items()}, "final": values})
    return {"motionAxis": "bow acceleration (m/s^2)", "changed": changed, "disagreeing": disagreeing,
            "units": {"jump": "", "staticFriction": "", "firstSlipTime": "s"}, "adoptedEffects": adopted,
            "trials": trials}


class PlotDiscoveryTest(unittest.TestCase):
    def test_an_unexplained_verdict_still_maps_what_disagrees(self):
        maps = synthetic_maps(0, ["jump"], [])
        self.assertEqual(plot_discovery.mapped_features(maps), ["jump"])
        fig = plot_discovery.draw(maps, "jump", 0.0899)
        panels = [ax for ax in fig.axes if ax.get_title()]
        self.assertEqual([ax.get_title() for ax in panels],
                         ["measured", "baseline model", "baseline, calibrated"])
        for ax in panels:
            self.assertEqual(ax.get_xlabel(), "bow acceleration (m/s^2)")
        self.assertEqual(panels[0].get_ylabel(), "bow force (N)")
        colourbar = [ax for ax in fig.axes if not ax.get_title()][0]
        self.assertEqual(colourbar.get_ylabel(), "jump (dimensionless)")
        plt.close(fig)

    def test_an_adopted_effect_adds_its_panel_and_the_features_it_changed(self):
        maps = synthetic_maps(1, ["jump"], ["staticFriction", "jump"])
        self.assertEqual(plot_discovery.mapped_features(maps), ["jump", "staticFriction"])
        fig = plot_discovery.draw(maps, "staticFriction", 0.0899)
        self.assertIn("calibrated + adopted effect(s)", [ax.get_title() for ax in fig.axes])
        plt.close(fig)

    def test_the_script_writes_one_png_per_feature_and_beta(self):
        with tempfile.TemporaryDirectory() as folder:
            with open(os.path.join(folder, "maps.json"), "w") as f:
                json.dump(synthetic_maps(0, ["jump", "staticFriction"], []), f)
            subprocess.run([sys.executable, SCRIPT, folder], check=True, capture_output=True)
            pngs = sorted(n for n in os.listdir(folder) if n.endswith(".png"))
            self.assertEqual(pngs, ["map-jump-b0.0899.png", "map-staticFriction-b0.0899.png"])

    def test_a_schelleng_scan_is_drawn_over_beta_and_force_in_one_figure(self):
        maps = schelleng_maps()
        self.assertTrue(plot_discovery.is_schelleng(maps))
        self.assertFalse(plot_discovery.is_schelleng(synthetic_maps(0, ["jump"], [])))
        fig = plot_discovery.draw(maps, "pitchCents")
        panels = [ax for ax in fig.axes if ax.get_title()]
        for ax in panels:
            self.assertEqual(ax.get_xlabel(), "relative bow position beta (dimensionless)")
            self.assertEqual([t.get_text() for t in ax.get_xticklabels()], ["0.02", "0.06", "0.18"])
        self.assertEqual(fig._suptitle.get_text(), "pitchCents at bow speed 0.05 m/s")
        plt.close(fig)
        with tempfile.TemporaryDirectory() as folder:
            with open(os.path.join(folder, "maps.json"), "w") as f:
                json.dump(maps, f)
            subprocess.run([sys.executable, SCRIPT, folder], check=True, capture_output=True)
            self.assertEqual(sorted(n for n in os.listdir(folder) if n.endswith(".png")), ["map-pitchCents.png"])

    def test_a_feature_no_trial_has_draws_nothing(self):
        self.assertIsNone(plot_discovery.draw(synthetic_maps(0, ["firstSlipTime"], []), "firstSlipTime", 0.0899))


if __name__ == "__main__":
    unittest.main()
