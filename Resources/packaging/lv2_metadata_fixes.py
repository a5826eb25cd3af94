#!/usr/bin/env python3
"""Makes the LV2 bundle's metadata say what the LV2 specifications define, where Debian's JUCE 7.0.5
(juce_lv2_helper) writes otherwise; `lv2_validate` (Debian's lv2-dev) reported each of these:

- the plugin is also a doap:Project (it carries doap:maintainer and doap:release, whose domain that is);
- the maintainer's empty foaf:mbox <> (a file URL in lv2info) is left out;
- the presets' state key <...:Program> is declared: an rdf:Property with a label and an xsd:int range;
- the UI lists ui:noUserResize (a feature) as extension data and opts:interface (extension data) as an
  optional feature: each is taken out of the list it does not belong to (ui:resize is offered, so the UI
  does not claim noUserResize at all).

The toggle and enumeration port properties JUCE attaches to its lv2:Parameter subjects are kept: hosts read
them, and the specification has no parameter-level equivalent.

usage: lv2_metadata_fixes.py BUNDLE_DIR     (rewrites dsp.ttl, manifest.ttl and ui.ttl in place)
Exit status 0, or 1 when a file cannot be read or does not hold what JUCE writes.
"""
import os
import re
import sys

PROGRAM_KEY = """
<%s:Program>
\ta rdf:Property ;
\trdfs:label "Program" ;
\trdfs:comment "The factory program a preset selects (its index)." ;
\trdfs:range xsd:int .
"""


def replace_once(text, old, new, what):
    if new in text and old not in text:
        return text  # already fixed (run twice)
    if text.count(old) != 1:
        raise ValueError("expected one %s" % what)
    return text.replace(old, new)


def fix_dsp(text):
    text = re.sub(r"\n\t\tfoaf:mbox <> ;", "", text)
    m = re.search(r"(?m)^<([^>]+)>\n\tui:ui <[^>]+> ;\n\ta lv2:InstrumentPlugin[ ,a-zA-Z:]* ;", text)
    if not m:
        raise ValueError("no plugin subject of the form JUCE writes")
    plugin = m.group(1)
    text = replace_once(text, "\ta lv2:InstrumentPlugin ;", "\ta lv2:InstrumentPlugin , doap:Project ;",
                        "plugin type")
    if "<%s:Program>" % plugin not in text:
        if "@prefix rdf:" not in text or "@prefix rdfs:" not in text or "@prefix xsd:" not in text:
            raise ValueError("rdf, rdfs or xsd prefix missing")
        text = text.rstrip("\n") + "\n" + PROGRAM_KEY % plugin
    return text


def fix_ui(text):
    text = replace_once(text, "\t\topts:interface ,\n\t\tui:noUserResize ,\n", "\t\topts:interface ,\n",
                        "ui:noUserResize in the UI's extension data")
    return replace_once(text, "\t\tui:resize ,\n\t\topts:interface ,\n\t\topts:options ;",
                        "\t\tui:resize ,\n\t\topts:options ;", "opts:interface among the UI's features")


def main(argv):
    if len(argv) != 1:
        print(__doc__, file=sys.stderr)
        return 1
    bundle = argv[0]
    for name, fix in (("dsp.ttl", fix_dsp), ("ui.ttl", fix_ui)):
        path = os.path.join(bundle, name)
        try:
            with open(path) as f:
                text = fix(f.read())
        except (OSError, ValueError) as e:
            print("lv2_metadata_fixes: %s: %s" % (path, e), file=sys.stderr)
            return 1
        with open(path, "w") as f:
            f.write(text)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
