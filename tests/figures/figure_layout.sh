#!/usr/bin/env bash
# The figure harness (issue 36): every figure of every shipped scene drawn with its layout
# logged (MMVLAB_FIGURE_LAYOUT, renders/layout.hpp), then judged by check_layout.py: no
# text box overlapping another or leaving the canvas, every legend entry drawn, visible
# and in a colour of its own. Coarse meshes and short runs: the layout, not the physics.
# ctest runs it; by hand: tests/figures/figure_layout.sh build/mmvlab
source "$(dirname "$0")/../readback/prelude.sh"  # bin, the repository as cwd, tmp
here=$(pwd)/tests/figures
fig() {  # fig NAME ARGS...: mmvlab ARGS with the layout logged to NAME.jsonl
  local name=$1; shift
  MMVLAB_FIGURE_LAYOUT="$tmp/$name.jsonl" "$bin" "$@" >/dev/null 2>"$tmp/$name.err" || { echo "$name: $*"; cat "$tmp/$name.err"; exit 1; }
}
for path in scenes/*.yaml; do
  s=$(basename "$path" .yaml)
  if [[ $s == hamsas ]]; then
    fig "$s-frf" frf "$path" --out "$tmp/$s-frf"
    fig "$s-frf-vary" frf "$path" --vary counterweight_mass=0,2,3.37,5,7 --out "$tmp/$s-frf-vary"
    fig "$s-place" place-sensors "$path" --modes 1-6 --count 6 --out "$tmp/$s-place"
    fig "$s-render" render "$path" --out "$tmp/$s.png"
    fig "$s-render-modes" render "$path" --mode 1-6 --out "$tmp/$s-modes.png"
    continue
  fi
  fig "$s-render" render "$path" --segments 4 --out "$tmp/$s.png"
  fig "$s-render-modes" render "$path" --segments 4 --mode 1-4 --out "$tmp/$s-modes.png"
  fig "$s-converge" converge "$path" --max-segments 8 --out "$tmp/$s-converge"
  fig "$s-frf" frf "$path" --segments 4 --out "$tmp/$s-frf"
  fig "$s-place" place-sensors "$path" --segments 4 --count 6 --modes 1-4 --out "$tmp/$s-place"
  fig "$s-simulate" simulate "$path" --segments 2 --duration 0.5 --out "$tmp/$s-simulate"
done
fig mmv-compare compare --segments 4 --out "$tmp/mmv-compare"
fig mmv-sweep-config sweep-config --segments 4 --grid joint1:-90:90:30 --modes 6 --out "$tmp/mmv-sweep-config"
fig mmv-slew-trade trade scenes/mmv-slew.yaml --segments 2 --duration 0.3 --out "$tmp/mmv-slew-trade"
fig mmv-slew-history render --history "$tmp/mmv-slew-simulate" --at 0.25 --out "$tmp/mmv-slew-history.png"
fig mmv-slew-history-traces render --history "$tmp/mmv-slew-simulate" --at 0.25 \
  --traces enc1,joint1_torque_n_m,acc_link3a_tip,table_x_m,gyro_link1_tip --out "$tmp/mmv-slew-history-traces.png"
fig link3-sweep sweep sweeps/link3-sizing.yaml --out "$tmp/link3-sweep"
fig mmv-table-correlate correlate scenes/mmv-table.yaml --measured docs/figures/correlate/measured.uff --modes 12 --out "$tmp/mmv-table-correlate"
fig mmv-table-update update scenes/mmv-table.yaml --measured docs/figures/correlate/measured.uff --modes 6 \
  --params joints.joint2.torquer.mass:4:5 --out "$tmp/mmv-table-update"
python3 "$here/check_layout.py" "$tmp"/*.jsonl
