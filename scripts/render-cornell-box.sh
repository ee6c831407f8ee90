#!/usr/bin/env bash
# Installs what is missing, builds Release and renders the built-in Cornell box to
# out/cornell-box.exr (linear, scene-referred) and out/cornell-box.png (sRGB).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
cmake --preset release >/dev/null
cmake --build --preset release --target prism_cli
mkdir -p out
./build/release/prism render cornell-box -o out/cornell-box.exr -o out/cornell-box.png "$@"
