#!/usr/bin/env python3
"""Puts the LV2 metadata's choices on the values the plugin reads: Debian's JUCE 7.0.5 writes each choice
parameter's lv2:scalePoint values as its normalised positions (k / (n - 1): "viscous" of six friction laws
at 0.6) while it gives the parameter's lv2:minimum and lv2:maximum on the real range (0 and 5) and reads
what a host sends on that range, so a host that offers the list set the wrong choice (0.6 rounds to 1,
"reconstructed"). Rewrites, in the dsp.ttl JUCE's juce_lv2_helper wrote, every parameter whose n scale points
sit at k / (n - 1) on a range 0 .. n - 1 to the values 0 .. n - 1; anything else is left as written.

usage: lv2_choice_values.py DSP.TTL        (rewrites the file in place; prints what it changed)
Exit status 0, or 1 when the file cannot be read or a choice parameter is not of the expected form.
"""
import re
import sys

BLOCK = re.compile(r"(?ms)^(plug:\S+)\n\ta lv2:Parameter ;.*?\.\n")
VALUE = re.compile(r"rdf:value ([0-9.eE+-]+) ;")


def number(block, key):
    m = re.search(r"lv2:%s ([0-9.eE+-]+)" % key, block)
    return float(m.group(1)) if m else None


def fix_block(block):
    """The block with its scale points on the real range, and whether it changed."""
    values = [float(v) for v in VALUE.findall(block)]
    n = len(values)
    low, high = number(block, "minimum"), number(block, "maximum")
    if n < 2 or low != 0.0 or high != float(n - 1) or high == 1.0:
        return block, False  # not a choice list, or one whose positions already are its values
    if values == [float(k) for k in range(n)]:
        return block, False  # already on the real range (run twice)
    if any(abs(v - k / (n - 1)) > 1e-6 for k, v in enumerate(values)):
        raise ValueError("scale points %s are not at k / (n - 1)" % values)
    index = iter(range(n))
    return VALUE.sub(lambda m: "rdf:value %d ;" % next(index), block), True


def main(argv):
    if len(argv) != 1:
        print(__doc__, file=sys.stderr)
        return 1
    path = argv[0]
    try:
        with open(path) as f:
            text = f.read()
        changed = []

        def fix(m):
            block, did = fix_block(m.group(0))
            if did:
                changed.append(m.group(1))
            return block

        fixed = BLOCK.sub(fix, text)
    except (OSError, ValueError) as e:
        print("lv2_choice_values: %s: %s" % (path, e), file=sys.stderr)
        return 1
    with open(path, "w") as f:
        f.write(fixed)
    print("lv2_choice_values: %s: choices on their values for %s" % (path, ", ".join(changed) or "none"))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
