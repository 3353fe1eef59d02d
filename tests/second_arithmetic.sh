#!/usr/bin/env bash
# The numerical suites again in a second arithmetic environment a user may have (issue 62):
# OpenBLAS's BLAS and LAPACK (Debian's libopenblas0-pthread, unpacked by `./setup.sh --test`
# into OPENBLAS_DIR, not installed: the machine's reference BLAS/LAPACK stay its default)
# in place of Debian's reference ones, through the dynamic loader's search path. A test
# that holds only by one library's rounding, or that expects LAPACK to fail on a crafted
# input, fails here on the developers' machine instead of on a user's. Which library
# answered is checked, not assumed: the loader must map OpenBLAS's liblapack.so.3.
#
#   tests/second_arithmetic.sh [BUILD_DIR]      (default build/, after the plain suite)
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
dir=${OPENBLAS_DIR:-/var/cache/mmvlab/openblas}/usr/lib/x86_64-linux-gnu/openblas-pthread
[[ -f $dir/liblapack.so.3 && -f $dir/libblas.so.3 ]] ||
  { echo "second_arithmetic: no OpenBLAS in $dir (./setup.sh --test unpacks it)" >&2; exit 1; }
export LD_LIBRARY_PATH=$dir${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}
# One thread each: ctest already runs one test per core.
export OPENBLAS_NUM_THREADS=1
map=$(LD_DEBUG=libs "$build/mmvlab" --version 2>&1 >/dev/null | grep -E "calling init: .*liblapack\.so\.3" | head -1)
[[ $map == *"$dir/liblapack.so.3"* ]] || { echo "second_arithmetic: mmvlab did not load OpenBLAS's LAPACK ($map)" >&2; exit 1; }
# The library and command-line suites whose numbers come through LAPACK (Simbody's
# factorizations, dstemr, the linear models) and the goldens of every verb's output.
ctest --test-dir "$build" --output-on-failure -j"$(nproc)" -L numerical
