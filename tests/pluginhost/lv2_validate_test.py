#!/usr/bin/env python3
"""The built LV2 bundle against the LV2 specifications: Debian's lv2_validate finds no error but the toggle and
enumeration port properties JUCE attaches to its parameters (one per such property, which
Resources/packaging/lv2_metadata_fixes.py keeps on purpose), and lv2info's view has no empty e-mail address.

usage: lv2_validate_test.py LV2_VALIDATE BUNDLE_DIR
"""
import glob
import os
import re
import subprocess
import sys

KEPT = "Subject not in domain <http://lv2plug.in/ns/lv2core#Port>"


def main(validate, bundle):
    files = sorted(glob.glob(os.path.join(bundle, "*.ttl")))
    run = subprocess.run([validate] + files, capture_output=True, text=True)
    errors = [line.split("error: ", 1)[1].strip() for line in (run.stdout + run.stderr).splitlines()
              if "error: " in line and "Found " not in line]
    with open(os.path.join(bundle, "dsp.ttl")) as f:
        dsp = f.read()
    # One error per lv2:portProperty value on an lv2:Parameter subject.
    expected = 0
    for m in re.finditer(r"(?ms)^plug:\S+\n\ta lv2:Parameter ;(.*?)\.\n", dsp):
        for props in re.findall(r"lv2:portProperty ([^;]+);", m.group(1)):
            expected += len(props.split(","))
    other = [e for e in errors if e != KEPT]
    print("lv2_validate: %d errors, %d of them the parameters' port properties (expected %d)"
          % (len(errors), len(errors) - len(other), expected))
    ok = True
    if other:
        print("unexpected errors:\n  " + "\n  ".join(sorted(set(other))))
        ok = False
    if len(errors) - len(other) != expected:
        ok = False
    if "foaf:mbox <>" in dsp:
        print("the maintainer has an empty e-mail address (foaf:mbox <>)")
        ok = False
    return 0 if ok else 1


if __name__ == "__main__":
    if len(sys.argv) != 3:
        print(__doc__, file=sys.stderr)
        sys.exit(2)
    sys.exit(main(sys.argv[1], sys.argv[2]))
