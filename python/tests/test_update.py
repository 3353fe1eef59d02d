"""mmvlab.update against the CLI's JSON for the same request, its tables against the
CSVs the CLI writes, HAM-SAS from Python, and its errors named as Python spells them."""
import csv
import json
import os
import subprocess

import pytest

import mmvlab

MMVLAB = os.environ["MMVLAB_BINARY"]
SOURCE = os.path.abspath(os.environ["MMVLAB_SOURCE_DIR"])


def test_update_equals_the_cli_json_and_csv(measured_uff, tmp_path):
    key = "materials.carbon_carbon.youngs_modulus"
    py = mmvlab.update(mmvlab.load_scene(), [key + ":30e9:60e9"], measured=measured_uff, segments=4, modes=10)
    out = tmp_path / "u"
    r = subprocess.run([MMVLAB, "update", "--segments", "4", "--measured", measured_uff, "--modes", "10", "--params",
                        key + ":30e9:60e9", "--json", "--out", str(out)], capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    cli = json.loads(r.stdout)
    assert py.json == cli
    assert py.converged and py.updated[key] == pytest.approx(44.6e9, rel=1e-4)  # conftest's measured set: 44.6e9
    with open(out / "parameters.csv", newline="") as f:
        rows = list(csv.DictReader(f))
    table = py.table()
    assert list(rows[0].keys()) == list(table.keys())
    assert float(rows[0]["updated"]) == table["updated"][0]  # %.17g: the same double
    assert py.updated_scene == (out / "updated_scene.yaml").read_text()
    assert len(py.pairs_table()["test"]) == len(cli["pairs"])
    assert "MMV" in repr(py) and "MMV" in repr(mmvlab.check(mmvlab.load_scene(), segments=2))  # scene as {name} or a name


def test_update_of_hamsas_from_python_needs_no_file():
    s = mmvlab.load_scene(os.path.join(SOURCE, "scenes", "hamsas.yaml"),
                          set={"hamsas.mgas_vertical_stiffness": 108.57})
    with pytest.raises(mmvlab.UsageError, match="params hamsas.mgas_vertical_stiffness: also given by --set"):
        mmvlab.update(s, ["hamsas.mgas_vertical_stiffness"])
    u = mmvlab.update(mmvlab.load_scene(os.path.join(SOURCE, "scenes", "hamsas.yaml")), {"hamsas.mgas_vertical_stiffness": (50, 200)})
    assert u.converged and u.updated["hamsas.mgas_vertical_stiffness"] == pytest.approx(98.7, rel=0.01)


@pytest.mark.parametrize("kwargs, name", [
    (dict(params=["materials.carbon_carbon.youngs_modulus:50e9:60e9"]), "params"),
    (dict(params=["materials.carbon_carbon.youngs_modulus"], frequency_sigma=0), "frequency_sigma"),
    (dict(params=["materials.carbon_carbon.youngs_modulus"], max_iterations=0), "max_iterations"),
    (dict(params=["materials.carbon_carbon.youngs_modulus"], modes=0), "modes"),
    (dict(params=[]), "params"),
])
def test_update_options_are_named_as_python_spells_them(measured_uff, kwargs, name):
    with pytest.raises(mmvlab.UsageError, match=f"^{name}"):
        mmvlab.update(mmvlab.load_scene(), measured=measured_uff, segments=2, **kwargs)
