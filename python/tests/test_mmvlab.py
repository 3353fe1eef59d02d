"""The Python API against the command line and its own promises (docs/python.md).

Run by ctest (python.api) with PYTHONPATH at build/python and MMVLAB_BINARY the CLI.
"""
import _thread
import csv
import io
import gc
import json
import os
import subprocess
import threading
import time
import warnings

import numpy as np
import pytest

import mmvlab

MMVLAB = os.environ["MMVLAB_BINARY"]
SOURCE = os.path.abspath(os.environ["MMVLAB_SOURCE_DIR"])
TIMING_KEYS = {"time_s", "seconds", "wall_time_s"}


def cli_json(*args):
    r = subprocess.run([MMVLAB, *args, "--json"], capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    return json.loads(r.stdout)


def without_timing(x):
    """The document with its wall times removed (they differ between any two runs)."""
    if isinstance(x, dict):
        return {k: without_timing(v) for k, v in x.items() if k not in TIMING_KEYS and not k.endswith("_time_s")}
    if isinstance(x, list):
        return [without_timing(v) for v in x]
    return x


def scene_path(name):
    return os.path.join(SOURCE, "scenes", name)


# --- every verb from Python equals the CLI's JSON for the same request ---------------

def test_modes_equal_the_cli_json():
    py = mmvlab.modes(mmvlab.load_scene(), segments=8, modes=6)
    assert without_timing(py.json) == without_timing(cli_json("modes", "--segments", "8", "--modes", "6"))
    assert py.frequencies_hz.shape == (6,)
    np.testing.assert_array_equal(py.frequencies_hz, [m["frequency_hz"] for m in py.json["modes"]])


def test_the_mode_table_the_csv_and_the_json_come_from_one_field_list():
    m = mmvlab.modes(mmvlab.load_scene(scene_path("mmv-table.yaml")), segments=4, modes=8)
    fields = mmvlab.mode_fields()
    table = m.table()
    header = m.csv.splitlines()[0].split(",")
    assert list(table) == header  # the same columns in the same order
    assert header == [f["key"] for f in fields if f["csv"] and f["key"] in header]
    assert "damping_ratio" in header and "effective_mass_z_kg" not in header  # damped, planar
    rows = list(csv.DictReader(io.StringIO(m.csv)))
    for k in header:  # each column two ways: the CSV's digits and the JSON's numbers
        for row, value, mode in zip(rows, table[k], m.json["modes"]):
            if isinstance(value, str):
                assert row[k] == value
            elif np.isnan(value):
                assert row[k] == "" and mode.get(k) is None
            else:
                assert float(row[k]) == pytest.approx(value, rel=1e-5, abs=1e-12), k
    np.testing.assert_array_equal(table["frequency_hz"], m.frequencies_hz)
    keys = {f["key"] for f in fields}
    for mode in m.json["modes"]:
        assert set(mode) - {"shape", "at_points", "stress_per_mm_of_peak"} <= keys  # lists, not fields
    h = mmvlab.modes(mmvlab.load_scene(scene_path("hamsas.yaml")))  # its own record: its scalar keys
    np.testing.assert_array_equal(h.table()["frequency_hz"], h.frequencies_hz)


def test_modes_with_set_points_and_a_file_equal_the_cli_json():
    path = scene_path("mmv-table.yaml")
    py = mmvlab.modes(mmvlab.load_scene(path, set={"materials.s_glass_epoxy.youngs_modulus": 45e9}), segments=4,
                      modes=4, points=["link1.tip", "link2@0.5"], error_estimate=False)
    cli = cli_json("modes", path, "--set", "materials.s_glass_epoxy.youngs_modulus=45000000000.0", "--segments", "4",
                   "--modes", "4", "--points", "link1.tip", "--points", "link2@0.5", "--no-error-estimate")
    assert without_timing(py.json) == without_timing(cli)


def test_hamsas_modes_equal_the_cli_json():
    py = mmvlab.modes(mmvlab.load_scene(scene_path("hamsas.yaml")), modes=0)
    assert without_timing(py.json) == without_timing(cli_json("modes", scene_path("hamsas.yaml"), "--modes", "0"))
    assert py.shapes.shape[0] == len(py.frequencies_hz)
    # Each moving body's six motions, as modes.json's shape lists them.
    assert py.shape_components == ["tx", "ty", "tz", "rx", "ry", "rz"]
    assert py.shapes.shape == (len(py.frequencies_hz), len(py.json["modes"][0]["shape"]), 6)
    first = py.json["modes"][0]["shape"][0]
    assert py.shape_points[0] == first["body"]
    assert list(py.shapes[0, 0]) == first["translation"] + first["rotation"]


def test_frf_equals_the_cli_json_and_its_csv(tmp_path):
    args = ["--segments", "8", "--input", "table_x", "--input", "force:link3a.tip:y", "--output", "link3a.tip:y",
            "--output", "link2.tip:x:disp", "--to", "40", "--points", "120"]
    py = mmvlab.frf(mmvlab.load_scene(), segments=8, inputs=["table_x", "force:link3a.tip:y"],
                    outputs=["link3a.tip:y", "link2.tip:x:disp"], f_max_hz=40, points=120)
    assert without_timing(py.json) == without_timing(cli_json("frf", *args))
    assert py.H.shape == (len(py.frequencies_hz), 2, 2) and py.output_names == ["link3a.tip:y", "link2.tip:x:disp"]
    # The same responses as the CSV `frf --out` writes (8 significant digits there).
    out = tmp_path / "frf"
    r = subprocess.run([MMVLAB, "frf", *args, "--out", str(out)], capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    csv = np.genfromtxt(out / "frf_link3a.tip_y__force_link3a.tip_y.csv", delimiter=",", names=True)
    np.testing.assert_allclose(csv["frequency_hz"], py.frequencies_hz, rtol=1e-7)
    np.testing.assert_allclose(csv["magnitude_db"], 20 * np.log10(np.abs(py.H[:, 0, 1])), atol=1e-6)
    np.testing.assert_allclose(csv["rom_magnitude_db"], 20 * np.log10(np.abs(py.H_reduced[:, 0, 1])), atol=1e-6)


def test_rom_equals_the_cli_json_and_its_matrices_give_its_responses(tmp_path):
    py = mmvlab.rom(mmvlab.load_scene(), segments=8, rom_modes=6)
    r = subprocess.run([MMVLAB, "rom", "--segments", "8", "--rom-modes", "6", "--out", str(tmp_path / "rom"), "--json"],
                       capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    assert without_timing(py.json) == without_timing(json.loads(r.stdout))
    # H_reduced computed again from the matrices: C (i w E - A)^-1 B + D.
    m = py.reduced
    assert m["A"].shape == (12, 12) and py.full["A"].shape[0] > 12
    for k in (0, len(py.frequencies_hz) // 2, -1):
        w = 2 * np.pi * py.frequencies_hz[k]
        h = m["C"] @ np.linalg.solve(1j * w * m["E"] - m["A"], m["B"]) + m["D"]
        np.testing.assert_allclose(h, py.H_reduced[k], rtol=1e-9, atol=1e-12 * np.abs(py.H_reduced[k]).max())


def test_simulate_equals_the_cli_json_and_history(tmp_path):
    path = scene_path("mmv-slew.yaml")
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", mmvlab.RunWarning)
        py = mmvlab.simulate(mmvlab.load_scene(path), segments=2, duration=0.5, integrator="rk_merson", accuracy=1e-4)
    args = ["--segments", "2", "--duration", "0.5", "--integrator", "rk_merson", "--accuracy", "1e-4"]
    assert without_timing(py.json) == without_timing(cli_json("simulate", path, *args))
    out = tmp_path / "run"
    r = subprocess.run([MMVLAB, "simulate", path, *args, "--out", str(out)], capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    with open(out / "history.csv") as f:
        header = f.readline().strip().split(",")
    rows = np.loadtxt(out / "history.csv", delimiter=",", skiprows=1)
    assert header == py.columns and rows.shape == py.history_array.shape
    for c in ("time_s", "joint2_torque_n_m", "gimbal_yaw_angle_deg"):
        k = header.index(c)
        np.testing.assert_allclose(rows[:, k], py.history[c], rtol=1e-7, atol=1e-9 * np.abs(py.history[c]).max())


def test_sweep_equals_the_cli_sweep(tmp_path):
    spec = tmp_path / "spec.yaml"
    spec.write_text(f"scene: {scene_path('mmv.yaml')}\n"
                    "segments: 4\n"
                    "parameters:\n"
                    "  - {key: sections.link3_rod.radius, range: {from: 0.001, to: 0.003, samples: 3}}\n"
                    "  - {key: links.link3.length, values: [0.5, 0.762]}\n"
                    "design: grid\n"
                    "outputs: [frequencies, mass, check]\n"
                    "modes: 3\n")
    py = mmvlab.sweep(spec, tmp_path / "py", jobs=2)
    r = subprocess.run([MMVLAB, "sweep", str(spec), "--out", str(tmp_path / "cli"), "--jobs", "1", "--json"],
                       capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    cli = json.loads(r.stdout)
    assert (tmp_path / "py" / "sweep.csv").read_text() == (tmp_path / "cli" / "sweep.csv").read_text()
    for k in ("fingerprint", "design", "points", "shard", "computed", "reused", "columns", "fields"):
        assert py.json[k] == cli[k], k
    assert py.columns == cli["columns"] and len(py.table["mode1_hz"]) == 6
    # One field list made the header and the field records: same keys, same order; its
    # units and kinds are the ones the CSV's cells have.
    assert [f["key"] for f in cli["fields"]] == cli["columns"]
    assert py.fields["mode1_hz"]["unit"] == "Hz" and py.fields["mass_kg"]["unit"] == "kg"
    assert py.fields["mode1_mac"]["unit"] == "1" and not py.fields["check_overall"]["number"]
    assert all(isinstance(py.table[k], np.ndarray) == f["number"] for k, f in py.fields.items())
    assert py.table["status"] == ["ok"] * 6
    again = mmvlab.sweep(spec, tmp_path / "py")  # resumed: every point already in the journal
    assert again.json["computed"] == 0 and again.json["reused"] == 6
    with pytest.raises(mmvlab.UsageError, match="jobs"):
        mmvlab.sweep(spec, tmp_path / "x", jobs=-1)
    with pytest.raises(mmvlab.UsageError, match="jobs: must be a finite number of at least 0 and at most 1024"):
        mmvlab.sweep(spec, tmp_path / "x", jobs=1025)
    at_bound = mmvlab.sweep(spec, tmp_path / "bound", jobs=1024)  # the documented bound is accepted
    assert at_bound.csv == py.csv and at_bound.json["jobs"] == 1024
    with pytest.raises(mmvlab.UsageError, match="shard"):
        mmvlab.sweep(spec, tmp_path / "x", shard=(3, 2))


def test_converge_and_compare_equal_the_cli_json():
    s = mmvlab.load_scene()
    c = mmvlab.converge(s, max_segments=8, modes=3)
    assert without_timing(c.json) == without_timing(cli_json("converge", "--max-segments", "8", "--modes", "3"))
    np.testing.assert_array_equal(c.segments, [1, 2, 4, 8])
    # The finest mesh's first frequency, a second way: modes at 8 segments.
    assert c.frequencies_hz[-1, 0] == mmvlab.modes(s, segments=8, modes=1, error_estimate=False).frequencies_hz[0]
    p = mmvlab.compare(s, segments=4, component_modes=3, modes=6, bc="pinned-free", tip_mass="1.5,0.01")
    cli = cli_json("compare", "--segments", "4", "--component-modes", "3", "--modes", "6", "--bc", "pinned-free",
                   "--tip-mass", "1.5,0.01")
    assert without_timing(p.json) == without_timing(cli)


def test_check_equals_the_cli_json():
    py = mmvlab.check(mmvlab.load_scene(), segments=4, margin=30, band_hz=(0.5, 40))
    assert without_timing(py.json) == without_timing(cli_json("check", "--segments", "4", "--margin", "30",
                                                              "--band", "0.5:40"))
    assert py.overall == py.json["overall"]


def test_check_table_is_check_csv(tmp_path):
    """CheckResult.table() and `check --out`'s check.csv: one field list, the same columns
    and values (the CSV's 8 significant digits)."""
    scene = scene_path("mmv-table.yaml")
    py = mmvlab.check(mmvlab.load_scene(scene), segments=4).table()
    out = tmp_path / "c"
    subprocess.run([MMVLAB, "check", scene, "--segments", "4", "--out", str(out)], check=True, capture_output=True)
    with open(out / "check.csv", newline="") as f:
        rows = list(csv.DictReader(f))
    assert list(py.keys()) == [f["key"] for f in mmvlab.check_line_fields()] == list(rows[0].keys())
    assert len(rows) == len(py["id"]) >= 5
    for k, f in enumerate(rows):
        for field in mmvlab.check_line_fields():
            key, cell = field["key"], f[field["key"]]
            if field["unit"]:
                got = py[key][k]
                assert (cell == "" and np.isnan(got)) or abs(float(cell) - got) <= 1e-7 * abs(got), (key, cell, got)
            else:
                assert cell == py[key][k].replace(",", ";").replace('"', "'"), (key, cell)  # CSV text, escaped


def test_place_sensors_equals_the_cli_json():
    py = mmvlab.place_sensors(mmvlab.load_scene(), segments=4, count=6, modes=[1, 2, 3], method="mke")
    cli = cli_json("place-sensors", "--segments", "4", "--count", "6", "--modes", "1-3", "--method", "mke")
    assert without_timing(py.json) == without_timing(cli)
    assert len(py.chosen) == 6


def test_sweep_config_equals_the_cli_json():
    py = mmvlab.sweep_config(mmvlab.load_scene(), "joint2:0:20:10", segments=2, modes=3, method="craig-bampton")
    cli = cli_json("sweep-config", "--segments", "2", "--grid", "joint2:0:20:10", "--modes", "3", "--method",
                   "craig-bampton")
    assert without_timing(py.json) == without_timing(cli)
    assert len(py.points) == 3 and py.columns[0] == "joint2_deg"
    # Each tracked frequency two ways: sweep.csv's digits and the JSON's number.
    rows = [(p["angles_deg"][0], t["frequency_hz"]) for p in py.points for t in p["tracks"]]
    assert len(rows) == len(py.table["frequency_hz"])
    for (angle, f), a, g in zip(rows, py.table["joint2_deg"], py.table["frequency_hz"]):
        assert a == angle and g == pytest.approx(f, rel=1e-7)


def test_hamsas_frf_and_rom_equal_the_cli_json(tmp_path):
    h = mmvlab.load_scene(scene_path("hamsas.yaml"))
    py = mmvlab.frf(h, points=60, vary=("counterweight_mass", [0, 3.5]))
    cli = cli_json("frf", scene_path("hamsas.yaml"), "--points", "60", "--vary", "counterweight_mass=0,3.5")
    assert without_timing(py.json) == without_timing(cli)
    assert py.T.shape == (60, 6, 6) and py.dof_names[0] == "x" and len(py.varied["points"]) == 2
    # Each curve two ways: the complex array's magnitude and the JSON's dB.
    for p in py.json["pairs"]:
        i, j = py.dof_names.index(p["table"]), py.dof_names.index(p["ground"])
        seen = abs(py.T[:, i, j]) > 1e-15  # an exact zero (by symmetry) is the JSON's floor, -inf here
        np.testing.assert_allclose(20 * np.log10(abs(py.T[seen, i, j])), np.array(p["magnitude_db"])[seen], rtol=1e-9)
    # The 10 Hz table two ways: the study's own at 10 Hz and a grid 1, 10, 100 Hz's middle.
    t = mmvlab.frf(h, f_min_hz=1, f_max_hz=100, points=3)
    assert t.frequencies_hz[1] == pytest.approx(10, rel=1e-12)
    for i in range(6):
        assert 20 * np.log10(abs(t.T[1, i, i])) == pytest.approx(t.json["at_10_hz_db"][i][i], abs=1e-6)
    rom = mmvlab.rom(h, points=60, rom_modes=6)
    out = tmp_path / "rom"
    cli_rom = cli_json("rom", scene_path("hamsas.yaml"), "--points", "60", "--rom-modes", "6", "--out", str(out))
    assert without_timing(rom.json) == without_timing(cli_rom)
    assert rom.H.shape == (60, 8, 8) and rom.full["A"].shape[0] == rom.full["A"].shape[1]
    # The reduced model's responses recomputed from its matrices equal the ones returned.
    E, A, B, C, D = (rom.reduced[m] for m in "EABCD")
    w = 2 * np.pi * rom.frequencies_hz[7]
    np.testing.assert_allclose(C @ np.linalg.solve(1j * w * E - A, B) + D, rom.H_reduced[7], rtol=1e-9, atol=1e-12)


def test_trade_equals_the_cli_json():
    kw = dict(segments=2, duration=0.2, integrators=["rk3", "cvode_bdf"], accuracies=[1e-3, 1e-5], segment_ladder=[1],
              modes_ladder=[1], modes_accuracies=[1e-5], all=True)
    py = mmvlab.trade(mmvlab.load_scene(scene_path("mmv-slew.yaml")), **kw)
    cli = cli_json("trade", scene_path("mmv-slew.yaml"), "--segments", "2", "--duration", "0.2", "--integrators",
                   "rk3,cvode_bdf", "--accuracies", "1e-3,1e-5", "--segment-ladder", "1", "--modes-ladder", "1",
                   "--modes-accuracies", "1e-5", "--all")
    # cheapest_within_target is chosen by the runs' measured CPU time: two runs of the same
    # trade on a loaded machine may order rk3 and cvode_bdf differently (seen under the
    # sanitizers), so it is left out with the timings.
    strip = lambda d: {k: v for k, v in without_timing(d).items() if k not in ("runs", "total_seconds", "cheapest_within_target")}
    assert strip(py.json) == strip(cli)
    # The runs, less their wall times: the same runs with the same errors (deterministic).
    runs = lambda d: [{k: v for k, v in r.items() if k not in ("cpu_s", "pareto", "status")} for r in d["runs"]]
    assert runs(py.json) == runs(cli)
    assert py.columns[0] == "integrator" and len(py.table["tip_error_m"]) == len(py.runs)
    # Each run's error two ways: trade.csv's digits and the JSON's number.
    for e, r in zip(py.table["tip_error_m"], py.runs):
        assert e == pytest.approx(r["tip_error_m"], rel=1e-5)


def test_correlate_equals_the_cli_json(measured_uff):
    s = mmvlab.load_scene()
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", mmvlab.RunWarning)
        py = mmvlab.correlate(s, measured_uff, segments=4, modes=10, mac_threshold=0.6, damping=0.02,
                              pairs={1: "link1.root"})
    cli = cli_json("correlate", "--measured", measured_uff, "--segments", "4", "--modes", "10", "--mac-threshold", "0.6",
                   "--damping", "0.02", "--pair", "1=link1.root")
    assert without_timing(py.json) == without_timing(cli)
    assert py.mac.shape == (len(cli["test_modes"]), 10)
    assert len(py.pairs) > 0 and py.frequency_errors.shape == (len(py.pairs),)
    # Each pair's frequency error two ways: from the pair, and from the two frequency lists.
    for p, e in zip(py.pairs, py.frequency_errors):
        t, m = int(p["test"][1:]) - 1, int(p["model"][1:]) - 1
        assert e == pytest.approx(py.model_frequencies_hz[m] / py.test_frequencies_hz[t] - 1, rel=1e-12, abs=1e-15)
        assert py.mac[t, m] == pytest.approx(p["mac"])
    assert py.frac.shape == (16,) and np.all((py.frac >= 0) & (py.frac <= 1))  # 4 tips x 2 axes x 2 table inputs


def test_correlate_warns_what_the_cli_warns(measured_uff):
    with pytest.warns(mmvlab.RunWarning, match="raise modes|raise --modes"):
        mmvlab.correlate(mmvlab.load_scene(), measured_uff, segments=4, modes=3)


def test_correlate_s_measured_file_errors_are_python_s():
    with pytest.raises(mmvlab.SceneFileError, match="nonexistent.uff"):
        mmvlab.correlate(mmvlab.load_scene(), "/nonexistent.uff", segments=2)
    with pytest.raises(mmvlab.UsageError, match="correlate"):
        mmvlab.correlate(mmvlab.load_scene(scene_path("hamsas.yaml")), "/nonexistent.uff")


# --- values checked once, named as Python spells them --------------------------------

@pytest.mark.parametrize("call, name", [
    (lambda s: mmvlab.modes(s, segments=1025), "segments"),
    (lambda s: mmvlab.modes(s, segments=-1), "segments"),
    (lambda s: mmvlab.modes(mmvlab.load_scene(scene_path("hamsas.yaml")), segments=-1), "segments"),
    (lambda s: mmvlab.modes(s, modes=-1), "modes"),
    (lambda s: mmvlab.modes(s, target_error=1e-3, modes=0), "target_error"),
    (lambda s: mmvlab.modes(s, points=["link9.tip"]), "points"),
    (lambda s: mmvlab.check(s, margin=99.5), "margin"),
    (lambda s: mmvlab.check(s, band_hz=(5, 1)), "band"),
    (lambda s: mmvlab.place_sensors(s, count=0), "count"),
    (lambda s: mmvlab.place_sensors(s, count=100001), "count"),
    (lambda s: mmvlab.place_sensors(s, spacing=1e-4), "spacing"),
    (lambda s: mmvlab.place_sensors(s, method="best"), "method"),
    (lambda s: mmvlab.place_sensors(s, modes=[1, 2], below_hz=30), "below_hz"),
    (lambda s: mmvlab.frf(s, points=1), "points"),
    (lambda s: mmvlab.frf(s, rom_modes=0), "rom_modes"),
    (lambda s: mmvlab.frf(s, damping=1.5), "damping"),
    (lambda s: mmvlab.frf(s, f_min_hz=10, f_max_hz=1), "from"),
    (lambda s: mmvlab.frf(s, inputs=["push:link1.tip"]), "input"),
    (lambda s: mmvlab.frf(s, outputs=["link9.tip:y"]), "output"),
    (lambda s: mmvlab.rom(s, target_error=0.6), "target_error"),
    (lambda s: mmvlab.rom(s, segments=4, target_error=1e-2), "target_error"),
    (lambda s: mmvlab.converge(s, max_segments=1025), "max_segments"),
    (lambda s: mmvlab.converge(s, modes=0), "modes"),
    (lambda s: mmvlab.compare(s, bc="welded"), "bc"),
    (lambda s: mmvlab.compare(s, tip_mass="-1"), "tip_mass"),
    (lambda s: mmvlab.compare(s, component_modes=201), "component_modes"),
    (lambda s: mmvlab.compare(s, topologies=["ring"]), "topologies"),
    (lambda s: mmvlab.simulate(s, duration=0), "duration"),
    (lambda s: mmvlab.simulate(s, duration=-1), "duration"),
    (lambda s: mmvlab.simulate(s, sample_rate=float("nan")), "sample_rate"),
    (lambda s: mmvlab.simulate(s, integrator="rk45"), "integrator"),
    (lambda s: mmvlab.simulate(s, accuracy=1.0), "accuracy"),
    (lambda s: mmvlab.simulate(s, absolute_tolerance=1e-6, integrator="rk_merson"), "absolute_tolerance"),
    (lambda s: mmvlab.simulate(s, time_budget=3), "time_budget"),
    (lambda s: mmvlab.simulate(s, target_error=1e-3, accuracy=1e-5), "target_error"),
    (lambda s: mmvlab.correlate(s, "x.uff", pair_distance=0), "pair_distance"),
    (lambda s: mmvlab.correlate(s, "x.uff", modes=501), "modes"),
    (lambda s: mmvlab.correlate(s, "x.uff", mac_threshold=1.01), "mac_threshold"),
    (lambda s: mmvlab.correlate(s, "x.uff", max_frequency_error=0), "max_frequency_error"),
    (lambda s: mmvlab.correlate(s, "x.uff", damping=-0.01), "damping"),
    (lambda s: mmvlab.correlate(s, "x.uff", pairs=["x=link1.tip"]), "pair"),
    (lambda s: mmvlab.correlate(s, ""), "measured"),
    (lambda s: mmvlab.trade(s, integrators=["rk45"]), "integrators"),
    (lambda s: mmvlab.frf(mmvlab.load_scene(scene_path("hamsas.yaml")), inputs=["table_x"]), "input"),
    (lambda s: mmvlab.frf(mmvlab.load_scene(scene_path("hamsas.yaml")), vary="mass=abc"), "vary"),
    (lambda s: mmvlab.frf(mmvlab.load_scene(scene_path("hamsas.yaml")), target_error=0.01), "target_error"),
    (lambda s: mmvlab.frf(s, vary="counterweight_mass=1"), "vary"),
    (lambda s: mmvlab.sweep_config(s, "joint9:0:10:5"), "grids"),
    (lambda s: mmvlab.sweep_config(s, []), "grids"),
    (lambda s: mmvlab.sweep_config(s, "joint2:0:10:5", modes=0), "modes"),
    (lambda s: mmvlab.sweep_config(s, "joint2:0:10:5", method="guyan"), "method"),
    (lambda s: mmvlab.trade(s, accuracies=[1.0]), "accuracies"),
    (lambda s: mmvlab.trade(s, segment_ladder=[0]), "segment_ladder"),
    (lambda s: mmvlab.trade(s, modes_ladder=[-1]), "modes_ladder"),
    (lambda s: mmvlab.trade(s, duration=0), "duration"),
    (lambda s: mmvlab.trade(s, time_budget=-1), "time_budget"),
])
def test_a_bad_argument_is_a_usage_error_naming_it(call, name):
    with pytest.raises(mmvlab.UsageError) as e:
        call(mmvlab.load_scene())
    assert str(e.value).startswith(name) or f" {name}" in str(e.value), str(e.value)
    assert "--" not in str(e.value).split(":")[0], "named as the command line spells it"


def test_the_documented_limits_hold_at_the_bound():
    s = mmvlab.load_scene()
    assert mmvlab.check(s, segments=2, margin=99).json["overall"]
    with pytest.raises(mmvlab.UsageError, match="^count 100000: there are"):  # the parser accepts it, the analysis refuses
        mmvlab.place_sensors(s, segments=2, count=100000)


# --- one exception class per error class ------------------------------------------------

def test_a_bad_scene_value_is_a_scene_error_with_its_position(tmp_path):
    with pytest.raises(mmvlab.SceneError, match="links.link2.E=abc"):
        mmvlab.load_scene(set={"links.link2.E": "abc"})
    bad = tmp_path / "bad.yaml"
    bad.write_text(open(scene_path("mmv.yaml")).read().replace("density: 1650", "density: -1650"))
    with pytest.raises(mmvlab.SceneError, match=r"bad.yaml:\d+:\d+"):
        mmvlab.load_scene(str(bad))


def test_a_missing_file_is_a_scene_file_error():
    with pytest.raises(mmvlab.SceneFileError):
        mmvlab.load_scene("/nonexistent/scene.yaml")
    with pytest.raises(mmvlab.UsageError):
        mmvlab.load_scene("")


def test_numbers_that_cannot_be_trusted_are_a_numerical_error(tmp_path):
    p = tmp_path / "singular.yaml"
    p.write_text("name: horizontal pendulum\n"
                 "materials: {m: {density: 1000, youngs_modulus: 1e9}}\n"
                 "sections: {s: {shape: explicit, area: 1e-4, second_moment: 1e-10}}\n"
                 "base: {direction_deg: -90}\n"
                 "joints: [{name: j1, parent: base, angle_deg: 90, hold: free}]\n"
                 "links: [{name: l1, joint: j1, material: m, section: s, length: 1.0, segments: rigid}]\n")
    with pytest.raises(mmvlab.NumericalError, match="tangent stiffness is singular"):
        mmvlab.modes(mmvlab.load_scene(str(p)))


def test_the_error_classes_are_one_family_and_python_s_own():
    for cls, builtin in [(mmvlab.UsageError, ValueError), (mmvlab.SceneError, ValueError),
                         (mmvlab.SceneFileError, OSError), (mmvlab.NumericalError, ArithmeticError),
                         (mmvlab.UnavailableError, mmvlab.Error), (mmvlab.InternalError, mmvlab.Error)]:
        assert issubclass(cls, mmvlab.Error) and issubclass(cls, builtin)


def test_a_hamsas_scene_refuses_what_does_not_apply():
    h = mmvlab.load_scene(scene_path("hamsas.yaml"))
    with pytest.raises(mmvlab.UsageError, match="check"):
        mmvlab.check(h)
    with pytest.raises(mmvlab.UsageError, match="segments"):
        mmvlab.modes(h, segments=4)


# --- warnings -----------------------------------------------------------------------------

def test_a_unit_slip_is_a_warning_and_strict_makes_it_an_error():
    with pytest.warns(mmvlab.SceneWarning, match="likely a unit mistake"):
        mmvlab.load_scene(set={"links.link1.length": 900})
    with pytest.raises(mmvlab.SceneError, match="strict"):
        mmvlab.load_scene(set={"links.link1.length": 900}, strict=True)


# --- long runs: the GIL, Ctrl-C, progress ------------------------------------------------

def long_modes(**kw):
    return mmvlab.modes(mmvlab.load_scene(), segments=256, modes=12, **kw)


def long_run(kind):
    if kind == "modes":
        return long_modes()
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", mmvlab.RunWarning)
        return mmvlab.simulate(mmvlab.load_scene(scene_path("mmv-slew.yaml")), segments=8, duration=10)


@pytest.mark.parametrize("kind", ["modes", "simulate"])
def test_ctrl_c_interrupts_a_long_run_and_the_interpreter_goes_on(kind):
    long_run(kind)  # warm: the first call pays for loading
    t0 = time.monotonic()
    long_run(kind)
    clean = time.monotonic() - t0
    fired = []

    def ctrl_c():
        fired.append(time.monotonic())
        _thread.interrupt_main()

    timer = threading.Timer(clean * 0.2, ctrl_c)
    timer.start()
    try:
        with pytest.raises(KeyboardInterrupt):
            long_run(kind)
    finally:
        timer.cancel()  # a run that failed otherwise must not interrupt the next test
        timer.join()
    latency = time.monotonic() - fired[0]
    # Between two steps of the study, not at its end (which is 80 % of the run away).
    assert latency < clean * 0.5, f"stopped {latency:.3f} s after Ctrl-C, in a {clean:.3f} s run"
    assert mmvlab.modes(mmvlab.load_scene(), segments=4, modes=3).frequencies_hz.shape == (3,)


def test_the_gil_is_released_during_a_study():
    ticks = []
    done = threading.Event()

    def count():
        while not done.is_set():
            ticks.append(1)
            time.sleep(0.001)

    t = threading.Thread(target=count, daemon=True)
    t.start()
    t0 = time.monotonic()
    try:
        long_modes(error_estimate=False)
        elapsed = time.monotonic() - t0
    finally:
        done.set()  # a run that failed must not leave the thread counting (the interpreter would wait for it)
        t.join()
    # A thread held off by the GIL would tick about once (at the start); a free one
    # ticks every millisecond or so.
    assert len(ticks) > 0.1 * elapsed / 0.001, f"{len(ticks)} ticks in {elapsed:.2f} s"


def test_progress_reports_stages_and_an_exception_in_it_ends_the_run():
    seen = []
    long_modes(progress=lambda stages: seen.append(stages))
    assert seen and all(isinstance(s, list) and s for s in seen)
    assert all(s[0][0] == "python" for s in seen), seen[:3]  # outermost first
    assert any(len(s) > 1 and ("equilibrium" in s[1][0] or "eigen" in s[1][0] or "assembling" in s[1][0]) for s in seen), seen


    def stop(stages):
        raise RuntimeError("enough")

    with pytest.raises(RuntimeError, match="enough"):
        long_modes(progress=stop)


# --- arrays own their data --------------------------------------------------------------

def test_arrays_own_their_data_and_outlive_the_result():
    m = mmvlab.modes(mmvlab.load_scene(), segments=4, modes=5)
    f, shapes = m.frequencies_hz, m.shapes
    assert f.flags.owndata and shapes.flags.owndata
    expected = f.copy()
    del m
    gc.collect()
    for _ in range(3):
        mmvlab.modes(mmvlab.load_scene(), segments=4, modes=5)
    np.testing.assert_array_equal(f, expected)
    assert np.isfinite(shapes[:, :, 0]).all()


def test_version_is_the_cli_and_cmake_version():
    import re
    cmake = open(os.path.join(SOURCE, "CMakeLists.txt")).read()
    version = re.search(r"project\(mmvlab VERSION ([0-9.]+)", cmake).group(1)
    assert mmvlab.__version__ == version
    r = subprocess.run([MMVLAB, "--version"], capture_output=True, text=True)
    assert r.stdout.strip() == "mmvlab " + version


def test_scenes_and_results_pickle_and_give_the_same_study():
    import pickle
    scene = mmvlab.load_scene(os.path.join(SOURCE, "scenes", "mmv-table.yaml"), set={"links.link2.length": 1.5},
                              segments=4, no_gravity=True)
    again = pickle.loads(pickle.dumps(scene))
    assert (again.name, again.source, again.kind, again.warnings) == (scene.name, scene.source, scene.kind,
                                                                      scene.warnings)
    a, b = mmvlab.modes(scene, modes=4), mmvlab.modes(again, modes=4)
    assert without_timing(a.json) == without_timing(b.json)  # the same patches, segments and gravity
    r = pickle.loads(pickle.dumps(a))
    assert (r.frequencies_hz == a.frequencies_hz).all() and r.json == a.json and r.text == a.text
    # A pickle of another format is refused by name, not read as a scene.
    with pytest.raises(Exception, match="not a pickled scene"):
        mmvlab.Scene.__new__(mmvlab.Scene).__setstate__((2, "", "", "", [], None, False, False, []))


def test_a_path_with_a_nul_and_a_sweep_without_a_folder_are_refused(tmp_path, monkeypatch):
    # "mmv.yaml\0junk" loaded mmv.yaml; sweep(spec, None) wrote into a folder named ./None.
    with pytest.raises(mmvlab.UsageError, match="NUL"):
        mmvlab.load_scene(os.path.join(SOURCE, "scenes", "mmv.yaml") + "\0junk")
    monkeypatch.chdir(tmp_path)
    spec = tmp_path / "spec.yaml"
    spec.write_text(f"scene: {SOURCE}/scenes/mmv.yaml\nparameters:\n  - {{key: links.link2.length, values: [1.5]}}\n"
                    "outputs: [mass]\n")
    with pytest.raises(mmvlab.UsageError, match="out"):
        mmvlab.sweep(spec, None)
    assert not (tmp_path / "None").exists()


def test_a_sweep_replaces_only_its_own_files(tmp_path):
    spec = tmp_path / "spec.yaml"
    spec.write_text(f"scene: {SOURCE}/scenes/mmv.yaml\nsegments: 4\nparameters:\n"
                    "  - {key: links.link2.length, values: [1.4, 1.6]}\noutputs: [mass]\n")
    out = tmp_path / "out"
    out.mkdir()
    (out / "sweep.csv").write_text("the user's own\n")
    with pytest.raises(mmvlab.OutputError, match="was not written by mmvlab"):
        mmvlab.sweep(spec, out, restart=True)
    assert sorted(p.name for p in out.iterdir()) == ["sweep.csv"]
    assert (out / "sweep.csv").read_text() == "the user's own\n"
    (out / "sweep.csv").unlink()
    first = mmvlab.sweep(spec, out)
    assert (out / "sweep.json").exists() and (out / ".mmvlab-outputs").exists()
    again = mmvlab.sweep(spec, out)  # its own files: replaced on the resume
    assert again.csv == first.csv
