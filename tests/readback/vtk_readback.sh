#!/usr/bin/env bash
# modes.vtp read back by VTK's own reader and compared with modes.json of the same run
# (tests/readback/read_vtk.py), on the default article, the spatial article and the
# damped table scene; sensors.vtp against channels.csv and placement.json. ctest runs it; by hand: tests/readback/vtk_readback.sh build/mmvlab
set -euo pipefail
bin=$(realpath "${1:-build/mmvlab}")
here=$(cd "$(dirname "$0")" && pwd)
cd "$here/../.."
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
run() { local name=$1; shift; "$bin" modes "$@" --no-error-estimate --out "$tmp/$name" >/dev/null 2>"$tmp/$name.err" || { cat "$tmp/$name.err"; exit 1; }; }
run planar
run spatial --set model=spatial --modes 16
run damped scenes/mmv-table.yaml --modes 6
"$bin" place-sensors --count 10 --out "$tmp/sensors" >/dev/null 2>"$tmp/sensors.err" || { cat "$tmp/sensors.err"; exit 1; }
"$bin" place-sensors scenes/mmv-slew.yaml --set model=spatial --segments 8 --triaxial --count 6 --keep-scene-sensors --out "$tmp/sensors3" >/dev/null 2>"$tmp/sensors3.err" \
  || { cat "$tmp/sensors3.err"; exit 1; }
/usr/bin/python3 "$here/read_vtk.py" "$tmp/planar" "$tmp/spatial" "$tmp/damped" "$tmp/sensors" "$tmp/sensors3"
# A run: render --history to a .pvd, its frames against the run's history.csv.
"$bin" simulate scenes/mmv-slew.yaml --segments 2 --duration 0.2 --sample-rate 250 --out "$tmp/run" >/dev/null 2>"$tmp/run.err" \
  || { cat "$tmp/run.err"; exit 1; }
"$bin" render --history "$tmp/run" --fps 50 --out "$tmp/run.pvd" >/dev/null 2>"$tmp/pvd.err" || { cat "$tmp/pvd.err"; exit 1; }
# 0.2 s at 50 frames/s: 11 frames, reported as one line, then the collection.
[[ "$(cat "$tmp/pvd.err")" == "mmvlab: wrote 11 frames (.vtp) in $tmp/run_frames"$'\n'"mmvlab: wrote $tmp/run.pvd" ]] \
  || { echo "render .pvd: expected one line for the 11 frames, then the .pvd; got:"; cat "$tmp/pvd.err"; exit 1; }
/usr/bin/python3 "$here/read_vtk.py" --run "$tmp/run.pvd" "$tmp/run"
