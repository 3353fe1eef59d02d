#!/usr/bin/env python3
"""A 1000-point sizing sweep driven from Python against the same sweep run by the CLI
(docs/benchmarks.md, "Python"). Both are whole processes timed on the same machine:

    PYTHONPATH=build/python /usr/bin/python3 bench/scripts/python_sweep.py build/mmvlab [JOBS]

The CLI: `mmvlab sweep SPEC --jobs JOBS` (modes tracked, mass, deflection, check at
every point; journal and CSV written). `mmvlab.sweep(SPEC, OUT, jobs=JOBS)`: the same
sweep from Python (sweep.csv compared byte for byte). A Python loop: the same 1000 points read from the CLI's
sweep.csv, each `load_scene(set=...)`, `modes(...)` and `check(...)` in a thread pool of
JOBS workers (the studies release the GIL). The first frequency and the check verdict of
every point are compared with the CLI's row, so the two did the same work.
"""
import concurrent.futures
import csv
import os
import subprocess
import sys
import tempfile
import time

import mmvlab

SOURCE = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
KEYS = ["sections.link3_rod.radius", "links.link3.length", "links.link2.length"]
SPEC = f"""scene: {SOURCE}/scenes/mmv.yaml
parameters:
  - {{key: {KEYS[0]}, range: {{from: 0.001, to: 0.003, samples: 2}}}}
  - {{key: {KEYS[1]}, range: {{from: 0.5, to: 1.0, samples: 2}}}}
  - {{key: {KEYS[2]}, range: {{from: 1.2, to: 1.8, samples: 2}}}}
design: {{type: latin_hypercube, samples: 1000, seed: 3}}
outputs: [frequencies, mass, deflection, check]
"""


def point(values):
    scene = mmvlab.load_scene(set=dict(zip(KEYS, values)))
    m = mmvlab.modes(scene, modes=6, error_estimate=False)
    c = mmvlab.check(scene)
    return m.frequencies_hz[0], c.overall


def main(binary, jobs):
    with tempfile.TemporaryDirectory() as tmp:
        spec = os.path.join(tmp, "spec.yaml")
        with open(spec, "w") as f:
            f.write(SPEC)
        t = time.perf_counter()
        subprocess.run([binary, "sweep", spec, "--out", os.path.join(tmp, "cli"), "--jobs", str(jobs)], check=True,
                       stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        cli_s = time.perf_counter() - t
        with open(os.path.join(tmp, "cli", "sweep.csv")) as f:
            rows = list(csv.DictReader(f))
        t = time.perf_counter()
        api = mmvlab.sweep(spec, os.path.join(tmp, "api"), jobs=jobs)
        api_s = time.perf_counter() - t
        assert api.csv == open(os.path.join(tmp, "cli", "sweep.csv")).read(), "mmvlab.sweep wrote another sweep.csv"
    points = [[float(r[k.replace(".", "_")]) for k in KEYS] for r in rows]
    t = time.perf_counter()
    with concurrent.futures.ThreadPoolExecutor(jobs) as pool:
        results = list(pool.map(point, points))
    py_s = time.perf_counter() - t
    # mode1_hz is the nominal first mode tracked by its shape: the first frequency at
    # nearly every point (a point where another mode has dropped below it differs).
    same_f1 = sum(abs(f / float(r["mode1_hz"]) - 1) < 1e-9 for (f, _), r in zip(results, rows))
    same_verdict = sum(v == r["check_overall"] for (_, v), r in zip(results, rows))
    print(f"{len(points)} points, {jobs} jobs: CLI sweep {cli_s:.2f} s; mmvlab.sweep {api_s:.2f} s "
          f"(x{api_s / cli_s:.2f}, the same sweep.csv); Python loop of load_scene, modes, check {py_s:.2f} s "
          f"(x{py_s / cli_s:.2f}; first frequency equal (1e-9) at {same_f1}, check verdict at {same_verdict} "
          f"of {len(points)})")


if __name__ == "__main__":
    main(sys.argv[1], int(sys.argv[2]) if len(sys.argv) > 2 else 2)
