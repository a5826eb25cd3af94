#!/usr/bin/env python3
"""Rosin installed as a Linux audio plugin, checked from the installed tree only.

Default mode (CTest `install.destdir`): `cmake --install` into a DESTDIR under /usr, then
  - the layout hosts and desktops expect (VST3, LV2, the Standalone, rosin, data, desktop entry, icons);
  - a host scan of the staged plugin folders finds Rosin as VST3 and LV2, loads it and plays it
    (test_pluginhost's Installed/* tests), and the harness's own checks pass on the staged bundles;
  - the installed `rosin`, run from another folder, finds its presets and figure scripts beside itself:
    it renders the demo phrase and a preset by name, and a small scan draws its figures with the installed
    scripts (a marker written by the installed copy proves which script ran);
  - `cpack` makes a .deb whose file list is exactly the staged tree and whose Depends name the package of
    every library the binaries link (found with dpkg -S), plus Python's matplotlib and the X11 libraries JUCE
    opens at run time.
`--system` (root only; CI): installs that .deb with apt, checks a host's default scan finds Rosin, renders
from /tmp, removes the package and checks that nothing it installed is left behind.
"""
import argparse
import os
import shutil
import subprocess
import sys
import tempfile

EXPECTED = [
    "usr/bin/rosin",
    "usr/bin/rosin-standalone",
    "usr/lib/vst3/Rosin.vst3/Contents/x86_64-linux/Rosin.so",
    "usr/lib/lv2/Rosin.lv2/manifest.ttl",
    "usr/lib/lv2/Rosin.lv2/libRosin.so",
    "usr/share/applications/rosin.desktop",
    "usr/share/icons/hicolor/256x256/apps/rosin.png",
    "usr/share/icons/hicolor/scalable/apps/rosin.svg",
    "usr/share/rosin/presets/cello-plastic.json",
    "usr/share/rosin/figures/plot_scan.py",
    "usr/share/rosin/figures/plot_discovery.py",
    "usr/share/rosin/demo/phrase.mid",
    "usr/share/doc/rosin/README.md",
    "usr/share/man/man1/rosin.1.gz",
    "usr/share/bash-completion/completions/rosin",
]
# Loaded with dlopen (JUCE's X11 layer) or run (the figure scripts): invisible to dpkg-shlibdeps.
RUNTIME_DEPENDS = ["libx11-6", "libxext6", "libxcursor1", "libxinerama1", "libxrandr2", "libxrender1",
                   "python3", "python3-matplotlib", "python3-numpy"]
LINKED_BINARIES = ["usr/bin/rosin", "usr/bin/rosin-standalone",
                   "usr/lib/vst3/Rosin.vst3/Contents/x86_64-linux/Rosin.so",
                   "usr/lib/lv2/Rosin.lv2/libRosin.so"]
# Folders a removal must leave as they were (the package owns files only under /usr).
WATCHED = ["/usr/bin", "/usr/lib/vst3", "/usr/lib/lv2", "/usr/share/rosin", "/usr/share/doc/rosin",
           "/usr/share/applications", "/usr/share/icons/hicolor", "/usr/share/man/man1",
           "/usr/share/bash-completion", "/etc", "/opt"]

failures = []


def check(condition, message):
    print(("ok    " if condition else "FAIL  ") + message, flush=True)
    if not condition:
        failures.append(message)
    return condition


def run(cmd, cwd=None, env=None, timeout=600):
    print("$ " + " ".join(cmd), flush=True)
    return subprocess.run(cmd, cwd=cwd, env=env, timeout=timeout, text=True, stdout=subprocess.PIPE,
                          stderr=subprocess.STDOUT)


def clean_env(**extra):
    """The user's environment without anything that would point rosin at the source tree."""
    env = {k: v for k, v in os.environ.items() if not k.startswith("ROSIN_")}
    env.update(extra)
    return env


def stage_install(build, destdir):
    result = run(["cmake", "--install", build, "--prefix", "/usr"], env=clean_env(DESTDIR=destdir))
    check(result.returncode == 0, "cmake --install into DESTDIR " + destdir)
    for path in EXPECTED:
        check(os.path.isfile(os.path.join(destdir, path)), "installed " + path)
    check(os.access(os.path.join(destdir, "usr/bin/rosin-standalone"), os.X_OK), "rosin-standalone executable")
    desktop = os.path.join(destdir, "usr/share/applications/rosin.desktop")
    result = run(["desktop-file-validate", desktop])
    check(result.returncode == 0 and result.stdout.strip() == "", "desktop-file-validate: " + result.stdout)


def host_checks(pluginhost, scan_path, bundles=None, label="staged"):
    env = clean_env(ROSIN_PLUGINHOST_SCAN_PATH=scan_path) if scan_path else clean_env()
    result = run([pluginhost, "--gtest_filter=Installed/*"], env=env)
    print(result.stdout[-3000:])
    check(result.returncode == 0, "host scan of the " + label + " plugin folders finds, loads and plays Rosin")
    if bundles:
        env = clean_env(ROSIN_PLUGINHOST_VST3=bundles[0], ROSIN_PLUGINHOST_LV2=bundles[1])
        result = run([pluginhost, "--gtest_filter=Formats/PluginHost.ScansAsAMidiInstrumentWithAnOutput/*:"
                      "Formats/PluginHost.ProgramsHaveNamesAndPlay/*:Formats/PluginHost.StateRestoresIntoANewInstance/*"],
                     env=env)
        print(result.stdout[-2000:])
        check(result.returncode == 0, "the host harness's checks pass on the " + label + " bundles")


def is_wav(path):
    with open(path, "rb") as f:
        head = f.read(12)
    return len(head) == 12 and head[:4] == b"RIFF" and head[8:] == b"WAVE" and os.path.getsize(path) > 1000


def rosin_checks(prefix, workdir, mark_figure_script):
    rosin = os.path.join(prefix, "bin/rosin")
    share = os.path.join(prefix, "share/rosin")
    # A name it does not know: the message names the file it looked for, in the installed presets.
    refused = run([rosin, "render", "--preset", "no-such-preset", "--out", os.path.join(workdir, "never.wav")],
                  cwd=workdir, env=clean_env()).stdout
    check(os.path.join(share, "presets", "no-such-preset.json") in refused,
          "installed rosin looks up presets in " + share + "/presets")
    demo = run([rosin, "render", "--midi", os.path.join(share, "demo/phrase.mid"), "--out", "demo.wav"],
               cwd=workdir, env=clean_env())
    check(demo.returncode == 0 and is_wav(os.path.join(workdir, "demo.wav")), "renders the demo phrase: " +
          demo.stdout.strip().splitlines()[0] if demo.stdout.strip() else "renders the demo phrase")
    named = run([rosin, "render", "--preset", "cello-plastic", "--gesture",
                 "steady:speed=0.1,force=1,beta=0.1,seconds=0.3", "--out", "preset.wav"], cwd=workdir, env=clean_env())
    check(named.returncode == 0 and is_wav(os.path.join(workdir, "preset.wav")),
          "renders an installed preset by name: " + named.stdout.strip()[-200:])
    marker = os.path.join(workdir, "figure-script-ran")
    if mark_figure_script:  # a line after the shebang: the script ends in sys.exit
        script = os.path.join(share, "figures/plot_scan.py")
        lines = open(script).read().split("\n")
        lines.insert(1, "open(%r, 'w').write(__file__)" % marker)
        open(script, "w").write("\n".join(lines))
    scan = run([rosin, "scan", "schelleng", "--grid", "3x3", "--duration", "0.2", "--out", "scan", "--no-progress"],
               cwd=workdir, env=clean_env())
    figures = [f for f in os.listdir(os.path.join(workdir, "scan")) if f.endswith(".png")] if scan.returncode == 0 else []
    check(scan.returncode == 0 and "schelleng.png" in figures, "a 3 x 3 scan draws its figures: " + ", ".join(figures))
    if mark_figure_script:
        ran = open(marker).read() if os.path.exists(marker) else "none"
        check(ran == os.path.join(share, "figures/plot_scan.py"), "the installed figure script ran (" + ran + ")")


def package(build, workdir, destdir):
    out = os.path.join(workdir, "package")
    result = run(["cpack", "--config", os.path.join(build, "CPackConfig.cmake"), "-B", out])
    debs = [os.path.join(out, f) for f in os.listdir(out) if f.endswith(".deb")] if os.path.isdir(out) else []
    if not check(result.returncode == 0 and len(debs) == 1, "cpack makes one .deb: " + result.stdout[-500:]):
        return None
    deb = debs[0]
    listing = run(["dpkg-deb", "-c", deb]).stdout.splitlines()
    packaged = sorted(line.split()[-1].lstrip("./") for line in listing if not line.startswith("d"))
    staged = sorted(os.path.relpath(os.path.join(root, f), destdir)
                    for root, _, files in os.walk(destdir) for f in files)
    check(packaged == staged, ".deb holds exactly the staged files (%d): extra %s, missing %s" % (
        len(packaged), sorted(set(packaged) - set(staged))[:5], sorted(set(staged) - set(packaged))[:5]))
    check(all(p.startswith("usr/") for p in packaged), ".deb installs under /usr only")
    depends = run(["dpkg-deb", "-f", deb, "Depends"]).stdout
    names = {d.strip().split(" ")[0] for alt in depends.split(",") for d in alt.split("|")}
    print("Depends: " + depends.strip())
    for package_name in RUNTIME_DEPENDS:
        check(package_name in names, "Depends names " + package_name)
    for package_name in linked_packages(destdir):
        check(package_name in names, "Depends names " + package_name + " (a library the binaries link)")
    return deb


def linked_packages(destdir):
    """The Debian packages of every library the installed binaries link (readelf NEEDED -> ldconfig -> dpkg -S)."""
    cache = run(["ldconfig", "-p"]).stdout
    sonames = set()
    for binary in LINKED_BINARIES:
        dynamic = run(["readelf", "-d", os.path.join(destdir, binary)]).stdout
        sonames.update(line.split("[")[1].split("]")[0] for line in dynamic.splitlines() if "(NEEDED)" in line)
    packages = set()
    for soname in sorted(sonames):
        paths = [l.split("=>")[1].strip() for l in cache.splitlines()
                 if l.strip().startswith(soname + " ") and "x86-64" in l]
        owner = package_owning(os.path.realpath(paths[0])) if paths else None
        if check(owner is not None, soname + " belongs to a package (%s)" % owner):
            packages.add(owner)
    return sorted(packages)


def package_owning(path):
    """dpkg -S, also under the /lib alias a merged /usr gives the path (packages own /lib/... there)."""
    for candidate in (path, path[len("/usr"):] if path.startswith("/usr/lib/") else None):
        if candidate:
            result = subprocess.run(["dpkg", "-S", candidate], text=True, capture_output=True)
            if result.returncode == 0:
                return result.stdout.split(":")[0]
    return None


def snapshot():
    files = set()
    for top in WATCHED:
        for root, _, names in os.walk(top):
            files.update(os.path.join(root, n) for n in names)
    return files


def manual_checks():
    """`man rosin` finds the installed page and sets it without warnings; the completion offers commands."""
    if shutil.which("man"):
        where = run(["man", "-w", "rosin"])
        check(where.stdout.strip() == "/usr/share/man/man1/rosin.1.gz", "man -w rosin: " + where.stdout.strip())
        page = run(["man", "--warnings", "rosin"], env=clean_env(MANPAGER="cat", MANWIDTH="100", LANG="C.UTF-8"))
        check(page.returncode == 0 and "rosin render" in page.stdout and "--parse-only" in page.stdout
              and "warning" not in page.stdout, "man rosin shows the commands without warnings")
    else:
        check(False, "man is installed (man-db, .ci/install-deps)")
    script = "source /usr/share/bash-completion/completions/rosin; COMP_WORDS=(rosin sc); COMP_CWORD=1; " \
             "_rosin; echo ${COMPREPLY[*]}"
    done = run(["bash", "-c", script])
    check(done.stdout.strip() == "scan", "the installed bash completion completes 'rosin sc' to scan: "
          + done.stdout.strip())


def system_install(deb, pluginhost, workdir):
    if run(["dpkg-query", "-W", "-f=${Status}", "rosin"]).stdout.startswith("install ok"):
        check(False, "a rosin package is already installed here: not touching it")
        return
    before = snapshot()
    result = run(["apt-get", "install", "-y", "-qq", deb], env=clean_env(DEBIAN_FRONTEND="noninteractive"))
    ok = result.returncode == 0
    if not check(ok, "apt-get install " + os.path.basename(deb) + ("" if ok else ": " + result.stdout[-800:])):
        return
    try:
        host_checks(pluginhost, None, label="default (/usr/lib/vst3, /usr/lib/lv2)")
        system_run = os.path.join(workdir, "system-run")
        os.makedirs(system_run)
        rosin_checks("/usr", system_run, mark_figure_script=False)
        manual_checks()
    finally:
        removed = run(["dpkg", "--remove", "rosin"])  # what `apt remove` does; the package has no conffiles
        check(removed.returncode == 0, "dpkg --remove rosin")
        run(["dpkg", "--purge", "rosin"])
    left = sorted(snapshot() - before)
    check(not left, "removing the package leaves nothing behind (%d new files: %s)" % (len(left), left[:5]))


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--build", required=True, help="the build folder (cmake -B)")
    parser.add_argument("--pluginhost", required=True, help="test_pluginhost")
    parser.add_argument("--system", action="store_true", help="also install the .deb on this machine (root)")
    args = parser.parse_args()
    workdir = tempfile.mkdtemp(prefix="rosin-install-test-")
    try:
        destdir = os.path.join(workdir, "stage")
        stage_install(args.build, destdir)
        usr = os.path.join(destdir, "usr")
        host_checks(args.pluginhost, usr + "/lib/vst3;" + usr + "/lib/lv2",
                    (usr + "/lib/vst3/Rosin.vst3", usr + "/lib/lv2/Rosin.lv2"))
        run_dir = os.path.join(workdir, "elsewhere")
        os.makedirs(run_dir)
        # The package is made from a fresh staging by cpack; the marker goes into this copy only.
        deb = package(args.build, workdir, destdir)
        rosin_checks(usr, run_dir, mark_figure_script=True)
        if args.system and deb:
            if check(os.geteuid() == 0, "--system runs as root"):
                system_install(deb, args.pluginhost, workdir)
    finally:
        shutil.rmtree(workdir, ignore_errors=True)
    print("%d failure(s)" % len(failures))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
