#!/usr/bin/env python3
"""Makes the LV2 bundle's metadata say what the LV2 specifications define, where Debian's JUCE 7.0.5
(juce_lv2_helper) writes otherwise; `lv2_validate` (Debian's lv2-dev) reported each of these:

- the plugin is also a doap:Project (it carries doap:maintainer and doap:release, whose domain that is);
- the maintainer's empty foaf:mbox <> (a file URL in lv2info) is left out;
- the project gets its licence (doap:license), homepage (doap:homepage) and a description that says what it
  is (JUCE writes the product name again), as the command line gives them;
- the presets' state key <...:Program> is declared: an rdf:Property with a label and an xsd:int range;
- the UI lists ui:noUserResize (a feature) as extension data and opts:interface (extension data) as an
  optional feature: each is taken out of the list it does not belong to (ui:resize is offered, so the UI
  does not claim noUserResize at all).

- a switch or a list is said by the parameter's datatype, not by port properties: JUCE attaches
  lv2:portProperty lv2:enumeration (and lv2:toggled) to its lv2:Parameter subjects, but lv2:portProperty
  belongs to ports only. A switch becomes rdfs:range atom:Bool and a list rdfs:range atom:Int, each keeping
  its labelled scale points (which lv2core allows on a parameter) and integer bounds. Ardour then offers a
  toggle and integer steps where it offered sliders (it reads a property's datatype, not port properties);
  JUCE's LV2 host reads both, and the plugin takes a host's atom:Bool and atom:Int values as numbers.
- the plugin's bypass parameter is not offered as a property: JUCE's wrapper sets it from the lv2:enabled
  port at every block, so a value a host sent to the property was undone at once (Ardour listed it as a
  control that did nothing). The host's own bypass reaches the plugin through that port.

usage: lv2_metadata_fixes.py BUNDLE_DIR LICENSE_URI HOMEPAGE_URI DESCRIPTION
       (rewrites dsp.ttl and ui.ttl in place)
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


PARAMETER = re.compile(r"(?ms)^plug:\S+\n\ta lv2:Parameter ;.*?\.\n")
PORT_PROPERTY = re.compile(r"\n\tlv2:portProperty ([^;]+);")


BYPASS = "bypass"  # the parameter id of the plugin's getBypassParameter (EngineParameters.cpp)


def without_bypass_property(text):
    """The dsp.ttl without the bypass parameter's block and its patch:writable / patch:readable entries."""
    if "lv2:designation lv2:enabled" not in text:
        raise ValueError("no lv2:enabled port to carry the bypass")
    text, blocks = re.subn(r"(?ms)^plug:%s\n\ta lv2:Parameter ;.*?\.\n\n" % BYPASS, "", text)
    text, entries = re.subn(r"\n\t\tplug:%s ," % BYPASS, "", text)
    if (blocks, entries) not in ((1, 2), (0, 0)):  # (0, 0): already done
        raise ValueError("the bypass parameter in %d blocks and %d lists, expected 1 and 2" % (blocks, entries))
    return text


def integer_bounds(block):
    """lv2:default, lv2:minimum and lv2:maximum written as integers (JUCE writes them as floats)."""
    def whole(m):
        value = float(m.group(2))
        if value != round(value):
            raise ValueError("a non-integer %s %s on a switch or list" % (m.group(1), m.group(2)))
        return "lv2:%s %d" % (m.group(1), round(value))
    return re.sub(r"lv2:(default|minimum|maximum) ([0-9.eE+-]+)", whole, block)


def typed_parameter(block):
    """One parameter block with its port properties said as its datatype."""
    m = PORT_PROPERTY.search(block)
    if not m:
        return block
    properties = {p.strip() for p in m.group(1).split(",")}
    if not properties <= {"lv2:enumeration", "lv2:toggled"} or "rdfs:range atom:Float ;" not in block:
        raise ValueError("a parameter with port properties %s of a form JUCE does not write" % m.group(1))
    datatype = "atom:Bool" if "lv2:toggled" in properties else "atom:Int"
    block = block.replace(m.group(0), "").replace("rdfs:range atom:Float ;", "rdfs:range %s ;" % datatype)
    return integer_bounds(block)


def fix_dsp(text, license_uri, homepage, description):
    text = PARAMETER.sub(lambda m: typed_parameter(m.group(0)), without_bypass_property(text))
    text = re.sub(r"\n\t\tfoaf:mbox <> ;", "", text)
    m = re.search(r"(?m)^<([^>]+)>\n\tui:ui <[^>]+> ;\n\ta lv2:InstrumentPlugin[ ,a-zA-Z:]* ;", text)
    if not m:
        raise ValueError("no plugin subject of the form JUCE writes")
    plugin = m.group(1)
    text = replace_once(text, "\ta lv2:InstrumentPlugin ;", "\ta lv2:InstrumentPlugin , doap:Project ;",
                        "plugin type")
    if "doap:license" not in text:
        text = replace_once(text, '\tdoap:description "%s" ;\n' % re.search(r'doap:name "([^"]*)"', text).group(1),
                            '\tdoap:description "%s" ;\n\tdoap:license <%s> ;\n\tdoap:homepage <%s> ;\n'
                            % (description.replace('"', "'"), license_uri, homepage), "doap:description")
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
    if len(argv) != 4:
        print(__doc__, file=sys.stderr)
        return 1
    bundle, license_uri, homepage, description = argv
    for name, fix in (("dsp.ttl", lambda t: fix_dsp(t, license_uri, homepage, description)), ("ui.ttl", fix_ui)):
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
