#!/usr/bin/env python3
"""The model-form tolerance of rosin discover's verdict, measured: how far Rosin's calibrated model stays
from datasets that another simulator of the same physics made with nothing hidden.

Reads the `maps.json` that `rosin discover DATASET --report DIR` writes (every trial's measured and
calibrated features and its sigma) for datasets with no hidden effect, and prints per feature the tau at
which the verdict's own statistic, the mean of min(z^2, 9) with z = d / sqrt(sigma^2 + tau^2), falls to its
null value 1 on each dataset, and the largest over the datasets (the tolerance that leaves every one of them
clean). Features measured only in Helmholtz motion are compared where both sides show it, the others count
z = 3 where one side lacks them, as the verdict does (Source/lab/discovery/discover/GapMeasure.cpp).

With --score TABLE (e.g. pitchCents=5.9,harmonicTilt=2.0) it scores the datasets instead: the verdict's
test on the final model (the remaining gap's p, Bonferroni over features, and its feature) with that table,
as rosin discover computes it, so a table can be judged on datasets without running discover again.

    python3 Resources/scripts/model_form_tolerance.py REPORT_DIR [REPORT_DIR ...] [--json OUT]
    python3 Resources/scripts/model_form_tolerance.py REPORT_DIR [REPORT_DIR ...] --score TABLE
"""
import argparse
import json
import math
import sys

HELMHOLTZ = {"pitchCents", "harmonicTilt", "slipFraction", "loopArea"}
CATEGORICAL = {"regime"}
MISSING_Z = 3.0
MIN_TRIALS = 3
TAU_CEILING = 1e3  # x the feature's median sigma: "no finite tolerance"


def comparisons(maps, feature, side="calibrated"):
    """(d, sigma) pairs; d None where one side lacks the feature (z = +-3 whatever tau)."""
    pairs = []
    for t in maps["trials"]:
        m, c, s = t["measured"].get(feature), t[side].get(feature), t["sigma"].get(feature)
        if s is None:
            continue
        if feature in HELMHOLTZ and (m is None or c is None):
            continue
        if m is None and c is None:
            continue
        pairs.append((None if m is None or c is None else m - c, s))
    return pairs


def statistic(pairs, tau):
    total = 0.0
    for d, s in pairs:
        z2 = MISSING_Z ** 2 if d is None else d * d / (s * s + tau * tau)
        total += min(z2, MISSING_Z ** 2)
    return total / len(pairs)


def tolerance(pairs):
    """The smallest tau with mean min(z^2, 9) <= 1 (0 if already; inf if no tau reaches it)."""
    if statistic(pairs, 0.0) <= 1.0:
        return 0.0
    sigmas = sorted(s for _, s in pairs)
    hi = TAU_CEILING * sigmas[len(sigmas) // 2]
    if statistic(pairs, hi) > 1.0:
        return math.inf
    lo = 0.0
    for _ in range(100):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if statistic(pairs, mid) > 1.0 else (lo, mid)
    return hi


def categorical_statistic(maps, feature):
    """The regime's sum of min(z^2, 9) and count: z = 0 where the regimes agree, min(3, 1 / sqrt(q)) not."""
    total, n = 0.0, 0
    for t in maps["trials"]:
        m, c, q = t["measured"].get(feature), t["final"].get(feature), t["sigma"].get(feature)
        if q is None or (m is None and c is None):
            continue
        z = MISSING_Z if m is None or c is None else (0.0 if m == c else min(MISSING_Z, 1.0 / math.sqrt(q)))
        total, n = total + z * z, n + 1
    return total, n


def remaining_gap(maps, table):
    """(p, feature) of the verdict's test on the final model with the tolerance `table`."""
    worst, tested = (1.0, None), 0
    for f in maps["trials"][0]["measured"]:
        if f in CATEGORICAL:
            x, n = categorical_statistic(maps, f)
        else:
            pairs = comparisons(maps, f, "final")
            n = len(pairs)
            x = statistic(pairs, table.get(f, 0.0)) * n if n else 0.0
        if n < MIN_TRIALS:
            continue
        tested += 1
        spread = 2.0 / (9.0 * n)  # Wilson-Hilferty: chi-square with n degrees of freedom
        normal = ((x / n) ** (1.0 / 3.0) - (1.0 - spread)) / math.sqrt(spread)
        p = 0.5 * math.erfc(normal / math.sqrt(2.0))
        if p < worst[0]:
            worst = (p, f)
    return min(1.0, worst[0] * max(tested, 1)), worst[1]


def score(maps, text):
    table = {k: float(v) for k, v in (item.split("=") for item in text.split(",") if item)}
    for name, m in maps.items():
        p, feature = remaining_gap(m, table)
        print("%-40s remaining p %.3g (%s): %s" % (name.rstrip("/").split("/")[-1], p, feature,
                                                  "no-significant-discrepancy" if p >= 0.01 else "unexplained"))


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("reports", nargs="+")
    parser.add_argument("--json")
    parser.add_argument("--score")
    args = parser.parse_args(argv)
    maps = {r: json.load(open(r.rstrip("/") + "/maps.json")) for r in args.reports}
    if args.score:
        return score(maps, args.score)
    features = [f for f in maps[args.reports[0]]["trials"][0]["measured"] if f not in CATEGORICAL]
    result = {}
    print("%-18s %s  largest" % ("feature", "  ".join("%12s" % r.rstrip("/").split("/")[-1][:12] for r in args.reports)))
    for f in features:
        per = {}
        for r in args.reports:
            pairs = comparisons(maps[r], f)
            per[r] = tolerance(pairs) if len(pairs) >= MIN_TRIALS else None
        known = [v for v in per.values() if v is not None]
        largest = max(known) if known else None
        result[f] = {"perDataset": per, "largest": largest}
        cells = "  ".join("%12s" % ("-" if v is None else "%.4g" % v) for v in per.values())
        print("%-18s %s  %s" % (f, cells, "-" if largest is None else "%.4g" % largest))
    if args.json:
        with open(args.json, "w") as out:
            json.dump(result, out, indent=1)


if __name__ == "__main__":
    main(sys.argv[1:])
