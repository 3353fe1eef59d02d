#!/usr/bin/env python3
"""The undamped free swing: mmvlab's cheapest run within 1e-4 m at the tip against MuJoCo's
RK4 on the same model (docs/benchmarks.md, "Against MuJoCo"; issue 37).

    bench/scripts/mujoco_swing.py [build]
    bench/scripts/mujoco_swing.py --check [build]   # the first 0.5 s by both codes, untimed

--check (the test suite's mujoco.swing_agrees_with_mmvlab): MuJoCo's RK4 at 1e-4 s and
mmvlab's ARKODE ERK at 1e-4 (both limited by the hinges' stability, not accuracy) must agree within 1e-6 m at the tip over the first 0.5 s.

The scene is bench/mujoco/free-swing.yaml (the two-link demo's elbow released 30 deg off
hanging, unbent, at rest, no damping, 2 s, every hinge); mjcf_export writes it as MJCF.
The reference is MuJoCo's RK4 at 1e-5 s, checked against mmvlab's ARKODE ERK at 1e-8
(the two must agree within 1e-6 m, or the script exits 1). Then the largest RK4 step (of
those dividing the 10 ms sample interval) within 1e-4 m of it, and for each of mmvlab's
integrators the loosest tolerance within 1e-4 m, on the same model and with each link in
its 3 or 4 lowest modes (`links.<name>.modes`), and the scene's default run (`simulation.
fidelity: auto`: the modes a release needs, CVODE BDF at the default tolerance), each
timed whole-process (MuJoCo's median of 5, mmvlab's of 3).
"""
import csv
import math
import os
import subprocess
import sys
import tempfile
import time

SCENE = "bench/mujoco/free-swing.yaml"
TARGET = 1e-4
STEPS = [1e-3, 5e-4, 2.5e-4, 2e-4, 1.25e-4, 0.01 / 95, 1e-4, 5e-5]  # 0.01 / 90 and larger: unstable
TOLERANCES = [1e-3, 1e-4, 1e-5, 1e-6]
INTEGRATORS = ["cvode_bdf", "rk_merson", "arkode_erk", "cpodes"]
MODAL_INTEGRATORS = ["arkode_erk", "cvode_bdf"]  # links in modal coordinates take SUNDIALS' ODE methods


def timed(args, runs):
    times = []
    for _ in range(runs):
        t = time.perf_counter()
        p = subprocess.run(args, capture_output=True, text=True)
        times.append(time.perf_counter() - t)
    times.sort()
    return times[len(times) // 2], p


def mujoco_tip(build, xml, h, runs=1, duration=2.0):
    seconds, p = timed([os.path.join(build, "bench", "mujoco_swing"), xml, "lower.tip", repr(h), repr(duration), "100"], runs)
    if p.returncode == 3:  # MuJoCo's state went to NaN or huge (mujoco_swing checks its warnings)
        return seconds, None
    if p.returncode != 0:
        sys.exit("mujoco_swing failed: " + p.stderr)
    return seconds, [(float(r["x"]), float(r["y"])) for r in csv.DictReader(p.stdout.splitlines())]


def mmvlab_tip(build, tmp, integrator, tol, runs=1, extra=()):
    """integrator None: the scene's default fidelity (`simulation.fidelity: auto`), integrator and tolerance."""
    out = os.path.join(tmp, "run")
    chosen = ["--set", "simulation.fidelity=auto"] if integrator is None else ["--integrator", integrator, "--accuracy", repr(tol)]
    args = [os.path.join(build, "mmvlab"), "simulate", SCENE, "--out", out, "--force"] + chosen + list(extra)
    seconds, p = timed(args, runs)
    if p.returncode != 0:
        return seconds, None
    with open(os.path.join(out, "history.csv")) as f:
        return seconds, [(float(r["lower_tip_x_m"]), float(r["lower_tip_y_m"])) for r in csv.DictReader(f)]


def error(a, ref):
    return max(math.hypot(u[0] - v[0], u[1] - v[1]) for u, v in zip(a, ref)) if a and len(a) == len(ref) else math.inf


def main():
    argv = sys.argv[1:]
    check = bool(argv) and argv[0] == "--check"
    argv = argv[1:] if check else argv
    build = argv[0] if argv else "build"
    with tempfile.TemporaryDirectory() as tmp:
        xml = os.path.join(tmp, "swing.xml")
        with open(xml, "w") as f:
            subprocess.run([os.path.join(build, "bench", "mjcf_export"), SCENE], stdout=f, check=True)
        if check:
            _, theirs = mujoco_tip(build, xml, 1e-4, duration=0.5)
            _, ours = mmvlab_tip(build, tmp, "arkode_erk", 1e-4, extra=["--duration", "0.5"])
            e = error(ours, theirs)
            print("the first 0.5 s: MuJoCo RK4 at 1e-4 s and mmvlab arkode_erk at 1e-4 agree within %.2g m at the tip" % e)
            sys.exit(0 if e <= 1e-6 else "they differ by more than 1e-6 m")
        _, ref = mujoco_tip(build, xml, 1e-5)
        _, check = mmvlab_tip(build, tmp, "arkode_erk", 1e-8)
        agree = error(check, ref)
        print("reference: MuJoCo RK4 at 1e-5 s; mmvlab arkode_erk at 1e-8 within %.2g m of it" % agree)
        if agree > 1e-6:
            sys.exit("the two codes' swings differ by %.2g m" % agree)
        best = None
        for h in STEPS:
            _, tip = mujoco_tip(build, xml, h)
            e = error(tip, ref)
            print("  MuJoCo RK4 h = %-8g tip error %s" % (h, "unstable" if tip is None else "%.2g m" % e))
            if e <= TARGET:
                best = h
                break
        mj_seconds, _ = mujoco_tip(build, xml, best, runs=5)
        print("MuJoCo RK4 h = %g: %.3f s whole process (median of 5)" % (best, mj_seconds))
        # The same model (every hinge), then each link in its lowest modes (a coarser model:
        # the truncation is part of its error, held to the same 1e-4 m).
        candidates = [("every hinge", integrator, []) for integrator in INTEGRATORS]
        for modes in (3, 4):
            extra = ["--set", "links.upper.modes=%d" % modes, "--set", "links.lower.modes=%d" % modes]
            candidates += [("%d modes a link" % modes, integrator, extra) for integrator in MODAL_INTEGRATORS]
        # What a user gets who names neither the model nor the integrator (docs/accuracy.md,
        # "The default fidelity"): the rule's modes for a release, its integrator and tolerance.
        seconds, tip = mmvlab_tip(build, tmp, None, None, runs=3)
        e = error(tip, ref)
        print("mmvlab the scene's default run (fidelity auto) tip error %.2g m%s: %.3f s whole process (median of 3), %.2fx MuJoCo"
              % (e, "" if e <= TARGET else " (NOT within 1e-4 m)", seconds, seconds / mj_seconds))
        for label, integrator, extra in candidates:
            for tol in TOLERANCES:
                seconds, tip = mmvlab_tip(build, tmp, integrator, tol, extra=extra)
                e = error(tip, ref)
                if e <= TARGET:
                    seconds, _ = mmvlab_tip(build, tmp, integrator, tol, runs=3, extra=extra)
                    print("mmvlab %-16s %-10s accuracy %-6g tip error %.2g m: %.3f s whole process (median of 3), %.2fx MuJoCo"
                          % (label, integrator, tol, e, seconds, seconds / mj_seconds))
                    break
                print("  mmvlab %-16s %-10s accuracy %-6g tip error %.2g m (%.2f s)" % (label, integrator, tol, e, seconds))


if __name__ == "__main__":
    main()
