"""Reading and validating `rosin scan` output (Resources/docs/scan-format.md).

Everything here raises ScanError with a message that names the file and the
column or field at fault, so the command line can report it and exit 2
instead of drawing a misleading figure from half-understood data.
"""

import csv
import json
import math
import os
from dataclasses import dataclass, field

import numpy as np

FORMAT = "rosin-scan/1"

# rosin::analysis::regimeName, in the order of rosin::analysis::allRegimes().
REGIMES = ("helmholtz", "s-motion", "double-slipping", "multiple-slipping",
           "raucous", "alf", "constant-slipping", "no-slip")

NUMERIC_COLUMNS = ("beta", "bowForce", "transientPeriods", "muStatic", "jump",
                   "firstSlipTime", "slipsPerPeriod", "pitchCents")

# The third grid axis: (CSV column, scan.json grid key).
THIRD_AXIS = {"schelleng": ("bowSpeed", "bowSpeeds"),
              "guettler": ("acceleration", "accelerations")}

LOOP_COLUMNS = ("time", "slidingSpeed", "frictionForce", "contactTemperature")

# Values are written with %.9g, so nominal settings agree to ~1e-9.
GRID_TOLERANCE = 1e-6


class ScanError(Exception):
    """Input that does not follow the scan contract."""


@dataclass
class Scan:
    """One scan: grid axes, per-cell arrays shaped like the grid, and scan.json."""
    directory: str
    meta: dict
    kind: str
    betas: np.ndarray
    forces: np.ndarray
    third: np.ndarray            # bow speeds (Schelleng) or accelerations
    values: dict = field(default_factory=dict)  # column -> float array
    regime: np.ndarray = None    # index into REGIMES, -1 where no row
    failure: np.ndarray = None   # failure strings
    missing: int = 0             # grid cells without a CSV row (drawn blank)

    @property
    def shape(self):
        if self.kind == "schelleng":
            return (len(self.betas), len(self.forces))
        return (len(self.betas), len(self.forces), len(self.third))

    @property
    def json_path(self):
        return os.path.join(self.directory, "scan.json")

    @property
    def csv_path(self):
        return os.path.join(self.directory, "scan.csv")


def read_scan(directory):
    """Reads DIR/scan.json and DIR/scan.csv into a Scan."""
    json_path = os.path.join(directory, "scan.json")
    meta = _read_json(json_path)
    kind = _field(meta, "kind", str, json_path)
    if kind not in THIRD_AXIS:
        raise ScanError(f"{json_path}: field 'kind' is {kind!r}; expected "
                        "'schelleng' or 'guettler'")
    fmt = meta.get("format")
    if fmt != FORMAT:
        raise ScanError(f"{json_path}: field 'format' is {fmt!r}; expected {FORMAT!r}")
    grid = _field(meta, "grid", dict, json_path)
    for name in ("theory", "variations"):  # optional, but objects when present
        if meta.get(name) is not None:
            _field(meta, name, dict, json_path)
    third_key = THIRD_AXIS[kind][1]
    scan = Scan(directory, meta, kind,
                _axis(grid, "betas", json_path), _axis(grid, "forces", json_path),
                _axis(grid, third_key, json_path))
    if kind == "schelleng" and (scan.betas.min() <= 0 or scan.forces.min() <= 0):
        raise ScanError(f"{json_path}: 'grid.betas' and 'grid.forces' must be positive "
                        "(a Schelleng diagram has log axes)")
    _fill_from_csv(scan, os.path.join(directory, "scan.csv"))
    return scan


def read_loop(path):
    """Reads a hysteresis-loop CSV into a dict of float arrays."""
    header, rows = _read_csv(path, LOOP_COLUMNS)
    columns = {}
    for name in LOOP_COLUMNS:
        index = header.index(name)
        columns[name] = np.array([_number(row, index, name, path, line)
                                  for line, row in rows])
    if len(rows) < 2:
        raise ScanError(f"{path}: needs at least 2 data rows to draw a loop, has {len(rows)}")
    return columns


def _read_json(path):
    try:
        with open(path, encoding="utf-8") as stream:
            meta = json.load(stream)
    except OSError as error:
        raise ScanError(f"cannot read {path}: {error.strerror}") from error
    except json.JSONDecodeError as error:
        raise ScanError(f"{path} is not valid JSON: {error}") from error
    if not isinstance(meta, dict):
        raise ScanError(f"{path}: expected a JSON object at the top level")
    return meta


def _field(obj, name, kind, path, prefix=""):
    if name not in obj:
        raise ScanError(f"{path}: missing field '{prefix}{name}'")
    if not isinstance(obj[name], kind):
        raise ScanError(f"{path}: field '{prefix}{name}' should be a {kind.__name__}")
    return obj[name]


def _axis(grid, name, path):
    values = _field(grid, name, list, path, "grid.")
    if not values or not all(isinstance(v, (int, float)) and math.isfinite(v)
                             for v in values):
        raise ScanError(f"{path}: field 'grid.{name}' should be a non-empty list of numbers")
    return np.asarray(values, dtype=float)


def _read_csv(path, required):
    """Returns (header, [(line number, row)]) after checking required columns."""
    try:
        with open(path, newline="", encoding="utf-8") as stream:
            lines = list(csv.reader(stream))
    except OSError as error:
        raise ScanError(f"cannot read {path}: {error.strerror}") from error
    if not lines:
        raise ScanError(f"{path} is empty; expected a header line with columns "
                        + ",".join(required))
    header = [name.strip() for name in lines[0]]
    missing = [name for name in required if name not in header]
    if missing:
        raise ScanError(f"{path}: missing column(s) {', '.join(missing)} in the header "
                        f"(found: {','.join(header)})")
    rows = [(number, row) for number, row in enumerate(lines[1:], start=2) if row]
    for number, row in rows:
        if len(row) != len(header):
            raise ScanError(f"{path} line {number}: {len(row)} fields, header has {len(header)}")
    return header, rows


def _number(row, index, name, path, line):
    text = row[index].strip()
    if not text:
        return math.nan  # the contract's EMPTY
    try:
        return float(text)
    except ValueError:
        raise ScanError(f"{path} line {line}: column '{name}' has {text!r}, "
                        "expected a number or empty") from None


def _fill_from_csv(scan, path):
    third_column = THIRD_AXIS[scan.kind][0]
    required = ("cell",) + NUMERIC_COLUMNS + (third_column, "regime", "failure")
    header, rows = _read_csv(path, required)
    index = {name: header.index(name) for name in required}
    shape = scan.shape
    total = int(np.prod(shape))
    for name in NUMERIC_COLUMNS + (third_column,):
        scan.values[name] = np.full(total, math.nan)
    scan.regime = np.full(total, -1, dtype=int)
    scan.failure = np.full(total, "", dtype=object)
    seen = np.zeros(total, dtype=bool)
    for line, row in rows:
        cell = _cell(row[index["cell"]], total, path, line)
        if seen[cell]:
            raise ScanError(f"{path} line {line}: cell {cell} appears twice")
        seen[cell] = True
        for name in NUMERIC_COLUMNS + (third_column,):
            scan.values[name][cell] = _number(row, index[name], name, path, line)
        scan.regime[cell] = _regime(row[index["regime"]], path, line)
        scan.failure[cell] = row[index["failure"]].strip()
    _check_nominal(scan, path, seen)
    scan.missing = int(np.count_nonzero(~seen))
    for name in scan.values:
        scan.values[name] = scan.values[name].reshape(shape)
    scan.regime = scan.regime.reshape(shape)
    scan.failure = scan.failure.reshape(shape)


def _cell(text, total, path, line):
    try:
        cell = int(text)
    except ValueError:
        raise ScanError(f"{path} line {line}: column 'cell' has {text!r}, "
                        "expected an integer") from None
    if not 0 <= cell < total:
        raise ScanError(f"{path} line {line}: cell {cell} is outside the grid of "
                        f"{total} cells described by scan.json")
    return cell


def _regime(text, path, line):
    name = text.strip()
    if name not in REGIMES:
        raise ScanError(f"{path} line {line}: column 'regime' has {name!r}, "
                        f"expected one of {', '.join(REGIMES)}")
    return REGIMES.index(name)


def _check_nominal(scan, path, seen):
    """Each row's beta/force/etc. must be the grid value its cell index implies."""
    for column, nominal in _nominal(scan).items():
        actual = scan.values[column]
        bad = seen & ~np.isclose(actual, nominal, rtol=GRID_TOLERANCE, atol=0.0)
        if bad.any():
            cell = int(np.flatnonzero(bad)[0])
            raise ScanError(f"{path}: cell {cell} has {column} {actual[cell]:.9g}, but its "
                            f"grid position in {scan.json_path} gives {nominal[cell]:.9g}")


def _nominal(scan):
    """Flattened grid value of each cell, per CSV column, in cell order."""
    if scan.kind == "guettler":
        grids = np.meshgrid(scan.betas, scan.forces, scan.third, indexing="ij")
        names = ("beta", "bowForce", "acceleration")
        return {name: grid.ravel() for name, grid in zip(names, grids)}
    beta, force = np.meshgrid(scan.betas, scan.forces, indexing="ij")
    nominal = {"beta": beta.ravel(), "bowForce": force.ravel()}
    # Schelleng cells span (beta, force) only, so a single bow speed is implied.
    if len(scan.third) == 1:
        nominal["bowSpeed"] = np.full(beta.size, scan.third[0])
    return nominal


def check_same_grid(a, b):
    """Raises ScanError naming both scan.json files and the first difference."""
    where = f"cannot compare {a.json_path} with {b.json_path}"
    if a.kind != b.kind:
        raise ScanError(f"{where}: kinds differ ({a.kind} vs {b.kind})")
    key = THIRD_AXIS[a.kind][1]
    for name, x, y in (("betas", a.betas, b.betas), ("forces", a.forces, b.forces),
                       (key, a.third, b.third)):
        if len(x) != len(y):
            raise ScanError(f"{where}: grid.{name} has {len(x)} values vs {len(y)}")
        if not np.allclose(x, y, rtol=GRID_TOLERANCE, atol=0.0):
            i = int(np.flatnonzero(~np.isclose(x, y, rtol=GRID_TOLERANCE, atol=0.0))[0])
            raise ScanError(f"{where}: grid.{name}[{i}] is {x[i]:.9g} vs {y[i]:.9g}")
