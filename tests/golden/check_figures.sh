#!/usr/bin/env bash
# Regenerates the committed figure data in docs/figures with the commands the docs
# give, into a temporary directory, and compares every CSV, Markdown and UFF file with
# the committed one as the golden tests compare (tests/golden/same_numbers.py: words
# exact, numbers to 1e-9 relative or a unit in the last printed digit, UFF dates
# masked). Exit 0 when all match, 1 with the first difference otherwise.
# ctest runs it (about 3 s); by hand: tests/golden/check_figures.sh build/mmvlab
# The trade studies (docs/figures/trade-slew, hamsas-trade) record wall times and take
# minutes, so they are not regenerated here.
set -euo pipefail
bin=$(realpath "${1:-build/mmvlab}")
cd "$(dirname "$0")/../.."
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
run() { local name=$1; shift; "$bin" "$@" --out "$tmp/$name" >/dev/null 2>&1; }
run compare-default compare
run frf-table frf scenes/mmv-table.yaml --input table_x --output link3a.tip:x --rom-modes 10
run hamsas frf scenes/hamsas.yaml --vary counterweight_mass=0,2,3.37,5,7
run sweep-joint1 sweep-config --grid joint1:-90:90:15 --modes 6
run sweep-closed-joint2 sweep-config scenes/mmv-closed.yaml --grid joint2:-45:45:15 --modes 6
# correlate: its report (stdout) and files against the committed measured set, which is an
# input (written by an older frf, real mode shapes), as is link2-stiff.yaml.
run correlate correlate scenes/mmv-table.yaml --measured docs/figures/correlate/measured.uff --modes 12
"$bin" correlate scenes/mmv-table.yaml --measured docs/figures/correlate/measured.uff --modes 12 \
  >"$tmp/correlate/correlate.txt" 2>&1
cp docs/figures/correlate/measured.uff docs/figures/correlate/link2-stiff.yaml "$tmp/correlate/"
status=0
for dir in compare-default frf-table hamsas sweep-joint1 sweep-closed-joint2 correlate; do
  for f in docs/figures/$dir/*; do
    case "$f" in *.png) continue ;; esac
    new="$tmp/$dir/$(basename "$f")"
    if [[ ! -f "$new" ]]; then echo "missing: $f"; status=1; continue; fi
    if ! why=$(python3 tests/golden/same_numbers.py "$f" "$new"); then
      echo "differs: $f: $why"; status=1
    fi
  done
done
[[ $status -eq 0 ]] && echo "docs/figures: every CSV, Markdown and UFF file reproduced (words exact, numbers to 1e-9)"
exit $status
