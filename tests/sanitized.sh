#!/usr/bin/env bash
# The whole test suite again under AddressSanitizer and UndefinedBehaviorSanitizer, in a
# second build directory (docs/reliability.md); any finding fails the run. Leaks that
# third-party libraries keep for the process's life are suppressed by library name
# (tests/sanitizers/lsan.supp).
set -euo pipefail
cd "$(dirname "$0")/.."
cmake -S . -B build-san -DMMVLAB_SANITIZE=ON -DMMVLAB_SANITIZED_READER_TEST=OFF >/dev/null
cmake --build build-san -j"$(nproc)"
export ASAN_OPTIONS="detect_leaks=1:strict_string_checks=1:detect_stack_use_after_return=1"
export LSAN_OPTIONS="suppressions=$PWD/tests/sanitizers/lsan.supp:print_suppressions=0"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
# The single-node Slurm run (cluster.*) is left to the plain suite: it drives the same
# sweep code as the sanitized sweep tests, through slurmctld and srun, and took 150 s of
# the 45-minute CI budget under the sanitizers.
ctest --test-dir build-san --output-on-failure -j"$(nproc)" --timeout 900 -E '^cluster\.'

