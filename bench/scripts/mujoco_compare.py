#!/usr/bin/env python3
"""`mmvlab modes` against MuJoCo doing the same work on the same model (docs/benchmarks.md,
"Against MuJoCo"; issue 37).

    bench/scripts/mujoco_compare.py [--check] [build] [segments ...]   # default: build 8 16 24

--check compares the frequencies only, untimed (the test suite's mujoco.modes_agree).
MuJoCo 2.2.2 reads MJCF with tinyxml2, which refuses elements nested past 100 deep: a
chain of bodies is nested, so the article's three links stop at 24 segments each (32 is
refused: "Element nesting is too deep").

For each mesh: mjcf_export writes the scene's segment model as MJCF (not timed);
mujoco_modes loads it, finds the equilibrium, linearizes and solves the 12 lowest modes;
`mmvlab modes --segments N --no-error-estimate` does the same (and with its error estimate,
which MuJoCo has no counterpart for). Each command is timed whole-process (medians of 21,
peak memory); the frequencies of the two must agree to 1e-8, or the script exits 1.
"""
import json
import os
import subprocess
import sys
import tempfile
import time

RUNS = 21


def measure(args):
    times, peak = [], 0
    for _ in range(RUNS):
        t = time.perf_counter()
        p = subprocess.Popen(args, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        _, status, usage = os.wait4(p.pid, 0)
        times.append(time.perf_counter() - t)
        peak = max(peak, usage.ru_maxrss)
        if status != 0:
            sys.exit("%s failed (status %d)" % (" ".join(args), status))
    times.sort()
    return times[len(times) // 2], times[0], peak // 1024


def main():
    argv = sys.argv[1:]
    check = bool(argv) and argv[0] == "--check"
    argv = argv[1:] if check else argv
    build = argv[0] if argv else "build"
    meshes = [int(a) for a in argv[1:]] or [8, 16, 24]
    mmvlab = os.path.join(build, "mmvlab")
    export = os.path.join(build, "bench", "mjcf_export")
    mujoco = os.path.join(build, "bench", "mujoco_modes")
    worst = 0.0
    with tempfile.TemporaryDirectory() as tmp:
        for n in meshes:
            xml = os.path.join(tmp, "article%d.xml" % n)
            with open(xml, "w") as f:
                subprocess.run([export, "scenes/mmv.yaml", str(n)], stdout=f, check=True)
            theirs = subprocess.run([mujoco, xml, "12"], capture_output=True, text=True, check=True).stdout.split("\n")
            ours = json.loads(subprocess.run([mmvlab, "modes", "--segments", str(n), "--no-error-estimate", "--json"],
                                             capture_output=True, text=True, check=True).stdout)["modes"]
            diff = max(abs(float(theirs[1 + k]) - m["frequency_hz"]) / m["frequency_hz"] for k, m in enumerate(ours[:12]))
            worst = max(worst, diff)
            rows = [("mujoco_modes", [mujoco, xml, "12"]),
                    ("mmvlab modes --no-error-estimate", [mmvlab, "modes", "--segments", str(n), "--no-error-estimate"]),
                    ("mmvlab modes", [mmvlab, "modes", "--segments", str(n)])]
            base = None
            print("%d segments a link (%s), 12 modes; frequencies agree to %.1e" % (n, theirs[0], diff))
            for name, args in [] if check else rows:
                median, best, mb = measure(args)
                base = base or median
                print("  %-34s median %.4f s  min %.4f s  peak %3d MB  %.2fx MuJoCo" % (name, median, best, mb, median / base))
    if worst > 1e-8:
        sys.exit("the frequencies differ by %.1e (more than 1e-8)" % worst)


if __name__ == "__main__":
    main()
