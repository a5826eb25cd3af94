#!/usr/bin/env python3
"""rosin's generated manual: the man page sets without a groff warning and names every option that each
command's --help lists; the bash completion offers the commands, options and choices rosin accepts; and
--parse-only accepts what a parser accepts and refuses the rest.

Usage: manual_test.py ROSIN SOURCE_DIR
"""
import os
import re
import shutil
import subprocess
import sys
import unittest

ROSIN, SOURCE = sys.argv[1], sys.argv[2]
COMMANDS = ["render", "scan", "synth-data", "discover"]


def rosin(*args):
    return subprocess.run([ROSIN, *args], capture_output=True, text=True)


def complete(*words):
    """What the generated completion offers for the command line `words` (the last one being typed)."""
    script = rosin("--completion", "bash").stdout
    line = " ".join("'%s'" % w for w in words)
    program = script + "\nCOMP_WORDS=(%s); COMP_CWORD=%d; _rosin; printf '%%s\\n' \"${COMPREPLY[@]}\"\n" % (
        line, len(words) - 1)
    done = subprocess.run(["bash", "-c", program], capture_output=True, text=True, cwd=SOURCE)
    return [w for w in done.stdout.splitlines() if w]


class ManPage(unittest.TestCase):
    def setUp(self):
        self.page = rosin("--man")
        self.assertEqual(self.page.returncode, 0)

    @unittest.skipUnless(shutil.which("groff"), "groff is not installed")
    def test_sets_without_warnings(self):
        done = subprocess.run(["groff", "-man", "-ww", "-z", "-Tutf8"], input=self.page.stdout,
                              capture_output=True, text=True)
        self.assertEqual(done.returncode, 0)
        self.assertEqual(done.stderr, "")

    def test_names_every_option_of_every_help(self):
        text = self.page.stdout.replace("\\-", "-")
        for command in COMMANDS:
            help_text = rosin(command, "--help").stdout
            options = set(re.findall(r"^  (?:-h, )?(--[a-z][a-z0-9-]*)", help_text, re.M))
            self.assertGreater(len(options), 3, command)
            for option in options:
                self.assertRegex(text, r"\\fB(-h, )?" + re.escape(option) + r"\\fR",
                                 "rosin %s: %s" % (command, option))

    def test_holds_no_path_of_the_build_machine(self):
        self.assertNotIn(os.path.abspath(SOURCE), self.page.stdout)


class Completion(unittest.TestCase):
    def test_commands(self):
        self.assertEqual(complete("rosin", "sc"), ["scan"])
        self.assertEqual(complete("rosin", "synth"), ["synth-data"])

    def test_options_of_the_command_being_typed(self):
        self.assertIn("--friction", complete("rosin", "render", "--fr"))
        self.assertIn("--midi", complete("rosin", "render", "--mi"))
        self.assertEqual(complete("rosin", "scan", "guettler", "--no-t"), ["--no-torsion"])

    def test_values_from_the_commands_own_lists(self):
        self.assertEqual(complete("rosin", "render", "--friction", "mod"), ["modified-bow", "modified-rod"])
        self.assertEqual(complete("rosin", "scan", "guettler", "--contact", ""), ["coulomb", "hertz"])
        self.assertIn("junction-growth", complete("rosin", "synth-data", "--effect", "jun"))
        self.assertIn("cello-plastic", complete("rosin", "render", "--preset", "cello-p"))

    def test_subcommands(self):
        self.assertEqual(complete("rosin", "scan", "g"), ["guettler"])


class ParseOnly(unittest.TestCase):
    def test_accepts_what_the_parser_accepts(self):
        for args in (["render", "--midi", "x.mid", "--out", "y.wav"],
                     ["scan", "guettler", "--grid", "300", "--contact", "hertz", "--out", "big"],
                     ["scan", "compare", "A", "B", "--out", "D"],
                     ["discover", "data", "--json", "j.json", "--report", "r"]):
            done = rosin("--parse-only", *args)
            self.assertEqual(done.returncode, 0, " ".join(args) + ": " + done.stderr)

    def test_refuses_an_unknown_option_a_bad_value_and_a_missing_argument(self):
        for args, message in ((["render", "--no-such", "1"], "--no-such"),
                              (["scan", "guettler", "--grid", "301", "--out", "x"], "--grid"),
                              (["discover", "data"], "--json")):
            done = rosin("--parse-only", *args)
            self.assertEqual(done.returncode, 2, " ".join(args))
            self.assertIn(message, done.stderr)


if __name__ == "__main__":
    unittest.main(argv=sys.argv[:1])
