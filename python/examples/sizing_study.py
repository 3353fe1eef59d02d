#!/usr/bin/env python3
"""A sizing study from Python (docs/python.md): link 2's bar depth against the article's
first modes and the torque joint 2 holds, as a pandas table and a matplotlib figure.

    PYTHONPATH=build/python python3 python/examples/sizing_study.py OUT_DIR [POINTS]
"""
import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")  # no display: write the figure to a file
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import pandas as pd  # noqa: E402

import mmvlab  # noqa: E402


def study(depths_m, segments=8, modes=4):
    rows = []
    for h in depths_m:
        scene = mmvlab.load_scene(set={"sections.link2_bar.h": float(h)})
        m = mmvlab.modes(scene, segments=segments, modes=modes, error_estimate=False)
        torque = {j["name"]: j["torque_n_m"] for j in m.json["equilibrium"]["joints"]}
        row = {"link2_depth_mm": h * 1e3, "joint2_torque_n_m": torque["joint2"],
               "moving_mass_kg": m.json["model"]["moving_mass_kg"]}
        row.update({f"f{k + 1}_hz": f for k, f in enumerate(m.frequencies_hz)})
        rows.append(row)
    return pd.DataFrame(rows)


def main(out_dir, points=7):
    out = Path(out_dir)
    out.mkdir(parents=True, exist_ok=True)
    table = study(np.linspace(0.008, 0.020, points))
    table.to_csv(out / "sizing.csv", index=False)
    fig, ax = plt.subplots(figsize=(7, 4.5))
    for col in [c for c in table.columns if c.endswith("_hz")]:
        ax.plot(table["link2_depth_mm"], table[col], marker="o", label=col.replace("_hz", ""))
    ax.set_xlabel("link 2 bar depth h (mm)")
    ax.set_ylabel("system mode frequency (Hz)")
    ax.set_title("MMV article: link 2 depth against the first modes (8 segments per link)")
    ax.grid(True, alpha=0.3)
    ax.legend()
    fig.tight_layout()
    fig.savefig(out / "sizing.png", dpi=110)
    print(table.to_string(index=False))


if __name__ == "__main__":
    main(sys.argv[1], int(sys.argv[2]) if len(sys.argv) > 2 else 7)
