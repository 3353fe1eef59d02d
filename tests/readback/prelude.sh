# Sourced by the readback scripts (readback.sh, vtk_readback.sh, report_browser.sh) and
# the figure harness (tests/figures): the binary (their first argument, else
# build/mmvlab), `here` (this directory), the repository as the working
# directory, a temporary directory removed at exit, and `run NAME VERB ARGS...`, which
# runs mmvlab with --out $tmp/NAME and shows its stderr if it fails.
set -euo pipefail
bin=$(realpath "${1:-build/mmvlab}")
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
cd "$here/../.."
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
run() { local name=$1; shift; "$bin" "$@" --out "$tmp/$name" >/dev/null 2>"$tmp/$name.err" || { cat "$tmp/$name.err"; exit 1; }; }
