"""docs/python.md's worked study runs as written, and its numbers are the CLI's."""
import json
import os
import subprocess
import sys

import pandas as pd

HERE = os.path.dirname(os.path.abspath(__file__))
EXAMPLE = os.path.join(HERE, "..", "examples", "sizing_study.py")


def test_the_sizing_study_writes_its_table_and_figure_with_the_cli_s_numbers(tmp_path):
    r = subprocess.run([sys.executable, EXAMPLE, str(tmp_path), "3"], capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    table = pd.read_csv(tmp_path / "sizing.csv")
    assert list(table["link2_depth_mm"]) == [8.0, 14.0, 20.0]
    assert (tmp_path / "sizing.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    cli = subprocess.run([os.environ["MMVLAB_BINARY"], "modes", "--json", "--segments", "8", "--modes", "4",
                          "--no-error-estimate", "--set", "sections.link2_bar.h=0.014"], capture_output=True, text=True)
    assert cli.returncode == 0, cli.stderr
    modes = json.loads(cli.stdout)["modes"]
    row = table[table["link2_depth_mm"] == 14.0].iloc[0]
    for k, m in enumerate(modes):
        assert abs(row[f"f{k + 1}_hz"] / m["frequency_hz"] - 1) < 1e-12  # the CSV's 16 digits
    joints = {j["name"]: j["torque_n_m"] for j in json.loads(cli.stdout)["equilibrium"]["joints"]}
    assert abs(row["joint2_torque_n_m"] / joints["joint2"] - 1) < 1e-12
