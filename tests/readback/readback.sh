#!/usr/bin/env bash
# Every CSV and JSON file that mmvlab writes, read back as users read them: Python's csv
# module, numpy and json (tests/readback/read_outputs.py), Octave's csvread and MATLAB's
# variable-name rule (tests/readback/read_csv.m). (The .mat files are loaded into
# Octave's ss() by tests/sim/io/mat_file_test.cpp, the UFF files read back by
# tests/sim/io/uff_test.cpp.) The outputs come from the commands a review uses, run
# small. ctest runs it; by hand: tests/readback/readback.sh build/mmvlab
source "$(dirname "$0")/prelude.sh"
run modes modes
run converge converge --max-segments 4
run compare compare
run sweep-config sweep-config --grid joint1:-30:30:30 --modes 3
run frf frf scenes/mmv-table.yaml --input table_x --points 40
run frf-hamsas frf scenes/hamsas.yaml --points 20
run simulate simulate scenes/mmv-slew.yaml --segments 2 --duration 0.2 --sample-rate 250
run trade trade scenes/mmv-slew.yaml --segments 2 --duration 0.1 --integrators cpodes --accuracies 1e-3 --segment-ladder 1
run place-sensors place-sensors --count 8
run correlate correlate scenes/mmv-table.yaml --measured "$tmp/frf/frf.uff" --modes 6
run update update scenes/mmv-table.yaml --segments 4 --measured "$tmp/frf/frf.uff" --modes 6 --params joints.joint2.torquer.mass:4:5
printf 'scene: %s/scenes/mmv.yaml\nparameters:\n  - {key: links.link2.length, values: [1.4, 1.6]}\noutputs: [frequencies, mass, check, "json:modes/modes/0/effective_mass_x_kg"]\nmodes: 2\n' "$PWD" > "$tmp/spec.yaml"
"$bin" sweep "$tmp/spec.yaml" --out "$tmp/sweep" >/dev/null 2>&1
run modes-damped modes scenes/mmv-table.yaml --modes 6
"$bin" sweep-merge "$tmp/sweep" --out "$tmp/merged" --json > "$tmp/merged.json"
/usr/bin/python3 "$here/read_outputs.py" "$tmp"
mapfile -t files < <(find "$tmp" -name '*.csv' ! -name journal.csv | sort)
# (Octave 7 prints "error: ignoring const execution_exception& while preparing to exit"
# after any script run with arguments; it does not change the exit status.)
octave --no-gui --no-window-system --quiet --norc "$here/read_csv.m" "${files[@]}" \
  2> >(grep -v "ignoring const execution_exception" >&2)
