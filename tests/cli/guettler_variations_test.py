#!/usr/bin/env python3
"""[Galluzzo2017]'s Fig. 12 model variations, run through `rosin scan guettler` and measured by
Resources/scripts/guettler_structure.py: classical curve, beta 0.0899, 120 x 120 (the paper: 300 x 300; on the 300
grid the shares below agree with the 120 ones within 0.2 points, the medians within 0.4 periods). Statements met are
asserted with their tolerance; those missed assert the measured direction (known discrepancies).
Usage: guettler_variations_test.py ROSIN SOURCE_DIR
"""
import os
import subprocess
import sys
import tempfile

rosin, source = sys.argv[1], sys.argv[2]
sys.path.insert(0, os.path.join(source, "Resources", "scripts"))
import guettler_structure  # noqa: E402

VARIANTS = {"base": ["--friction", "classical"],
            "finger": ["--friction", "classical", "--finger-damping"],
            "rigid": ["--friction", "classical", "--rigid-bridge"],
            "notorsion": ["--friction", "classical", "--no-torsion"],
            "nostiff": ["--friction", "classical", "--no-stiffness"],
            "thermal": ["--friction", "plastic"]}
failures = []


def check(condition, what):
    print(("ok   " if condition else "FAIL ") + what)
    if not condition:
        failures.append(what)


with tempfile.TemporaryDirectory() as work:
    s = {}
    for name, args in VARIANTS.items():
        out = os.path.join(work, name)
        subprocess.run([rosin, "scan", "guettler", "--beta", "0.0899", "--grid", "120", "--no-figures",
                        "--out", out] + args, check=True, stdout=subprocess.DEVNULL)
        s[name] = guettler_structure.summarise(out)
        r = s[name]
        print(f"{name:10s} share20 {100 * r['share20']:5.1f} %  median {r['medianTransient']:6.2f}  "
              f"radial A {r['radialAnisotropy']:6.2f}  spread {r['angularSpread']:6.2f} deg")
    base = s["base"]
    # "the case with no torsion ... shows a surprisingly small number of Helmholtz samples": measured 0-1 cells.
    check(s["notorsion"]["share20"] < 0.25 * base["share20"], "no torsion: far fewer successes")
    # "the finger-stopped case shows a larger number of Helmholtz occurrences" (measured 3.8 % vs 2.9 %) "and
    # generally shorter transients" (not met: the median is the base's within 1 %).
    check(s["finger"]["share20"] > 1.15 * base["share20"], "finger-stopped: more successes")
    check(abs(s["finger"]["medianTransient"] / base["medianTransient"] - 1) < 0.05,
          "finger-stopped: median transient as the base's (known discrepancy: the paper's are shorter)")
    # "a rigid termination reduces the number of Helmholtz samples": not met, it raises them (3.7 % vs 2.9 %).
    check(s["rigid"]["share20"] > base["share20"], "rigid bridge: more successes (known discrepancy)")
    # No bending stiffness: "a larger number of successful samples, the average number of unsuccessful
    # pre-Helmholtz periods is reduced" (both met), "more densely clustered around the center-line" (not met).
    check(s["nostiff"]["share20"] > 1.5 * base["share20"], "no stiffness: more successes")
    check(s["nostiff"]["medianTransient"] < 0.98 * base["medianTransient"], "no stiffness: shorter transients")
    check(s["nostiff"]["angularSpread"] > base["angularSpread"],
          "no stiffness: wider spread about the centre line (known discrepancy)")
    # "radial lines which contain apparently similar transients" with the friction curve, not with the thermal
    # model: A >= 1.5 as the script defines it (measured 3.5 and 1.2).
    for name in ("base", "finger", "rigid", "nostiff"):
        check(s[name]["radialAnisotropy"] >= 2.0, f"{name}: radial lines (A >= 2)")
    check(s["thermal"]["radialAnisotropy"] < 1.5, "thermal: no radial lines (A < 1.5)")
    # [Galluzzo2017] Fig. 12b against 12a: the thermal model's Helmholtz share far above the curve's.
    check(s["thermal"]["share20"] > 3 * base["share20"], "thermal: more successes than the classical curve")

sys.exit(1 if failures else 0)
