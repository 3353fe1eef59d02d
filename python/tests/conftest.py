"""Fixtures the Python tests share."""
import os
import subprocess

import pytest


@pytest.fixture(scope="session")
def measured_uff(tmp_path_factory):
    """A "measured" set: the FRFs and modes `frf --out` writes with links 1 and 2 8 % stiffer."""
    out = tmp_path_factory.mktemp("measured") / "frf"
    r = subprocess.run([os.environ["MMVLAB_BINARY"], "frf", "--segments", "4", "--set",
                        "materials.carbon_carbon.youngs_modulus=44.6e9", "--out", str(out)], capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    return str(out / "frf.uff")
