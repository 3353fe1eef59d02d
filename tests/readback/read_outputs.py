#!/usr/bin/python3
"""Reads every CSV and JSON file under the given directories the way users' tools do,
and fails (exit 1, naming the file and the column) if any would mangle it or cannot
read it. JSON: Python's json module, strictly (NaN and Infinity refused). CSV:

- Python's csv module: a header, and every row as long as it;
- numpy.genfromtxt(names=True): the field names it makes must be the header's own
  (it rewrites '.', ':', '/', '-', spaces and more, as MATLAB's readtable does);
- every header name a valid identifier in Python and in MATLAB/Octave (letters, digits
  and '_', starting with a letter, at most 63 characters).

Prints 'N passed, N failed' (one test per file)."""
import csv
import json
import keyword
import re
import sys
from pathlib import Path

import numpy as np

IDENT = re.compile(r"^[A-Za-z][A-Za-z0-9_]{0,62}$")


def problems(path):
    out = []
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    if not rows:
        return ["empty file"]
    header = rows[0]
    for name in header:
        if not IDENT.match(name) or keyword.iskeyword(name):
            out.append(f"column '{name}' is not a name numpy, pandas and MATLAB keep")
    for i, row in enumerate(rows[1:], start=2):
        if len(row) != len(header):
            out.append(f"line {i}: {len(row)} fields, the header has {len(header)}")
            break
    if any("," in cell for row in rows for cell in row):
        out.append("a quoted field holds a comma: numpy's genfromtxt and Octave's csvread split it")
    elif len(rows) > 1:
        try:
            data = np.genfromtxt(path, delimiter=",", names=True, dtype=None, encoding="utf-8", max_rows=50)
        except ValueError as e:
            return out + ["numpy cannot read it: " + str(e).splitlines()[-1].strip()]
        names = list(data.dtype.names or [])
        if names != header:
            diff = [f"{a} -> {b}" for a, b in zip(header, names) if a != b]
            out.append("numpy renames columns: " + ", ".join(diff[:5]))
    return out


def json_problems(path):
    def refuse(name):
        raise ValueError(f"{name} is not JSON")
    try:
        with open(path) as f:
            json.load(f, parse_constant=refuse)
    except ValueError as e:
        return [f"not strict JSON: {e}"]
    return []


def main():
    # journal.csv is a sweep's own resume record (a comment line, then rows), not a table.
    files = sorted(p for d in sys.argv[1:] for p in Path(d).rglob("*.csv") if p.name != "journal.csv")
    files += sorted(p for d in sys.argv[1:] for p in Path(d).rglob("*.json"))
    passed = failed = 0
    for p in files:
        bad = json_problems(p) if p.suffix == ".json" else problems(p)
        if bad:
            failed += 1
            for b in bad:
                print(f"{p}: {b}")
        else:
            passed += 1
    if not files:
        print("no CSV or JSON file found")
        failed += 1
    print(f"{passed} passed, {failed} failed")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
