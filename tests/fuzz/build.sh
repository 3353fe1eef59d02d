#!/usr/bin/env bash
# Builds the fuzzers (libFuzzer, clang 14 from Debian: clang and
# libclang-rt-14-dev) in build-fuzz/: scene_reader_fuzzer, scene_modes_fuzzer, spec_fuzzer,
# uff_fuzzer, set_fuzzer and rundir_fuzzer.
set -euo pipefail
cd "$(dirname "$0")/../.."
CC=clang-14 CXX=clang++-14 cmake -S . -B build-fuzz -DMMVLAB_FUZZ=ON -DMMVLAB_BUILD_TESTS=OFF -DMMVLAB_BUILD_BENCH=OFF \
  -DMMVLAB_SANITIZED_READER_TEST=OFF >/dev/null
cmake --build build-fuzz -j"$(nproc)" --target scene_reader_fuzzer scene_modes_fuzzer spec_fuzzer uff_fuzzer set_fuzzer rundir_fuzzer
