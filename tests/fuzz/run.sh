#!/usr/bin/env bash
# Runs the two scene fuzzers for a recorded budget (docs/reliability.md, "Fuzzing"):
#   tests/fuzz/run.sh [READER_RUNS [MODES_RUNS]]     defaults 1000000 and 10000
# from the shipped scenes as seeds, in a work corpus under build-fuzz/corpus/. A breach
# of the contract aborts the fuzzer with the input saved as build-fuzz/crash-*; reduce
# it and add it to tests/fuzz/regressions.txt. Build first: tests/fuzz/build.sh.
set -euo pipefail
cd "$(dirname "$0")/../.."
reader_runs=${1:-1000000}
modes_runs=${2:-10000}
mkdir -p build-fuzz/corpus/reader build-fuzz/corpus/modes
export ASAN_OPTIONS="detect_leaks=1:allocator_may_return_null=1:intercept_tls_get_addr=0"  # tests/sanitized.sh says why
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
common=(-dict=tests/fuzz/scene.dict -max_len=16384 -rss_limit_mb=4096 -print_final_stats=1)
build-fuzz/scene_reader_fuzzer "${common[@]}" -runs="$reader_runs" -timeout=10 -artifact_prefix=build-fuzz/crash-reader- \
  build-fuzz/corpus/reader scenes > build-fuzz/reader.log 2>&1 &
reader=$!
build-fuzz/scene_modes_fuzzer "${common[@]}" -runs="$modes_runs" -timeout=60 -artifact_prefix=build-fuzz/crash-modes- \
  build-fuzz/corpus/modes scenes > build-fuzz/modes.log 2>&1 &
modes=$!
status=0
wait $reader || status=1
wait $modes || status=1
for t in reader modes; do
  echo "== $t"
  grep -E "^stat::|Done|ERROR|breach|SUMMARY" build-fuzz/$t.log | tail -12
done
exit $status
