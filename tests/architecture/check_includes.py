#!/usr/bin/env python3
"""Which folder may include which, checked: the rules are the table in Resources/docs/architecture.md (between
its include-rules markers), so the page and the check cannot drift.

A source file belongs to the deepest folder of the table that holds it (lab/discovery/io is a library of its
own inside lab/discovery). A rule's entries are folders of the table, group folders that hold several of them
(`core`, `lab`: any library under it), or external libraries (JUCE, Eigen, MPI, nlohmann-json). Also checked:
one include style (every quoted include is spelled from Source/, or for tests and benchmarks from their own
tree, never with ./ or ../), and tests that mirror the source folders.

Usage: check_includes.py [--root REPO]; exit status 1 with one line per violation.
"""
import argparse
import os
import re
import sys

EXTERNAL = {
    "JUCE": lambda inc: inc.startswith("juce_"),
    "Eigen": lambda inc: inc.startswith("Eigen/") or inc.startswith("unsupported/Eigen/"),
    "MPI": lambda inc: inc == "mpi.h",
    "nlohmann-json": lambda inc: inc.startswith("nlohmann/"),
}
# Headers a build step writes (juce_add_binary_data), not files of the tree.
GENERATED = {"FactoryPresetData.h"}
# Test folders that are not one library's: they test across libraries or check the repository itself.
CROSS_CUTTING_TESTS = {"architecture", "docs", "format", "fuzz", "golden", "host", "install", "pluginhost", "support"}
INCLUDE = re.compile(r'^\s*#\s*include\s*([<"])([^>"]+)[>"]', re.M)


def read_rules(page):
    """{folder: [entries]} from the markdown table between the include-rules markers."""
    text = open(page, encoding="utf-8").read()
    match = re.search(r"<!-- include-rules -->(.*?)<!-- /include-rules -->", text, re.S)
    if not match:
        sys.exit("%s: no table between <!-- include-rules --> and <!-- /include-rules -->" % page)
    rules = {}
    for line in match.group(1).splitlines():
        cells = [c.strip() for c in line.strip().strip("|").split("|")]
        if len(cells) != 2 or not cells[0].startswith("`"):
            continue
        folder = cells[0].strip("`")
        entries = [e.strip().strip("`") for e in cells[1].split(",") if e.strip() and e.strip() != "nothing"]
        rules[folder] = entries
    if not rules:
        sys.exit("%s: the include-rules table has no rows" % page)
    return rules


def library_of(path, libraries):
    """The deepest library folder holding `path` (relative to Source/), or None."""
    best = None
    for lib in libraries:
        if (path == lib or path.startswith(lib + "/")) and (best is None or len(lib) > len(best)):
            best = lib
    return best


def allows(entry, target, libraries):
    if entry == target:
        return True
    # A group folder (not itself a library) allows every library under it.
    return entry not in libraries and target.startswith(entry + "/")


def cpp_files(top):
    for folder, _, files in os.walk(top):
        for name in sorted(files):
            if name.endswith((".h", ".cpp")):
                yield os.path.join(folder, name)


def check_source(root, rules, problems):
    source = os.path.join(root, "Source")
    libraries = set(rules)
    for path in cpp_files(source):
        rel = os.path.relpath(path, source)
        me = library_of(rel, libraries)
        if me is None:
            problems.append("%s: in no folder of the include rules" % os.path.join("Source", rel))
            continue
        for kind, inc in INCLUDE.findall(open(path, encoding="utf-8").read()):
            where = "Source/%s: #include %s" % (rel, kind + inc + (">" if kind == "<" else '"'))
            if kind == "<":
                group = next((name for name, test in EXTERNAL.items() if test(inc)), None)
                if group and group not in rules[me]:
                    problems.append("%s: %s may not include %s (rules: %s)" % (where, me, group,
                                                                               ", ".join(rules[me])))
                continue
            if inc in GENERATED:
                continue
            if inc.startswith(".") or not os.path.isfile(os.path.join(source, inc)):
                problems.append("%s: spell includes from Source/ (no such file Source/%s)" % (where, inc))
                continue
            target = library_of(inc, libraries)
            if target != me and not any(allows(e, target, libraries) for e in rules[me]):
                problems.append("%s: %s may not include %s (rules: %s)" % (where, me, target,
                                                                           ", ".join(rules[me]) or "nothing"))


def check_tree_style(root, tree, problems):
    """Tests and benchmarks: quoted includes from Source/ or from their own tree, exactly one of them."""
    top = os.path.join(root, tree)
    for path in cpp_files(top):
        rel = os.path.relpath(path, root)
        if "/fuzz/corpus/" in rel:
            continue
        for kind, inc in INCLUDE.findall(open(path, encoding="utf-8").read()):
            if kind == "<" or inc in GENERATED:
                continue
            hits = [t for t in ("Source", tree) if os.path.isfile(os.path.join(root, t, inc))]
            if inc.startswith(".") or len(hits) != 1:
                problems.append('%s: #include "%s" should name one file from Source/ or %s/ (found in: %s)'
                                % (rel, inc, tree, ", ".join(hits) or "neither"))


def check_test_mirror(root, problems):
    tests = os.path.join(root, "tests")
    source = os.path.join(root, "Source")
    for folder, _, files in os.walk(tests):
        rel = os.path.relpath(folder, tests)
        if rel == "." or rel.split("/")[0] in CROSS_CUTTING_TESTS:
            continue
        if any(f.endswith(("Test.cpp", "_test.py")) for f in files) and not os.path.isdir(os.path.join(source, rel)):
            problems.append("tests/%s: holds tests but Source/%s does not exist (tests mirror Source/)" % (rel, rel))


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--root", default=os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__)))))
    args = parser.parse_args()
    rules = read_rules(os.path.join(args.root, "Resources", "docs", "architecture.md"))
    problems = []
    for folder in rules:
        if not os.path.isdir(os.path.join(args.root, "Source", folder)):
            problems.append("Resources/docs/architecture.md: rule for Source/%s, which does not exist" % folder)
    check_source(args.root, rules, problems)
    check_tree_style(args.root, "tests", problems)
    check_tree_style(args.root, "benchmarks", problems)
    check_test_mirror(args.root, problems)
    for p in problems:
        print(p)
    if problems:
        print("%d violation(s) of the architecture's rules" % len(problems))
        return 1
    print("include rules: %d folders, every include allowed" % len(rules))
    return 0


if __name__ == "__main__":
    sys.exit(main())
