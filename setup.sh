#!/usr/bin/env bash
# Installs mmvlab's dependencies from Debian 12 packages.
# Idempotent: packages already present are skipped; apt-get runs only when something
# is missing. Needs root (or sudo) for the install step.
#
#   ./setup.sh          what building and running mmvlab needs (the README's first command)
#   ./setup.sh --test   that, plus what the test suite and the benchmarks add
#                       (GoogleTest, Google Benchmark, Octave, pytest, pip, Slurm, MuJoCo),
#                       and OpenBLAS's libraries unpacked (not installed) into
#                       /var/cache/mmvlab/openblas for CI's second arithmetic run
#                       (tests/second_arithmetic.sh)
set -euo pipefail

build_pkgs=(
  build-essential cmake pkg-config
  libsimbody-dev libeigen3-dev libsundials-dev
  libopencv-dev libpng-dev libosmesa6-dev libgl-dev
  libyaml-cpp-dev nlohmann-json3-dev libcli11-dev libmatio-dev libtbb-dev libspectra-dev liblapack-dev
  python3-dev pybind11-dev python3-numpy   # the Python module (python/): `import mmvlab`
)
test_pkgs=(
  libgtest-dev googletest libbenchmark-dev
  octave octave-control          # the test suite loads our .mat files into Octave's ss()
  python3 python3-numpy          # ... and reads every CSV back with Python's csv module and numpy
  python3-vtk9                   # ... and modes.vtp with VTK's own reader, as ParaView reads it
  chromium                       # ... and report.html in a real browser, headless (tests/readback/report_browser.sh)
  python3-pytest                 # the Python module's tests (python/tests)
  python3-pip python3-setuptools python3-wheel python3-venv   # ... and `pip install .` into a venv (tests/install/pip_test.sh)
  python3-pandas python3-matplotlib   # ... and docs/python.md's worked study, run by them
  slurmctld slurmd slurm-client munge   # a single-node Slurm runs the sharded sweep (tests/cluster/slurm_test.sh)
  libmujoco-dev                  # MuJoCo computes the article's modes beside mmvlab (bench/mujoco, mujoco.modes_agree_with_mmvlab)
)
want=("${build_pkgs[@]}")
case "${1:-}" in
  "") ;;
  --test) want+=("${test_pkgs[@]}") ;;
  *) echo "setup: unknown option '$1' (use no option, or --test for the test suite's packages too)" >&2; exit 64 ;;
esac

missing=()
for p in "${want[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

SUDO=""
if [[ $(id -u) -ne 0 ]]; then
  SUDO="sudo"
fi
need_root() {
  [[ -z $SUDO ]] || command -v sudo >/dev/null || { echo "setup: need root or sudo to $1" >&2; exit 1; }
}
export DEBIAN_FRONTEND=noninteractive
updated=0
if ((${#missing[@]} == 0)); then
  echo "setup: all ${#want[@]} packages present" >&2
else
  echo "setup: installing ${missing[*]}" >&2
  need_root "install: ${missing[*]}"
  $SUDO apt-get update -qq
  updated=1
  $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
  echo "setup: done" >&2
fi

# The second arithmetic environment (tests/second_arithmetic.sh): Debian's OpenBLAS
# package unpacked, not installed (installing it would make it every program's BLAS and
# LAPACK on this machine); the suite loads it through LD_LIBRARY_PATH.
openblas=/var/cache/mmvlab/openblas
if [[ ${1:-} == --test && ! -f $openblas/usr/lib/x86_64-linux-gnu/openblas-pthread/liblapack.so.3 ]]; then
  need_root "unpack OpenBLAS into $openblas"
  ((updated)) || $SUDO apt-get update -qq
  tmp=$(mktemp -d)
  (cd "$tmp" && chmod 755 . && $SUDO apt-get download -qq libopenblas0-pthread 2>/dev/null) ||
    { echo "setup: could not download libopenblas0-pthread" >&2; rm -rf "$tmp"; exit 1; }
  $SUDO mkdir -p "$openblas.new"
  $SUDO dpkg-deb -x "$tmp"/libopenblas0-pthread_*.deb "$openblas.new"
  $SUDO rm -rf "$openblas" "$tmp"
  $SUDO mv "$openblas.new" "$openblas"
  echo "setup: OpenBLAS unpacked into $openblas (the second arithmetic run's)" >&2
fi
