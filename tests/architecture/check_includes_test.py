#!/usr/bin/env python3
"""The include check fails where it should: on a small tree of its own with one violation of each kind."""
import os
import subprocess
import sys
import tempfile
import unittest

CHECK = os.path.join(os.path.dirname(os.path.abspath(__file__)), "check_includes.py")
RULES = """# Architecture
<!-- include-rules -->
| folder | may include |
| --- | --- |
| `core/physics` | Eigen |
| `core/config` | `core/physics` |
| `instrument/engine` | `core`, JUCE |
<!-- /include-rules -->
"""


def write(root, path, text=""):
    full = os.path.join(root, path)
    os.makedirs(os.path.dirname(full), exist_ok=True)
    with open(full, "w") as f:
        f.write(text)


def run(root):
    done = subprocess.run([sys.executable, CHECK, "--root", root], capture_output=True, text=True)
    return done.returncode, done.stdout


class IncludeRules(unittest.TestCase):
    def tree(self, extra):
        root = tempfile.mkdtemp()
        write(root, "Resources/docs/architecture.md", RULES)
        write(root, "Source/core/physics/Mode.h", "#include <Eigen/Dense>\n")
        write(root, "Source/core/config/Preset.h", '#include "core/physics/Mode.h"\n')
        write(root, "Source/instrument/engine/Engine.h",
              '#include <juce_core/juce_core.h>\n#include "core/config/Preset.h"\n')
        write(root, "tests/core/physics/ModeTest.cpp", '#include "core/physics/Mode.h"\n')
        for path, text in extra.items():
            write(root, path, text)
        return root

    def test_a_tree_that_keeps_the_rules_passes(self):
        self.assertEqual(run(self.tree({}))[0], 0)

    def test_an_include_against_the_rules_fails_and_is_named(self):
        code, out = run(self.tree({"Source/core/physics/Bad.h": '#include "instrument/engine/Engine.h"\n'}))
        self.assertEqual(code, 1)
        self.assertIn("core/physics may not include instrument/engine", out)

    def test_juce_in_the_core_fails(self):
        code, out = run(self.tree({"Source/core/config/Bad.h": "#include <juce_core/juce_core.h>\n"}))
        self.assertEqual(code, 1)
        self.assertIn("core/config may not include JUCE", out)

    def test_a_relative_or_bare_include_fails(self):
        code, out = run(self.tree({"Source/core/config/Other.h": '#include "Preset.h"\n#include "../physics/Mode.h"\n'}))
        self.assertEqual(code, 1)
        self.assertEqual(out.count("spell includes from Source/"), 2)

    def test_a_test_folder_that_mirrors_no_source_folder_fails(self):
        code, out = run(self.tree({"tests/physics/ModeTest.cpp": '#include "core/physics/Mode.h"\n'}))
        self.assertEqual(code, 1)
        self.assertIn("tests mirror Source/", out)


if __name__ == "__main__":
    unittest.main()
