#!/usr/bin/env bash
# Installs what is missing, builds and runs the test suites (what CI runs, .ci/run):
#   release     Release build, every test but the labels slow and fuzz-smoke (the gui
#               tests start their own Xvfb; the slurm test, as root, a one-node Slurm
#               cluster: docs/farm-rendering.md);
#   asan        clang AddressSanitizer + UndefinedBehaviorSanitizer (LeakSanitizer on):
#               every unit and CLI test; the same build has the libFuzzer targets, and
#   fuzz-smoke  runs each of them for 30 s on its seed corpus;
#   tsan        ThreadSanitizer: the render, checkpoint, determinism and viewer render
#               worker tests (the test files the `tsan` configure preset builds).
# Any sanitizer report fails the run. Options and suppressions (third-party code only) are
# in the test presets and tests/sanitizers/; docs/reliability.md explains them.
# PRISM_SANITIZERS=0 runs the Release stage only (a quick local check, not what CI runs).
set -euo pipefail
cd "$(dirname "$0")/.."
sanitizers="${PRISM_SANITIZERS:-1}"
if [ "$sanitizers" = 1 ]; then
  bash scripts/install-deps.sh --sanitizers
else
  bash scripts/install-deps.sh
fi

stage() { echo "== test.sh: $1 ($(date -u +%H:%M:%S))"; }
stage "release"
cmake --preset release >/dev/null
cmake --build --preset release
ctest --preset release
[ "$sanitizers" = 1 ] || exit 0

stage "asan: build"
# The sanitizer builds run the Release build's (uninstrumented) Jakob–Hanika table generator:
# same tables, minutes less under TSan.
jh_generator="$PWD/build/release/src/prism/prism_generate_jakob_hanika_tables"
cmake --preset asan -DPRISM_JAKOB_HANIKA_GENERATOR="$jh_generator" >/dev/null
cmake --build --preset asan
stage "asan: tests"
ctest --preset asan
stage "fuzz-smoke"
ctest --preset fuzz-smoke
stage "tsan: build"
cmake --preset tsan -DPRISM_JAKOB_HANIKA_GENERATOR="$jh_generator" >/dev/null
cmake --build --preset tsan --target prism_tests prism_cli
stage "tsan: tests"
ctest --preset tsan
stage "done"
