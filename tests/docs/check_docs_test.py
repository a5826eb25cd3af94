#!/usr/bin/env python3
"""The docs check fails where it should, on a small tree of its own: a broken link, a missing anchor, a
missing image and a rosin command its parser refuses each fail it and are named; the same tree without them
passes.  Usage: check_docs_test.py ROSIN
"""
import os
import subprocess
import sys
import tempfile
import unittest

CHECK = os.path.join(os.path.dirname(os.path.abspath(__file__)), "check_docs.py")
ROSIN = sys.argv[1]
README = """# Example

See [the page](Resources/docs/page.md#a-section) and ![a figure](Resources/figures/f.png).

```sh
rosin scan guettler --grid 12 --out gu && rosin scan merge gu
```
"""
PAGE = """# Page

## A section

Back to [the README](../../README.md) and [here](#page).

```text
rosin this is a synopsis [--not checked]
```
"""


def tree(readme=README, page=PAGE):
    root = tempfile.mkdtemp()
    os.makedirs(os.path.join(root, "Resources", "docs"))
    os.makedirs(os.path.join(root, "Resources", "figures"))
    open(os.path.join(root, "Resources", "figures", "f.png"), "w").close()
    with open(os.path.join(root, "README.md"), "w") as f:
        f.write(readme)
    with open(os.path.join(root, "Resources", "docs", "page.md"), "w") as f:
        f.write(page)
    return root


def check(root):
    done = subprocess.run([sys.executable, CHECK, "--root", root, "--rosin", ROSIN], capture_output=True, text=True)
    return done.returncode, done.stdout


class DocsCheck(unittest.TestCase):
    def test_a_tree_that_holds_passes(self):
        self.assertEqual(check(tree())[0], 0, check(tree())[1])

    def test_a_broken_link_fails_and_is_named(self):
        code, out = check(tree(readme=README.replace("page.md#", "pgae.md#")))
        self.assertEqual(code, 1)
        self.assertIn("pgae.md#a-section: no such file", out)

    def test_a_missing_anchor_fails(self):
        code, out = check(tree(page=PAGE.replace("## A section", "## Another section")))
        self.assertEqual(code, 1)
        self.assertIn('no heading or <a id> "a-section"', out)

    def test_a_missing_image_fails(self):
        code, out = check(tree(readme=README.replace("f.png", "g.png")))
        self.assertEqual(code, 1)
        self.assertIn("g.png: no such file", out)

    def test_a_command_the_parser_refuses_fails(self):
        code, out = check(tree(readme=README.replace("--grid 12", "--grid 301")))
        self.assertEqual(code, 1)
        self.assertIn("`rosin scan guettler --grid 301 --out gu` is refused", out)


if __name__ == "__main__":
    unittest.main(argv=sys.argv[:1])
