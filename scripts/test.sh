#!/usr/bin/env bash
# Installs what is missing, builds Release with tests and runs the test suite
# (everything but the labels slow, gui and fuzz-smoke).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
cmake --preset release >/dev/null
cmake --build --preset release
ctest --preset release
