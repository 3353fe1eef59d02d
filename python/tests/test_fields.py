"""Results' tables from the library's field lists: each `table()` equals the CSV file the
command line writes for the same request, column for column (docs/python.md)."""
import csv
import json
import os
import subprocess
import warnings

import numpy as np
import pytest

import mmvlab

MMVLAB = os.environ["MMVLAB_BINARY"]
SOURCE = os.path.abspath(os.environ["MMVLAB_SOURCE_DIR"])


def cli_csv(path):
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    return rows[0], rows[1:]


def expect_table_is_the_csv(table, path, field_list):
    header, rows = cli_csv(path)
    assert header == [f["key"] for f in field_list if f["csv"]]
    assert list(table) == header
    for j, f in enumerate(f for f in field_list if f["csv"]):
        column = [r[j] for r in rows]
        if f["number"]:
            want = np.array([np.nan if c == "" else float(c) for c in column])
            np.testing.assert_allclose(table[f["key"]], want, rtol=1e-5, atol=1e-6, equal_nan=True, err_msg=f["key"])
        else:
            assert [c.replace(";", ",") for c in column] == [str(v).replace(";", ",") for v in table[f["key"]]], f["key"]


def test_every_named_list_is_described():
    names = mmvlab.field_list_names()
    assert {"check_lines", "convergence_points", "correlation_pairs", "hamsas_modes"} <= set(names)
    for name in names:
        fields = mmvlab.fields(name)
        assert len({f["key"] for f in fields}) == len(fields), name
        assert all(len(f["meaning"]) > 10 for f in fields), name
    with pytest.raises(mmvlab.UsageError, match="no field list 'nope'"):
        mmvlab.fields("nope")


def test_correlate_s_table_is_pairs_csv(tmp_path):
    measured = tmp_path / "measured"
    r = subprocess.run([MMVLAB, "frf", "--segments", "4", "--set", "materials.carbon_carbon.youngs_modulus=44.6e9",
                        "--out", str(measured)], capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    out = tmp_path / "correlate"
    r = subprocess.run([MMVLAB, "correlate", "--measured", str(measured / "frf.uff"), "--segments", "4", "--modes", "10",
                        "--damping", "0.02", "--out", str(out)], capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", mmvlab.RunWarning)
        py = mmvlab.correlate(mmvlab.load_scene(), str(measured / "frf.uff"), segments=4, modes=10, damping=0.02)
    table = py.table()
    assert len(table["test"]) == len(py.pairs) > 0
    expect_table_is_the_csv(table, out / "pairs.csv", mmvlab.fields("correlation_pairs"))
    np.testing.assert_allclose(table["frequency_error"], table["model_hz"] / table["test_hz"] - 1, rtol=1e-9)
    np.testing.assert_allclose(table["model_damping_ratio"], 0.02, rtol=1e-12)  # --damping: every mode's ratio


def test_converge_s_table_is_converge_csv(tmp_path):
    out = tmp_path / "converge"
    r = subprocess.run([MMVLAB, "converge", "--max-segments", "4", "--modes", "3", "--out", str(out)],
                       capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    c = mmvlab.converge(mmvlab.load_scene(), max_segments=4, modes=3)
    table = c.table()
    expect_table_is_the_csv(table, out / "converge.csv", mmvlab.fields("convergence_points"))
    # Each row's frequency two ways: the table's long form, the result's [mesh, mode] array.
    for mode, segments, f in zip(table["mode"], table["segments"], table["frequency_hz"]):
        assert f == pytest.approx(c.frequencies_hz[list(c.segments).index(segments), int(mode) - 1], rel=1e-9)


def test_compare_s_tables_are_its_csv_files(tmp_path):
    out = tmp_path / "compare"
    r = subprocess.run([MMVLAB, "compare", "--set", "model=spatial", "--segments", "2", "--modes", "6", "--out", str(out)],
                       capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    c = mmvlab.compare(mmvlab.load_scene(set={"model": "spatial"}), segments=2, modes=6)
    expect_table_is_the_csv(c.table(), out / "system_modes.csv", mmvlab.fields("compare_system_modes"))
    expect_table_is_the_csv(c.synthesis_table(), out / "synthesis.csv", mmvlab.fields("compare_synthesis"))


def test_simulate_s_tables_are_its_summary_and_text():
    scene = mmvlab.load_scene(os.path.join(SOURCE, "scenes", "mmv-slew.yaml"))
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        r = mmvlab.simulate(scene, segments=2, duration=0.5)
    torques, sensors = r.torques_table(), r.sensors_table()
    assert len(torques["joint"]) == len(r.json["torques"]) > 0 and len(sensors["name"]) == len(r.json["sensors"]) > 0
    # Each peak torque two ways: the table, and the text report's row for that joint.
    rows = {line.split()[0]: line.split() for line in r.text.splitlines() if line.split()[:1] and line.split()[0] in torques["joint"]}
    for joint, peak in zip(torques["joint"], torques["peak_torque_n_m"]):
        assert float(rows[joint][1]) == pytest.approx(peak, abs=5e-5)
        # and the history's own largest |torque| of that joint, where the run records it
        column = f"{joint}_torque_n_m"
        if column in r.history:
            assert np.max(np.abs(r.history[column])) <= peak * (1 + 1e-9) + 1e-12
    assert all(s <= n for s, n in zip(sensors["saturated_samples"], sensors["samples"]))
    # Each link's peak stress two ways: the table, and the history's own largest value of its column.
    stress = r.stress_table()
    assert stress["link"] == [l["link"] for l in r.json["stress"]] and len(stress["link"]) == 4
    for link, peak in zip(stress["link"], stress["peak_stress_pa"]):
        assert np.max(r.history[f"{link}_stress_pa"]) == pytest.approx(peak, rel=1e-9)


def test_place_sensors_tam_table_is_tam_csv(tmp_path):
    out = tmp_path / "tam"
    r = subprocess.run([MMVLAB, "place-sensors", "--segments", "8", "--modes", "1-6", "--count", "8", "--tam", "guyan,serep",
                        "--out", str(out)], capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    p = mmvlab.place_sensors(mmvlab.load_scene(), segments=8, modes=range(1, 7), count=8, tam=["guyan", "serep"])
    assert [t["method"] for t in p.tams] == ["guyan", "serep"]
    expect_table_is_the_csv(p.tam_table(), out / "tam.csv", mmvlab.fields("tam_modes"))
    assert p.tam_csv == (out / "tam.csv").read_text()
    loaded = mmvlab.place_sensors(mmvlab.load_scene(), segments=8, count=8, sensor_mass=1e-6)
    assert len(loaded.json["mass_loading"]["modes"]) == len(loaded.target_modes)
    spread = mmvlab.place_sensors(mmvlab.load_scene(), segments=16, count=24, min_separation=0.15)
    cli = subprocess.run([MMVLAB, "place-sensors", "--segments", "16", "--count", "24", "--min-separation", "0.15", "--json"],
                         capture_output=True, text=True)
    assert [c["station"] for c in spread.chosen] == [c["station"] for c in json.loads(cli.stdout)["chosen"]]
    with pytest.raises(mmvlab.UsageError, match="^keep_out link1:0:2.44: covers the whole link"):
        mmvlab.place_sensors(mmvlab.load_scene(), segments=4, keep_out="link1:0:2.44")
    assert len(mmvlab.place_sensors(mmvlab.load_scene(), segments=8, channels=12, triaxial=True).chosen) == 4
    with pytest.raises(mmvlab.UsageError, match="sensor_mass"):
        mmvlab.place_sensors(mmvlab.load_scene(), segments=4, sensor_mass=101)
    with pytest.raises(mmvlab.UsageError, match="^tam: unknown test-analysis model 'craig'"):
        mmvlab.place_sensors(mmvlab.load_scene(), segments=4, tam="craig")


def test_a_hamsas_modes_table_is_its_modes_csv(tmp_path):
    scene = os.path.join(SOURCE, "scenes", "hamsas.yaml")
    out = tmp_path / "hamsas"
    r = subprocess.run([MMVLAB, "modes", scene, "--modes", "8", "--out", str(out)], capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    m = mmvlab.modes(mmvlab.load_scene(scene), modes=8)
    table = m.table()
    expect_table_is_the_csv(table, out / "modes.csv", mmvlab.fields("hamsas_modes"))
    np.testing.assert_array_equal(table["frequency_hz"], m.frequencies_hz)


def test_place_sensors_exciter_tables_are_its_csvs(tmp_path):
    out = tmp_path / "shaker"
    args = [MMVLAB, "place-sensors", "--segments", "8", "--count", "12", "--out", str(out),
            "--set", "shaker.at=link2@1.2m", "--set", "shaker.direction=[0, 1, 0]"]
    r = subprocess.run(args, capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    p = mmvlab.place_sensors(mmvlab.load_scene(set={"shaker.at": "link2@1.2m", "shaker.direction": [0, 1, 0]}), segments=8, count=12)
    assert p.exciter["at"] == "link2@1.2m"
    expect_table_is_the_csv(p.exciter_table(), out / "exciter.csv", mmvlab.fields("exciter_modes"))
    ranking = p.exciter_ranking_table()
    header, rows = cli_csv(out / "exciter_ranking.csv")
    assert list(ranking) == header
    assert ranking["station"] == [row[header.index("station")] for row in rows[:10]]
    np.testing.assert_allclose(ranking["score"], [float(row[header.index("score")]) for row in rows[:10]], rtol=1e-5)
    assert mmvlab.place_sensors(mmvlab.load_scene(), segments=8, count=12).exciter is None


def test_correlate_tam_test_orthogonality(tmp_path):
    out = tmp_path / "pretest"
    p = subprocess.run([MMVLAB, "place-sensors", "--segments", "8", "--modes", "1-6", "--count", "8", "--tam", "serep",
                        "--out", str(out)], capture_output=True, text=True)
    assert p.returncode == 0, p.stderr
    c = mmvlab.correlate(mmvlab.load_scene(), str(out / "test_geometry.uff"), segments=8, modes=8, tam=str(out / "tam.mat"))
    t = c.json["test_orthogonality"]
    assert t["method"] == "serep" and t["pass"]
    np.testing.assert_allclose(np.array(t["matrix"]), np.eye(6), atol=1e-5)


def test_place_sensors_keeps_the_scenes_sensors_as_the_cli():
    slew = os.path.join(SOURCE, "scenes", "mmv-slew.yaml")
    p = mmvlab.place_sensors(mmvlab.load_scene(slew), segments=8, count=8, keep_scene_sensors=True)
    cli = subprocess.run([MMVLAB, "place-sensors", slew, "--segments", "8", "--count", "8", "--keep-scene-sensors", "--json"],
                         capture_output=True, text=True)
    assert cli.returncode == 0, cli.stderr
    fixed = lambda chosen: sorted(f"{c['station']} {c['axis']}" for c in chosen if c["fixed"] == 1)
    assert fixed(p.chosen) == ["link2@1.52m transverse", "link3a@0.762m transverse"]
    assert fixed(json.loads(cli.stdout)["chosen"]) == fixed(p.chosen)
    with pytest.raises(mmvlab.UsageError, match="below the 2 accelerometers"):
        mmvlab.place_sensors(mmvlab.load_scene(slew), segments=8, count=1, keep_scene_sensors=True)


def test_place_sensors_with_an_instrument_iterated_as_the_cli():
    scene = mmvlab.load_scene(set={"instruments.accelerometer.mass_kg": 0.002})
    p = mmvlab.place_sensors(scene, segments=8, count=8, modes=[1, 2, 3, 4], iterate_loaded=True)
    cli = subprocess.run([MMVLAB, "place-sensors", "--segments", "8", "--count", "8", "--modes", "1-4", "--iterate-loaded",
                          "--set", "instruments.accelerometer.mass_kg=0.002", "--json"], capture_output=True, text=True)
    assert cli.returncode == 0, cli.stderr
    assert p.json["mass_loading"] == json.loads(cli.stdout)["mass_loading"]
    assert p.json["instrument"]["mass_kg"] == 0.002
    assert [f["key"] for f in mmvlab.fields("mass_loading_iterations")] == ["pass", "changed", "tie", "settled", "repeats"]
    with pytest.raises(mmvlab.UsageError, match="instrument='accelerometr'|unknown instrument 'accelerometr'"):
        mmvlab.place_sensors(scene, segments=8, count=8, instrument="accelerometr")


def test_place_sensors_films_as_the_cli():
    p = mmvlab.place_sensors(mmvlab.load_scene(), segments=8, count=6, modes=[1, 2, 3, 4], strain_span=0.3)
    cli = subprocess.run([MMVLAB, "place-sensors", "--segments", "8", "--count", "6", "--modes", "1-4", "--strain-span", "0.3",
                          "--json"], capture_output=True, text=True)
    assert cli.returncode == 0, cli.stderr
    assert p.json == json.loads(cli.stdout) | {"mmvlab_version": p.json["mmvlab_version"]}
    assert p.json["sensor"] == "strain" and p.json["strain_span_m"] == 0.3
    assert all(c["axis"] == "strain" for c in p.json["chosen"])
    with pytest.raises(mmvlab.UsageError, match="effective independence only"):
        mmvlab.place_sensors(mmvlab.load_scene(), segments=8, count=6, strain_span=0.3, method="mke")


def test_modes_strains_as_the_cli():
    span = "link3a@0.1m:link3a@0.5m"
    m = mmvlab.modes(mmvlab.load_scene(), segments=4, modes=3, strains=span, error_estimate=False)
    cli = subprocess.run([MMVLAB, "modes", "--segments", "4", "--modes", "3", "--no-error-estimate", "--strain", span, "--json"],
                         capture_output=True, text=True)
    assert cli.returncode == 0, cli.stderr
    assert [x["strains"] for x in m.json["modes"]] == [x["strains"] for x in json.loads(cli.stdout)["modes"]]
    with pytest.raises(mmvlab.UsageError, match="the span is empty"):
        mmvlab.modes(mmvlab.load_scene(), segments=4, strains="link3a@0.1m:link3a@0.1m")
