#!/usr/bin/env bash
# Installs what is missing, builds Release with tests and runs the test suite
# (everything but the labels slow and fuzz-smoke; the gui tests start their own Xvfb).
#
# PRISM_SANITIZERS=1 then also builds and runs the sanitizer presets (issue 9):
#   asan  AddressSanitizer + UndefinedBehaviorSanitizer, every unit and CLI test;
#   tsan  ThreadSanitizer, the render/checkpoint/integrator/determinism tests (the `tsan`
#         test preset's name filter).
# Options and suppressions (third-party only) are in the test presets and
# tests/sanitizers/. Off by default for now: two more full builds do not yet fit the CI
# time budget on a 2-core machine and have not had a verified clean run (see
# docs/reliability.md, "Sanitizers"); set PRISM_SANITIZERS=1 to run them.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
cmake --preset release >/dev/null
cmake --build --preset release
ctest --preset release

if [ "${PRISM_SANITIZERS:-0}" = 1 ]; then
  cmake --preset asan >/dev/null
  cmake --build --preset asan
  ctest --preset asan
  cmake --preset tsan >/dev/null
  # The build runs the (instrumented) Jakob–Hanika table generator: same suppressions.
  TSAN_OPTIONS="suppressions=$PWD/tests/sanitizers/tsan.supp" \
    cmake --build --preset tsan --target prism_tests prism_cli
  ctest --preset tsan
fi
