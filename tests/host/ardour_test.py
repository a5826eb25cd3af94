#!/usr/bin/env python3
"""Rosin in a real DAW: Debian's Ardour 7 loads the built LV2 and VST3, plays MIDI files through them and
exports the master bus, and every export must equal `rosin render --midi` of the same file within 1e-6 of
full scale, at two sample rates:

- the demo melody (the default program's musical mapping), its events of one tick in the order Ardour plays
  them (below);
- a phrase of controller lanes, pitch bend and channel pressure;
- the demo phrase on a factory program chosen through the host (a preset of the LV2, a program of the VST3),
  in a session saved and reopened by ardour7-export: the plugin's state through a real host.

And the parameters as Ardour sees them (HostParameters below): what it lists of each, every value of every
choice and switch written as an automation lane and played, each landing on its parameter in the plugin's
saved state and nowhere else, and what the host reads back after a factory program is loaded through it.

Two things Ardour does with a file that `rosin render` does not, both measured here: at one tick it plays
controllers before notes whatever the file's order, and a controller at the session's very start does not
sound as written. So the files given to both are first put in Ardour's order and one beat later
(smf.for_host); the demo melody as written is rendered too, and its difference printed, not asserted.

usage: ardour_test.py ROSIN LV2_BUNDLE VST3_BINARY_DIR LV2_URI DEMO_DIR
Exit status 77 (a skip) when Ardour is not installed: `apt-get install --no-install-recommends ardour`
(.ci/install-deps installs it).
"""
import os
import subprocess
import sys
import tempfile
import unittest

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "support"))
import debian_python  # noqa: E402

debian_python.ensure("numpy", "scipy")

import numpy as np  # noqa: E402

import ardour_session  # noqa: E402
import smf  # noqa: E402 (Resources/scripts/smf.py, on the path ardour_session sets)

TOLERANCE = 1e-6  # of full scale
SKIP = 77
RATES = (44100, 96000)
FORMATS = ("LV2", "VST3")
PROGRAM = "violin-thermal"
TAIL = 2.0  # s after the last event: rosin render's default --tail


def controller_phrase(path):
    """Two notes under moving controllers: expression and force lanes (CC11, CC1), bow position (CC21),
    a bend up and back (finger glide) and channel pressure, at 960 ticks per quarter and 120 bpm."""
    ticks_per_second = 1920
    events = [(0, b"\xff\x51\x03\x07\xa1\x20"), (0, b"\xb0\x01\x40"), (0, b"\xb0\x0b\x3c")]

    def at(seconds, *message):
        events.append((int(round(seconds * ticks_per_second)), bytes(message)))

    at(0.025, 0x90, 50, 84)  # D3
    for i in range(21):
        at(0.05 * i, 0xB0, 11, 60 + 2 * i)  # expression 60 -> 100 over 1 s
    for i in range(11):
        bend = 8192 + int(4095 * np.sin(np.pi * i / 10))
        at(1.0 + 0.05 * i, 0xE0, bend & 0x7F, bend >> 7)  # up about a semitone and back
    at(1.6, 0xB0, 21, 80)  # bow nearer the bridge
    at(1.9, 0x80, 50, 0)
    at(2.0, 0x90, 57, 100)  # A3
    for i in range(15):
        at(2.0 + 0.05 * i, 0xB0, 1, 64 + 2 * i)  # force 64 -> 92
        at(2.025 + 0.05 * i, 0xD0, 40 + 4 * i)  # pressure
    at(3.5, 0x80, 57, 0)
    smf.write(path, 960, smf.for_host(events, 960))


def difference(a, b, rate):
    """The largest difference of two renders over their common length, and where they first part."""
    n = min(len(a), len(b))
    d = np.max(np.abs(a[:n] - b[:n]), axis=1)
    error = float(np.max(d)) if n else 0.0
    if error <= TOLERANCE:
        return error, ""
    first = int(np.argmax(d > TOLERANCE))
    return error, f" (first at {first / rate:.4f} s, the largest at {int(np.argmax(d)) / rate:.4f} s)"


def report_faults_and_clean_up(case):
    """A test class's tearDownClass: how often Ardour failed by itself, then its temporary folder gone."""
    print("Ardour's own failures, each tried again: " + (", ".join(f"{n} {kind}" for kind, n in
                                                             sorted(case.host.faults.items())) or "none"))
    case.temp.cleanup()


class ArdourRendersLikeRosin(unittest.TestCase):
    rosin = lv2 = vst3 = uri = demo = None

    @classmethod
    def setUpClass(cls):
        cls.temp = tempfile.TemporaryDirectory(prefix="rosin-ardour-")
        cls.host = ardour_session.Ardour(os.path.join(cls.temp.name, "home"), cls.lv2, cls.vst3, cls.uri)
        cls.files = {}
        for name in ("melody", "phrase"):
            division, events = smf.read(os.path.join(cls.demo, name + ".mid"))
            cls.files[name] = os.path.join(cls.temp.name, name + "-in-host-order.mid")
            smf.write(cls.files[name], division, smf.for_host(events, division))
        cls.files["controllers"] = os.path.join(cls.temp.name, "controllers.mid")
        controller_phrase(cls.files["controllers"])

    @classmethod
    def tearDownClass(cls):
        report_faults_and_clean_up(cls)

    def seconds(self, midi):
        division, events = smf.read(midi)
        return smf.last_tick(events) / division * 60.0 / smf.tempo_bpm(events) + TAIL

    def render(self, midi, rate, program=""):
        out = os.path.join(self.temp.name, f"rosin-{os.path.basename(midi)}-{rate}-{program}.wav")
        args = [self.rosin, "render", "--midi", midi, "--sample-rate", str(rate), "--out", out]
        subprocess.run(args + (["--preset", program] if program else []), check=True, capture_output=True)
        return ardour_session.read_float_wav(out)

    def through_ardour(self, midi, rate, plugin_format, program=""):
        """A saved session playing `midi` through the plugin, and the file its export is to be written to."""
        stem = os.path.splitext(os.path.basename(midi))[0]
        folder = os.path.join(self.temp.name, f"{stem}-{plugin_format}-{rate}{'-' + program if program else ''}")
        session = self.host.make_session(folder, rate, plugin_format, program)
        session.add_midi(midi, self.seconds(midi))
        return session, folder + ".wav"

    def assert_same(self, midi, program=""):
        for rate in RATES:
            reference_rate, reference = self.render(midi, rate, program)
            self.assertEqual(reference_rate, rate)
            peak = np.max(np.abs(reference))
            self.assertGreater(peak, 1e-3, "rosin render is silent: nothing to compare")
            for plugin_format in FORMATS:
                with self.subTest(format=plugin_format, rate=rate):
                    session, wav = self.through_ardour(midi, rate, plugin_format, program)
                    host_rate, host = self.host.export(session, wav)
                    self.assertEqual(host_rate, rate)
                    self.assertEqual(host.shape[1], 2, "the master bus is stereo")
                    self.assertLessEqual(abs(len(host) - len(reference)), 1, "lengths differ")
                    what = f"{os.path.basename(midi)} {program or 'default program'} {plugin_format} {rate} Hz"
                    error, where = difference(host, reference, rate)
                    print(f"{what}: {min(len(host), len(reference))} samples, peak {peak:.4f}, largest "
                          f"difference {error:.3g}{where}", flush=True)
                    if error > TOLERANCE:
                        error = self.export_again(session, wav, reference, host, what)
                    self.assertLessEqual(error, TOLERANCE)

    def export_again(self, session, wav, reference, first, what):
        """An export that differs from `rosin render` is made once more from the same saved session. Only
        when the second equals the render does the test pass, the first counted among the failures the test
        reports (its cause is not traced; see Resources/docs/tests.md)."""
        rate, again = self.host.export(session, wav)
        error, where = difference(again, reference, rate)
        between, at = difference(again, first, rate)
        print(f"{what}, exported again: largest difference {error:.3g}{where}; from the first export "
              f"{between:.3g}{at}", flush=True)
        if error <= TOLERANCE:
            key = "export differing from another export of its session"
            self.host.faults[key] = self.host.faults.get(key, 0) + 1
        return error

    def test_the_demo_melody(self):
        self.assert_same(self.files["melody"])

    def test_controller_lanes_pitch_bend_and_pressure(self):
        self.assert_same(self.files["controllers"])

    def test_a_program_chosen_through_the_host_survives_its_saved_session(self):
        self.assert_same(self.files["phrase"], PROGRAM)

    def test_the_demo_melody_as_written_differs_only_by_the_hosts_order(self):
        """Printed, not asserted: how far the unsorted melody lands from rosin's render in Ardour."""
        original = os.path.join(self.demo, "melody.mid")
        rate = RATES[0]
        _, reference = self.render(original, rate)
        _, host = self.host.export(*self.through_ardour(original, rate, "LV2"))
        n = min(len(host), len(reference))
        print(f"melody.mid as written, LV2 {rate} Hz: largest difference "
              f"{np.max(np.abs(host[:n] - reference[:n])):.3g} (peak {np.max(np.abs(reference)):.4f})")


class HostParameters(unittest.TestCase):
    """Every choice and switch, each of its values, written by Ardour as an automation lane and played."""

    lv2 = vst3 = uri = None
    RATE = 48000

    @classmethod
    def setUpClass(cls):
        cls.temp = tempfile.TemporaryDirectory(prefix="rosin-ardour-parameters-")
        cls.host = ardour_session.Ardour(os.path.join(cls.temp.name, "home"), cls.lv2, cls.vst3, cls.uri)
        cls.parameters = ardour_session.lv2_parameters(os.path.join(cls.lv2, "dsp.ttl"))
        cls.choices = [p for p in cls.parameters if p.choices >= 2]

    @classmethod
    def tearDownClass(cls):
        report_faults_and_clean_up(cls)

    def key(self, plugin_format, parameter):
        return parameter.label if plugin_format == "VST3" else parameter.id

    def host_value(self, plugin_format, parameter, index):
        """What the host sends for choice `index`: an LV2 property's own value, a VST3's normalised one."""
        return index / (parameter.choices - 1) if plugin_format == "VST3" else float(index)

    def run_host(self, plugin_format):
        plan = [(self.key(plugin_format, p), self.host_value(plugin_format, p, int(p.default)),
                 [self.host_value(plugin_format, p, k) for k in range(p.choices)]) for p in self.choices]
        folder = os.path.join(self.temp.name, "parameters-" + plugin_format)
        lines = self.host.automate(folder, self.RATE, plugin_format, PROGRAM, plan)
        return folder, lines

    def assert_listing(self, plugin_format, controls):
        """What the host lists of each parameter: its title, and a switch as a toggle, a list by its steps."""
        for p in self.parameters:
            key = self.key(plugin_format, p)
            self.assertIn(key, controls, f"{plugin_format}: the host does not list {p.label}")
            label, lower, upper, toggled, integer, steps = controls[key][:6]
            self.assertEqual(label, p.label)
            if plugin_format == "VST3":
                self.assertEqual((float(lower), float(upper)), (0.0, 1.0), p.label)
                self.assertEqual(toggled == "true", p.choices == 2, f"{p.label}: a toggle")
                self.assertEqual(int(steps), p.choices if p.choices > 2 else 0, f"{p.label}: steps")
            else:
                self.assertAlmostEqual(float(lower), p.minimum, delta=1e-6 * (p.maximum - p.minimum), msg=p.label)
                self.assertAlmostEqual(float(upper), p.maximum, delta=1e-6 * (p.maximum - p.minimum), msg=p.label)
                self.assertEqual(toggled == "true" or integer == "true", p.choices >= 2, f"{p.label}: a switch or list")

    def assert_no_latency(self, lines):
        """The host reads no latency of the plugin on its default program: only a measured body response's
        convolution adds any (none of the factory programs has one), and an export that the host shifted by
        a latency would not line up with `rosin render` to the sample."""
        latency = [int(line[1]) for line in lines if line[0] == "latency"]
        self.assertEqual(latency, [0])

    def assert_automation_lands(self, plugin_format, folder, lines):
        """Each snapshot holds the automated value on its parameter and, elsewhere, the first snapshot's
        values but for the parameters automated before, which their lanes left on their defaults."""
        by_key = {self.key(plugin_format, p): p for p in self.choices}
        snapshots = [line[1:] for line in lines if line[0] == "snapshot"]
        expected = ardour_session.saved_plugin_state(os.path.join(folder, snapshots[0][0] + ".ardour"))
        landed, previous = 0, None
        for name, key, value in snapshots[1:]:
            p = by_key[key]
            if previous is not None and previous is not p:
                expected[previous.id] = previous.default
            previous = p
            index = int(round(float(value) * (p.choices - 1) if plugin_format == "VST3" else float(value)))
            state = ardour_session.saved_plugin_state(os.path.join(folder, name + ".ardour"))
            self.assertEqual(state[p.id], index, f"{p.label}: the host sent {value}")
            moved = [k for k in state if k != p.id and abs(state[k] - expected[k]) > 1e-9]
            self.assertEqual(moved, [], f"{p.label} = {value} moved other parameters")
            landed += 1
        self.assertEqual(landed, sum(p.choices for p in self.choices))
        bypass = [line[1:] for line in lines if line[0] == "bypass"]
        self.assertEqual([b[1] for b in bypass], ["1", "0"])
        for name, bypassed in bypass:
            state = ardour_session.saved_plugin_state(os.path.join(folder, name + ".ardour"))
            self.assertEqual(state["bypass"], float(bypassed), "the host's bypass")
        return landed

    def test_lv2(self):
        folder, lines = self.run_host("LV2")
        controls = {line[1]: line[2:] for line in lines if line[0] == "control"}
        self.assert_listing("LV2", controls)
        self.assert_no_latency(lines)
        landed = self.assert_automation_lands("LV2", folder, lines)
        program = next(line for line in lines if line[0] == "program")
        state = ardour_session.saved_plugin_state(os.path.join(folder, program[2] + ".ardour"))
        readback = {line[1]: float(line[2]) for line in lines if line[0] == "readback"}
        unwritten = [p for p in self.parameters if p.choices < 2 and state[p.id] != 0]
        zeros = sum(readback[p.id] == 0 for p in unwritten)
        print(f"LV2: {len(controls)} parameters listed, {landed} automated values landed; after {program[1]} "
              f"the host reads 0 for {zeros} of the {len(unwritten)} parameters it never wrote (Ardour 7.3 "
              "learns no LV2 property's value from a plugin: printed, not asserted)")

    def test_vst3(self):
        folder, lines = self.run_host("VST3")
        controls = {line[1]: line[2:] for line in lines if line[0] == "control"}
        self.assert_listing("VST3", controls)
        self.assert_no_latency(lines)
        self.assertEqual(controls.get("Bypass", [None] * 4)[3], "true", "the VST3 lists its bypass as a toggle")
        landed = self.assert_automation_lands("VST3", folder, lines)
        first = next(line for line in lines if line[0] == "snapshot")
        base = ardour_session.saved_plugin_state(os.path.join(folder, first[1] + ".ardour"))
        program = next(line for line in lines if line[0] == "program")
        self.assertEqual(program[1], PROGRAM)
        state = ardour_session.saved_plugin_state(os.path.join(folder, program[2] + ".ardour"))
        readback = {line[1]: float(line[2]) for line in lines if line[0] == "readback"}
        moved = checked = 0
        for p in self.parameters:
            before, after = float(controls[p.label][6]), readback[p.label]
            if p.choices >= 2:
                self.assertAlmostEqual(before, base[p.id] / (p.choices - 1), delta=1e-6, msg=f"{p.label} read first")
                expected = state[p.id] / (p.choices - 1)
            else:
                expected = self.skewed(p, base[p.id], before, state[p.id])
            if expected is not None:
                self.assertAlmostEqual(after, expected, delta=1e-4, msg=f"{p.label} after {PROGRAM}")
                checked += 1
            self.assertEqual(after != before, state[p.id] != base[p.id], f"{p.label}: moved with the program")
            moved += state[p.id] != base[p.id]
        print(f"VST3: {len(controls)} parameters listed, {landed} automated values landed; after {PROGRAM} the "
              f"host reads every parameter as the plugin has it ({moved} moved, {checked} checked to 1e-4)")

    @staticmethod
    def skewed(p, first_value, first_host, value):
        """A continuous parameter's VST3 value on JUCE's skewed range (normalised = proportion ** skew), the
        skew told by the first pair of the plugin's value and the host's reading; None where that pair
        cannot tell it."""
        first, proportion = ((v - p.minimum) / (p.maximum - p.minimum) for v in (first_value, value))
        if abs(first - first_host) < 1e-7:
            return proportion  # linear
        if not (0 < first < 1 and 0 < first_host < 1):
            return None
        return proportion ** (np.log(first_host) / np.log(first))


if __name__ == "__main__":
    if len(sys.argv) != 6:
        sys.exit(__doc__)
    _, missing = ardour_session.tools()
    if missing:
        print("SKIPPED: Ardour is not installed (" + ", ".join(missing) + "); "
              "apt-get install --no-install-recommends ardour")
        sys.exit(SKIP)
    rosin, lv2, vst3_binary_dir, uri, demo = sys.argv[1:]
    vst3 = os.path.dirname(os.path.dirname(os.path.abspath(vst3_binary_dir)))  # Rosin.vst3/Contents/<arch>
    if not vst3.endswith(".vst3"):
        sys.exit(f"{vst3_binary_dir}: not inside a .vst3 bundle")
    (ArdourRendersLikeRosin.rosin, ArdourRendersLikeRosin.lv2, ArdourRendersLikeRosin.vst3,
     ArdourRendersLikeRosin.uri, ArdourRendersLikeRosin.demo) = rosin, lv2, vst3, uri, demo
    HostParameters.lv2, HostParameters.vst3, HostParameters.uri = lv2, vst3, uri
    result = unittest.main(argv=[sys.argv[0], "-v"], exit=False).result
    sys.exit(0 if result.wasSuccessful() else 1)
