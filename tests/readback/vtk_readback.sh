#!/usr/bin/env bash
# modes.vtp read back by VTK's own reader and compared with modes.json of the same run
# (tests/readback/read_vtk.py), on the default article, the spatial article, the
# damped table scene and HAM-SAS; sensors.vtp against channels.csv and placement.json; a run's .pvd
# against its history.csv. ctest runs it; by hand: tests/readback/vtk_readback.sh build/mmvlab
source "$(dirname "$0")/prelude.sh"
run planar modes --no-error-estimate
run spatial modes --no-error-estimate --set model=spatial --modes 16
run damped modes --no-error-estimate scenes/mmv-table.yaml --modes 6
run hamsas modes scenes/hamsas.yaml --modes 12
run sensors place-sensors --count 10
run sensors3 place-sensors scenes/mmv-slew.yaml --set model=spatial --segments 8 --triaxial --count 6 --keep-scene-sensors
/usr/bin/python3 "$here/read_vtk.py" "$tmp/planar" "$tmp/spatial" "$tmp/damped" "$tmp/hamsas" "$tmp/sensors" "$tmp/sensors3"
# A run: render --history to a .pvd, its frames against the run's history.csv.
run run simulate scenes/mmv-slew.yaml --segments 2 --duration 0.2 --sample-rate 250
"$bin" render --history "$tmp/run" --fps 50 --out "$tmp/run.pvd" >/dev/null 2>"$tmp/pvd.err" || { cat "$tmp/pvd.err"; exit 1; }
# 0.2 s at 50 frames/s: 11 frames, reported as one line, then the collection.
[[ "$(cat "$tmp/pvd.err")" == "mmvlab: wrote 11 frames (.vtp) in $tmp/run_frames"$'\n'"mmvlab: wrote $tmp/run.pvd" ]] \
  || { echo "render .pvd: expected one line for the 11 frames, then the .pvd; got:"; cat "$tmp/pvd.err"; exit 1; }
/usr/bin/python3 "$here/read_vtk.py" --run "$tmp/run.pvd" "$tmp/run"
# A HAM-SAS run: the bodies' boxes, each box's centre against history.csv's mass centre.
run hrun simulate scenes/hamsas.yaml --duration 0.2
"$bin" render --history "$tmp/hrun" --fps 50 --out "$tmp/hrun.pvd" >/dev/null 2>"$tmp/hpvd.err" || { cat "$tmp/hpvd.err"; exit 1; }
/usr/bin/python3 "$here/read_vtk.py" --run "$tmp/hrun.pvd" "$tmp/hrun"
