#!/usr/bin/env bash
# Installs the Debian 12 packages Prism needs to build and test.
# Idempotent: does nothing when everything is present. Uses sudo when not root.
# Usage: install-deps.sh [--sanitizers]
set -euo pipefail

packages=(
  build-essential cmake ninja-build pkg-config
  libembree-dev libtbb-dev libopenexr-dev libpng-dev zlib1g-dev libstb-dev
  nlohmann-json3-dev libcli11-dev libfmt-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  libopencolorio-dev  # ACES oracle in tests; `--ocio-config` display path (issue 6)
  liblcms2-dev        # ICC oracle in tests: Little CMS reads our profiles (issue 6)
  libavif-dev         # AVIF HDR output (issue 6)
  libtinyobjloader-dev  # OBJ + MTL loader (issue 5)
  libtinygltf-dev     # glTF 2.0 loader (issue 5)
  libglfw3-dev        # viewer window (issue 7)
  libimgui-dev        # viewer UI; its GLFW/OpenGL3 backends' sources are compiled in (issue 7)
  libgl-dev           # viewer OpenGL (issue 7)
  xvfb xauth          # viewer GUI tests: virtual X server (issue 7)
  xdotool             # viewer GUI tests: synthetic input (issue 7)
  libgl1-mesa-dri     # viewer GUI tests: Mesa software OpenGL under Xvfb (issue 7)
  slurm-wlm munge     # farm self-test: a one-node Slurm cluster (scripts/slurm/, issue 49)
  python3             # farm self-test: compare-merge.py checks the merged image (issue 49)
)
# `--sanitizers`: what the sanitizer and fuzzing stages of ./scripts/test.sh need (issue 9):
# clang with its runtimes (ASan/UBSan/libFuzzer) and llvm-symbolizer for readable reports.
if [ "${1:-}" = --sanitizers ]; then
  packages+=(clang libclang-rt-14-dev llvm-14)
fi

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  exit 0
fi

echo "install-deps: installing ${missing[*]}"
sudo_cmd=()
if [ "$(id -u)" -ne 0 ]; then
  sudo_cmd=(sudo)
fi
export DEBIAN_FRONTEND=noninteractive
"${sudo_cmd[@]}" apt-get update -qq
"${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
