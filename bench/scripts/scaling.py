#!/usr/bin/env python3
"""Whole-process time and peak memory of the analysis commands against segments per
link (docs/benchmarks.md, "Whole-process cost by mesh"): median of 3 runs.

    bench/scripts/scaling.py build/mmvlab [SEGMENTS...]      # default 16 64 128
"""
import os
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from startup import measure  # noqa: E402


def commands(n, out):
    seg = ["--segments", str(n)]
    return [
        ("modes", ["modes"] + seg),
        ("compare", ["compare"] + seg),
        ("place-sensors", ["place-sensors"] + seg),
        ("frf, 1 pair, --rom-modes 10", ["frf", "scenes/mmv-table.yaml", "--input", "table_x", "--output",
                                         "link3a.tip:x", "--rom-modes", "10"] + seg),
        ("frf, default 2 x 8 pairs", ["frf", "scenes/mmv-table.yaml"] + seg),
        ("rom, default 2 x 8 pairs", ["rom", "scenes/mmv-table.yaml", "--out", out, "--force"] + seg),
        ("modes, table scene (damped)", ["modes", "scenes/mmv-table.yaml"] + seg),
        ("correlate, 16 FRFs + 12 modes", ["correlate", "scenes/mmv-table.yaml", "--measured",
                                           "docs/figures/correlate/measured.uff", "--modes", "12"] + seg),
    ]


def main():
    binary = sys.argv[1] if len(sys.argv) > 1 else "build/mmvlab"
    sizes = [int(a) for a in sys.argv[2:]] or [16, 64, 128]
    with tempfile.TemporaryDirectory() as tmp:
        rows = {}
        for n in sizes:
            for name, args in commands(n, os.path.join(tmp, "rom")):
                median, _, mb = measure(binary, args, runs=3)
                rows.setdefault(name, []).append("%.2f s, %d MB" % (median, mb))
                print("%-30s %4d  %.3f s  %d MB" % (name, n, median, mb), file=sys.stderr)
    print("| command | " + " | ".join("%d segments (%d DOF)" % (n, 4 * n) for n in sizes) + " |")
    print("|---|" + "---|" * len(sizes))
    for name, cells in rows.items():
        print("| `%s` | %s |" % (name, " | ".join(cells)))


if __name__ == "__main__":
    main()
