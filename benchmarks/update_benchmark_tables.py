#!/usr/bin/env python3
"""Puts the benchmarks' own summary tables into Resources/docs/benchmarks.md: the figures are printed by the
benchmarks, not typed. Runs build/benchmarks/bench_voice and bench_plugin with --markdown=FILE and replaces
what lies between the page's two markers with their tables and the machine (no date: the page says what the
code does, git says when).

    python3 benchmarks/update_benchmark_tables.py BUILD_DIR [PAGE]   (or: cmake --build build
        --target readme-benchmarks)
    python3 benchmarks/update_benchmark_tables.py --check PAGE       (the markers and a table are there)
"""
import os
import pathlib
import platform
import subprocess
import sys
import tempfile

BEGIN = "<!-- benchmark-tables:begin (benchmarks/update_benchmark_tables.py writes this part) -->"
END = "<!-- benchmark-tables:end -->"
BENCHMARKS = [
    ("bench_voice", "One voice (cello D3 with the cello body) per friction law, and the four-string cello "
                    "stepped directly"),
    ("bench_plugin", "The plugin's `processBlock` with the four-string cello: all four strings bowed (a held "
                     "chord), and a solo line (one string bowed, the other three ringing)"),
]


def machine():
    """CPU model and core count, as the kernel reports them."""
    model = platform.processor() or platform.machine()
    try:
        for line in pathlib.Path("/proc/cpuinfo").read_text().splitlines():
            if line.startswith("model name"):
                model = line.split(":", 1)[1].strip()
                break
    except OSError:
        pass
    return f"{model}, {os.cpu_count()} cores"


def run(build_dir):
    """The Markdown summary of each benchmark, in BENCHMARKS order."""
    tables = []
    with tempfile.TemporaryDirectory() as tmp:
        for name, caption in BENCHMARKS:
            binary = pathlib.Path(build_dir) / "benchmarks" / name
            if not binary.exists():
                sys.exit(f"{binary}: not built (cmake --build {build_dir} --target {name})")
            out = pathlib.Path(tmp) / f"{name}.md"
            subprocess.run([str(binary), f"--markdown={out}"], check=True, stdout=subprocess.DEVNULL)
            tables.append(f"{caption} (`build/benchmarks/{name}`):\n\n{out.read_text().strip()}\n")
    return tables


def section(tables):
    head = (f"Printed by the benchmarks on an {machine()}; `cmake --build build --target "
            "readme-benchmarks` runs them again and rewrites this part.\n")
    return "\n".join([BEGIN, head] + tables + [END])


def replace(text, new_section):
    start, stop = text.find(BEGIN), text.find(END)
    if start < 0 or stop < start:
        raise ValueError(f"the page has no '{BEGIN}' ... '{END}' section")
    return text[:start] + new_section + text[stop + len(END):]


def check(readme):
    text = pathlib.Path(readme).read_text()
    start, stop = text.find(BEGIN), text.find(END)
    if start < 0 or stop < start:
        sys.exit(f"{readme}: the benchmark section's markers are missing")
    body = text[start:stop]
    for name, _ in BENCHMARKS:
        if f"build/benchmarks/{name}" not in body:
            sys.exit(f"{readme}: no table from {name} in the benchmark section")
    if "| benchmark | ns per sample |" not in body or "STK_Bowed" not in body:
        sys.exit(f"{readme}: the benchmark section holds no table printed by the benchmarks")
    print(f"{readme}: benchmark section present")


def main(argv):
    if len(argv) >= 2 and argv[1] == "--check":
        check(argv[2] if len(argv) > 2 else "Resources/docs/benchmarks.md")
        return
    if len(argv) < 2:
        sys.exit(__doc__)
    readme = pathlib.Path(argv[2] if len(argv) > 2 else "Resources/docs/benchmarks.md")
    readme.write_text(replace(readme.read_text(), section(run(argv[1]))))
    print(f"{readme}: benchmark section rewritten")


if __name__ == "__main__":
    main(sys.argv)
