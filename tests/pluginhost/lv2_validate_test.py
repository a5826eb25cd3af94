#!/usr/bin/env python3
"""The built LV2 bundle against the LV2 specifications: Debian's lv2_validate finds no error in it, no
parameter carries a port property (their domain is lv2:Port; Resources/packaging/lv2_metadata_fixes.py says
a switch or a list by its datatype), the project names its licence, homepage, maintainer and what it is, and
lv2info's view has no empty e-mail address.

usage: lv2_validate_test.py LV2_VALIDATE BUNDLE_DIR
"""
import glob
import os
import re
import subprocess
import sys


def main(validate, bundle):
    files = sorted(glob.glob(os.path.join(bundle, "*.ttl")))
    run = subprocess.run([validate] + files, capture_output=True, text=True)
    errors = [line.split("error: ", 1)[1].strip() for line in (run.stdout + run.stderr).splitlines()
              if "error: " in line and "Found " not in line]
    with open(os.path.join(bundle, "dsp.ttl")) as f:
        dsp = f.read()
    print("lv2_validate: %d errors" % len(errors))
    ok = not errors
    if not re.search(r"Found 0 errors among \d+ files", run.stdout + run.stderr):
        print("lv2_validate did not say it found no error:\n" + (run.stdout + run.stderr)[-2000:])
        ok = False
    if errors:
        print("errors:\n  " + "\n  ".join(sorted(set(errors))))
    parameters = re.findall(r"(?ms)^plug:\S+\n\ta lv2:Parameter ;.*?\.\n", dsp)
    typed = [p for p in parameters if re.search(r"rdfs:range atom:(Bool|Int) ;", p)]
    print("%d parameters, %d of them switches or lists by datatype" % (len(parameters), len(typed)))
    if any("lv2:portProperty" in p for p in parameters):
        print("a parameter carries lv2:portProperty")
        ok = False
    if not typed:
        print("no parameter is a switch or a list: the metadata fix did not run")
        ok = False
    for needed in ("doap:license <", "doap:homepage <", "doap:maintainer [", "doap:description"):
        if needed not in dsp:
            print("the plugin's metadata has no " + needed.split()[0])
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
