#!/usr/bin/env bash
# Issue 47's exposure goal on every scene: the median displayed luminance of the first render
# and of the viewer's first frame in [5 %, 30 %] of SDR white, and render and view within
# 0.3 EV (bench/tools/first_picture_exposure.cpp). Prints one markdown table per lighting.
#   scripts/first-picture-exposure.sh [BUILD_DIR] [SPP]   (default build/release, 64 spp)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build/release}
spp=${2:-64}
tool=${PRISM_FPE_TOOL:-$build/bench/prism_first_picture_exposure}
shared=$root/../shared/scenes
status=0
"$tool" --spp "$spp" cornell-box cornell-box-measured "$root"/data/scenes/material-test.json dispersion-prism \
  "$root"/bench/scenes/*.json ||
  status=1
for env in "$shared"/envmaps/*.hdr; do
  models=()
  for m in "$shared"/gltf/*/glTF/*.gltf; do models+=("$m"); done
  "$tool" --spp "$spp" --environment "$env" "${models[@]}" || status=1
done
exit $status
