"""Ardour 7 as a real host, headless: a session with Rosin on a MIDI track (make_session.lua through
ardour7-lua on the Dummy backend), a MIDI file as its region, and the master bus exported by ardour7-export.

Everything Ardour writes (its configuration, the VST3 scan cache) goes under a private HOME, so the test
leaves no trace and never sees a user's settings.
"""
import base64
import glob
import os
import re
import struct
import shutil
import subprocess
import sys
import warnings
import xml.etree.ElementTree as ET
from collections import namedtuple

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "Resources", "scripts"))
import smf  # noqa: E402 (Resources/scripts/smf.py)


HERE = os.path.dirname(os.path.abspath(__file__))
ARDOUR_LIB = "/usr/lib/ardour7"
SUPERCLOCKS_PER_SECOND = 282240000  # Ardour 7's superclock rate (the session's TempoMap says so too)
ARDOUR_TICKS_PER_BEAT = 1920
EXPORT_TIMEOUT = 40  # s; an export of these files takes 3-10 s, also on a loaded machine
SESSION_TIMEOUT = 60  # s; making a session takes 2-5 s
ATTEMPTS = 5  # Ardour's own failures came in up to one run of four on a loaded machine


class HostFault(Exception):
    """A failure of Ardour's own (see Ardour._retried), as opposed to one of the plugin or the test."""

    def __init__(self, kind, message):
        super().__init__(message)
        self.kind = kind


def tools():
    """The Ardour commands the test needs, or the reason they are missing."""
    needed = {"lua": "ardour7-lua", "export": "ardour7-export"}
    found = {key: shutil.which(name) for key, name in needed.items()}
    found["vst3-scanner"] = os.path.join(ARDOUR_LIB, "ardour-vst3-scanner")
    missing = [needed.get(k, v) for k, v in found.items() if not v or not os.path.exists(v)]
    return found, missing


class Ardour:
    def __init__(self, home, lv2_bundle, vst3_bundle, lv2_uri):
        self.tools, missing = tools()
        if missing:
            raise RuntimeError("Ardour is not installed: " + ", ".join(missing))
        self.home, self.lv2_uri = home, lv2_uri
        self.faults = {}
        os.makedirs(os.path.join(home, ".vst3"), exist_ok=True)
        self.env = dict(os.environ, HOME=home, XDG_CONFIG_HOME=os.path.join(home, ".config"),
                        XDG_CACHE_HOME=os.path.join(home, ".cache"), XDG_DATA_HOME=os.path.join(home, ".local"),
                        LV2_PATH=os.path.dirname(os.path.abspath(lv2_bundle)), ROSIN_HOST_SCRIPTS=HERE)
        link = os.path.join(home, ".vst3", os.path.basename(vst3_bundle))
        if not os.path.exists(link):
            os.symlink(os.path.abspath(vst3_bundle), link)
        self.vst3_id = self._scan_vst3(link)

    def _run(self, args, what, extra_env=None, timeout=180):
        """Runs one of Ardour's tools; a crash (a signal) or a hang is Ardour's fault (HostFault), any other
        failure a real error."""
        try:
            done = subprocess.run(args, env=dict(self.env, **(extra_env or {})), capture_output=True, text=True,
                                  timeout=timeout)
        except subprocess.TimeoutExpired as hung:
            raise HostFault("hang", f"{what} took over {timeout} s") from hung
        if done.returncode < 0:
            raise HostFault("crash", f"{what} died of signal {-done.returncode}: {done.stderr[-500:]}")
        if done.returncode != 0:
            raise RuntimeError(f"{what} failed ({done.returncode}):\n{done.stdout[-3000:]}\n{done.stderr[-3000:]}")
        return done.stdout

    def _retried(self, step, what, attempt):
        """`attempt()` until it succeeds, at most ATTEMPTS times while Ardour is at fault. Ardour 7.3's headless
        tools fail now and then by themselves (measured with its own synthesizer as with Rosin: the counts
        are in Resources/docs/tests.md, "In a real DAW"): an export whose butler never starts (a hang), a heap
        corruption found as the export tears its channels down (SIGABRT), a session whose track ports it
        registers twice (an abort in ardour7-lua). They are counted in `self.faults` by step and kind, and
        the test reports them."""
        for n in range(ATTEMPTS):
            try:
                return attempt()
            except HostFault as fault:
                key = f"{step} {fault.kind}"
                self.faults[key] = self.faults.get(key, 0) + 1
                if n + 1 == ATTEMPTS:
                    raise RuntimeError(f"{what}: Ardour failed {ATTEMPTS} times, last: {fault}") from fault

    def _scan_vst3(self, bundle):
        """Ardour lists a VST3 only after its scanner has indexed it; the index names the class id."""
        env = {"LD_LIBRARY_PATH": ARDOUR_LIB}
        self._run([self.tools["vst3-scanner"], "-f", bundle], "ardour-vst3-scanner", env)
        caches = glob.glob(os.path.join(self.env["XDG_CACHE_HOME"], "ardour7", "vst", "*.v3i"))
        for cache in caches:
            for info in ET.parse(cache).getroot().iter("VST3Info"):
                if info.get("name") == "Rosin":
                    return info.get("uid")
        raise RuntimeError("ardour-vst3-scanner indexed no Rosin in " + ", ".join(caches))

    def make_session(self, folder, rate, plugin_format, program=""):
        """A saved session in `folder` with Rosin (`plugin_format` LV2 or VST3) on a MIDI track. The folder's
        name is the session's (Ardour finds its sources under interchange/<folder name>) and holds letters,
        digits and dashes only."""
        name = os.path.basename(folder)
        if not name.replace("-", "").isalnum():
            raise ValueError(f"session folder {name!r}: letters, digits and dashes only")
        env = {"ROSIN_SESSION_DIR": folder, "ROSIN_SESSION_NAME": name, "ROSIN_SAMPLE_RATE": str(rate),
               "ROSIN_FORMAT": plugin_format, "ROSIN_PROGRAM": program,
               "ROSIN_PLUGIN_ID": self.vst3_id if plugin_format == "VST3" else self.lv2_uri}

        def attempt():
            shutil.rmtree(folder, ignore_errors=True)
            return self._run([self.tools["lua"], os.path.join(HERE, "make_session.lua")], "ardour7-lua", env,
                             timeout=SESSION_TIMEOUT)

        out = self._retried("session", "making the session " + name, attempt)
        if "instrument: Rosin" not in out or (program and f"program: {program}" not in out):
            raise RuntimeError(f"make_session.lua did not report Rosin {program} on the track:\n" + out)
        return Session(folder, name)

    def automate(self, folder, rate, plugin_format, program, plan):
        """Runs automate_parameters.lua: `plan` is [(key, default, [values])] in the host's values. Returns
        the lines it printed, each split at "|"."""
        name = os.path.basename(folder)
        env = {"ROSIN_SESSION_DIR": folder, "ROSIN_SESSION_NAME": name, "ROSIN_SAMPLE_RATE": str(rate),
               "ROSIN_FORMAT": plugin_format, "ROSIN_PROGRAM": program,
               "ROSIN_PLUGIN_ID": self.vst3_id if plugin_format == "VST3" else self.lv2_uri,
               "ROSIN_AUTOMATE": ";".join(f"{key}={default!r}:" + ",".join(repr(v) for v in values)
                                          for key, default, values in plan)}

        def attempt():
            shutil.rmtree(folder, ignore_errors=True)
            return self._run([self.tools["lua"], os.path.join(HERE, "automate_parameters.lua")], "ardour7-lua",
                             env, timeout=SESSION_TIMEOUT + 5 * sum(len(v) + 1 for _, _, v in plan))

        out = self._retried("automation", "automating the parameters in " + name, attempt)
        return [line.split("|") for line in out.splitlines() if "|" in line]

    def export(self, session, wav):
        """The master bus over the session range, 32-bit float, at the session's rate: (rate, samples x
        channels)."""
        args = [self.tools["export"], "-b", "float", "-o", wav, session.folder, session.name]
        # Every attempt exports the session as it was made: an export that hung or crashed can leave its
        # crash-recovery state (<name>.pending) behind, with the plugin's state as it was when it stopped (a
        # VST3's controller-mapped parameters at their last values), which the next attempt would load.
        pristine = session.folder + ".pristine"
        shutil.rmtree(pristine, ignore_errors=True)
        shutil.copytree(session.folder, pristine, symlinks=True)

        def attempt():
            if os.path.exists(wav):
                os.remove(wav)
            shutil.rmtree(session.folder)
            shutil.copytree(pristine, session.folder, symlinks=True)
            self._run(args, "ardour7-export", timeout=EXPORT_TIMEOUT)
            if not os.path.exists(wav):
                raise RuntimeError("ardour7-export wrote no " + wav)
            rate, samples = read_float_wav(wav)
            if not np.any(samples):
                raise RuntimeError(f"the export of {session.name} is silent")
            return rate, samples

        return self._retried("export", "exporting " + session.name, attempt)


def read_float_wav(path):
    """(rate, samples x channels) of a 32-bit float WAV."""
    import scipy.io.wavfile
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # chunks scipy does not know
        rate, x = scipy.io.wavfile.read(path)
    if x.dtype != np.float32:
        raise ValueError(f"{path}: {x.dtype} samples, expected 32-bit float")
    return rate, x.reshape(len(x), -1).astype(np.float64)


class Session:
    """A saved session's file, edited the way Ardour itself writes a MIDI region of a file."""

    def __init__(self, folder, name):
        self.folder, self.name = folder, name
        self.path = os.path.join(folder, name + ".ardour")

    def add_midi(self, midi_path, seconds):
        """The MIDI file as a region at the session's start, `seconds` long, the session's tempo set to the
        file's (Ardour places a file's ticks by the session's tempo map), and the session range over it."""
        division, events = smf.read(midi_path)
        bpm = smf.tempo_bpm(events)
        tree = ET.parse(self.path)
        root = tree.getroot()
        next_id = int(root.get("id-counter"))
        source_id, region_id, whole_id, range_id = (str(next_id + k) for k in range(1, 5))
        root.set("id-counter", str(next_id + 5))

        base = os.path.basename(midi_path)
        folder = os.path.join(self.folder, "interchange", self.name, "midifiles")
        os.makedirs(folder, exist_ok=True)
        shutil.copy(midi_path, os.path.join(folder, base))

        source = ET.SubElement(root.find("Sources"), "Source",
                               {"name": base, "type": "midi", "flags": "", "id": source_id, "take-id": "",
                                "origin": ""})
        # Controllers, bend and pressure as the file has them: stepped. Ardour interpolates a lane unless it
        # is marked discrete, which would send values the file does not hold.
        for channel in range(16):
            params = [f"midicc-{channel}-{n}" for n in range(128)]
            params += [f"midi-pitch-bender-{channel}", f"midi-channel-pressure-{channel}"]
            for param in params:
                ET.SubElement(source, "InterpolationStyle", {"parameter": param, "style": "Discrete"})

        ticks = int(round(seconds * bpm / 60.0 * ARDOUR_TICKS_PER_BEAT))
        region = {"name": os.path.splitext(base)[0], "muted": "0", "opaque": "1", "locked": "0",
                  "video-locked": "0", "automatic": "0", "import": "0", "external": "0", "hidden": "0",
                  "position-locked": "0", "start": "b0", "length": f"b{ticks}@b0", "position": "b0",
                  "sync-position": "b0", "ancestral-start": "b0", "ancestral-length": f"b{ticks}@b0",
                  "stretch": "1", "shift": "1", "layering-index": "0", "type": "midi", "first-edit": "nothing",
                  "source-0": source_id, "master-source-0": source_id}
        ET.SubElement(root.find("Regions"), "Region", dict(region, **{"whole-file": "1", "id": whole_id}))
        playlist = next(p for p in root.find("Playlists") if p.get("type") == "midi")
        ET.SubElement(playlist, "Region", dict(region, **{"whole-file": "0", "id": region_id}))

        end = int(round(seconds * SUPERCLOCKS_PER_SECOND))
        ET.SubElement(root.find("Locations"), "Location",
                      {"id": range_id, "name": "session", "start": "a0", "end": f"a{end}",
                       "flags": "IsSessionRange", "locked": "0", "timestamp": "0", "cue": "0"})
        for tempo in root.iter("Tempo"):
            tempo.set("npm", repr(bpm))
            tempo.set("enpm", repr(bpm))
        tree.write(self.path, xml_declaration=True, encoding="UTF-8")


JUCE_BASE64 = ".ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+"
JUCE_XML_MAGIC = b"VC2!"  # AudioProcessor::copyXmlToBinary's header, then the XML's byte count


def juce_base64(text):
    """The bytes of JUCE's MemoryBlock::toBase64Encoding ("<byte count>.<6 bits a character, least
    significant first>"), the form JUCE's LV2 wrapper saves a state in."""
    count, _, body = text.partition(".")
    bits = 0
    for i, c in enumerate(body):
        bits |= JUCE_BASE64.index(c) << (6 * i)
    return bits.to_bytes((6 * len(body) + 7) // 8, "little")[:int(count)]


def state_parameters(blob):
    """{parameter id: value} of the plugin's saved state, found inside what a wrapper wrote around it."""
    at = blob.find(JUCE_XML_MAGIC)
    if at < 0:
        raise ValueError("no JUCE state (VC2!) in the plugin's saved data")
    size = struct.unpack("<I", blob[at + 4:at + 8])[0]
    root = ET.fromstring(blob[at + 8:at + 8 + size].rstrip(b"\0"))
    return {p.get("id"): float(p.get("value")) for p in root.iter("PARAM")}


def saved_plugin_state(snapshot):
    """The plugin's own parameter values in a saved session file: an LV2's state directory, a VST3's
    chunk."""
    root = ET.parse(snapshot).getroot()
    for processor in root.iter("Processor"):
        if processor.get("name") != "Rosin" or processor.get("type") not in ("lv2", "vst3"):
            continue
        if processor.get("type") == "vst3":
            return state_parameters(base64.b64decode(processor.find("vst3/chunk").text))
        state_dir = processor.find("lv2").get("state-dir")
        ttl = os.path.join(os.path.dirname(snapshot), "plugins", processor.get("id"), state_dir, "state.ttl")
        with open(ttl) as f:
            text = re.search(r':StateString> "([^"]+)"', f.read()).group(1)
        return state_parameters(juce_base64(text))
    raise ValueError(snapshot + ": no Rosin plugin")


Parameter = namedtuple("Parameter", "id label default minimum maximum choices")  # choices: 0 if continuous


def lv2_parameters(dsp_ttl):
    """[Parameter] of the LV2 metadata, in order."""
    with open(dsp_ttl) as f:
        text = f.read()
    found = []
    for m in re.finditer(r"(?ms)^plug:(\S+)\n\ta lv2:Parameter ;(.*?)\.\n", text):
        block = m.group(2)

        def number(key):
            return float(re.search(r"lv2:%s ([0-9.eE+-]+)" % key, block).group(1))

        label = re.search(r'rdfs:label "([^"]*)"', block).group(1)
        choices = len(re.findall(r"rdf:value", block))
        found.append(Parameter(m.group(1), label, number("default"), number("minimum"), number("maximum"), choices))
    return found
