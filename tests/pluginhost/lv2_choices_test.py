#!/usr/bin/env python3
"""The built LV2 bundle's metadata gives every choice parameter's scale points on the range it declares and the
plugin reads: for a parameter with n scale points on lv2:minimum 0 .. lv2:maximum n - 1, the values 0 .. n - 1
in the order of the choices (Debian's JUCE writes k / (n - 1); Resources/packaging/lv2_choice_values.py puts
them right after the build). Also checks the three lists the host would have set wrongly by name.

usage: lv2_choices_test.py BUNDLE_DIR
"""
import re
import sys

EXPECTED = {"friction": ["classical", "reconstructed", "plastic", "viscous", "modified-bow", "modified-rod"],
            "string": ["auto", "I", "II", "III", "IV"],
            "output": ["radiated sound", "bridge force", "bridge velocity"]}


def parameters(text):
    """{name: (minimum, maximum, [(label, value), ...])} of every lv2:Parameter with scale points."""
    out = {}
    for m in re.finditer(r"(?ms)^plug:(\S+)\n\ta lv2:Parameter ;(.*?)\.\n", text):
        body = m.group(2)
        points = re.findall(r'rdfs:label "([^"]*)" ;\s*rdf:value ([0-9.eE+-]+) ;', body)
        if not points:
            continue
        low = float(re.search(r"lv2:minimum ([0-9.eE+-]+)", body).group(1))
        high = float(re.search(r"lv2:maximum ([0-9.eE+-]+)", body).group(1))
        out[m.group(1)] = (low, high, [(label, float(v)) for label, v in points])
    return out


def main(argv):
    with open(argv[0] + "/dsp.ttl") as f:
        found = parameters(f.read())
    failures = []
    for name, (low, high, points) in sorted(found.items()):
        values = [v for _, v in points]
        if low == 0.0 and high == len(points) - 1 and values != [float(k) for k in range(len(points))]:
            failures.append("%s: scale points %s on the range %g..%g, expected 0..%d" %
                            (name, values, low, high, len(points) - 1))
        if any(not low <= v <= high for v in values):
            failures.append("%s: a scale point outside %g..%g: %s" % (name, low, high, values))
    for name, labels in EXPECTED.items():
        if name not in found:
            failures.append("%s: no scale points in dsp.ttl" % name)
            continue
        got = [(label, v) for label, v in found[name][2]]
        if got != [(label, float(k)) for k, label in enumerate(labels)]:
            failures.append("%s: %s, expected %s at 0..%d" % (name, got, labels, len(labels) - 1))
    for f in failures:
        print("FAIL " + f)
    print("[figure] %d choice parameters checked, %d failures" % (len(found), len(failures)))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
