#!/usr/bin/env python3
"""A whole-process render against STK's: the wall time of `rosin render` bowing the cello D
string for SECONDS (one voice with the cello body, plastic law, the radiated sound written as a 32-bit float
WAV) against `stk-render` (benchmarks/StkRender.cpp: STK's Bowed at the same pitch, written by STK's
FileWvOut), each run RUNS times, the two interleaved so that the machine's drift hits both; prints the best
time of each and their ratio. Speed is reported, never asserted.

    python3 benchmarks/render_vs_stk.py BUILD_DIR [--seconds 60] [--runs 3]
    (or: cmake --build build --target render-vs-stk)
"""
import argparse
import pathlib
import subprocess
import sys
import tempfile
import time


def timed(command):
    began = time.perf_counter()
    subprocess.run(command, check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    return time.perf_counter() - began


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("build_dir", type=pathlib.Path)
    parser.add_argument("--seconds", type=float, default=60.0)
    parser.add_argument("--runs", type=int, default=3)
    args = parser.parse_args()
    rosin = args.build_dir / "rosin"
    stk = args.build_dir / "benchmarks" / "stk-render"
    for binary in (rosin, stk):
        if not binary.exists():
            sys.exit(f"{binary}: not built (cmake --build {args.build_dir})")
    gesture = f"steady:speed=0.1,force=1,beta=0.1,seconds={args.seconds:g}"
    with tempfile.TemporaryDirectory() as tmp:
        jobs = {
            "rosin render": [str(rosin), "render", "--preset", "cello-plastic", "--gesture", gesture,
                             "--out", f"{tmp}/rosin.wav"],
            "stk-render": [str(stk), f"{args.seconds:g}", f"{tmp}/stk.wav"],
        }
        best = {name: float("inf") for name in jobs}
        for _ in range(args.runs):
            for name, command in jobs.items():
                best[name] = min(best[name], timed(command))
    print(f"{args.seconds:g} s of audio at 48 kHz, best of {args.runs} interleaved runs:")
    for name, seconds in best.items():
        print(f"  {name:<13} {seconds:6.3f} s wall")
    print(f"  ratio         {best['rosin render'] / best['stk-render']:.2f} x STK")


if __name__ == "__main__":
    main()
