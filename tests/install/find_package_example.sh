#!/usr/bin/env bash
# `cmake --install` of this build into a scratch prefix, then a program outside the source
# tree (examples/render_cornell_box) configured against that prefix with find_package(Prism),
# built, and run: it renders the Cornell box through the C++ API and writes an EXR, which
# the installed `prism` reads back.
# Usage: find_package_example.sh BUILD_DIR EXAMPLE_DIR CXX_COMPILER MAKE_PROGRAM
set -euo pipefail
build="$1" example="$2" cxx="$3" make_program="$4"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*"; exit 1; }

cmake --install "$build" --prefix "$work/prefix" >"$work/install.log" || { cat "$work/install.log"; fail "cmake --install"; }
for f in bin/prism lib/libprism.a include/prism/render/renderer.h include/prism/core/version.h \
         lib/cmake/Prism/PrismConfig.cmake lib/cmake/Prism/PrismConfigVersion.cmake; do
  [ -e "$work/prefix/$f" ] || fail "the install lacks $f"
done
[ ! -e "$work/prefix/include/prism/viewer" ] || fail "the viewer's headers were installed"

# The example sees only the prefix: no source tree, no build tree on its include path.
cmake -S "$example" -B "$work/example" -G Ninja -DCMAKE_MAKE_PROGRAM="$make_program" \
  -DCMAKE_CXX_COMPILER="$cxx" -DCMAKE_PREFIX_PATH="$work/prefix" >"$work/configure.log" 2>&1 ||
  { cat "$work/configure.log"; fail "configuring the example against the installed package"; }
cmake --build "$work/example" >"$work/build.log" 2>&1 || { cat "$work/build.log"; fail "building the example"; }
! grep -q -- "-I$(cd "$(dirname "$0")/../.." && pwd)/src" "$work/build.log" "$work/example/build.ninja" ||
  fail "the example was compiled against the source tree"

out=$("$work/example/render_cornell_box" "$work/cornell.exr" 16 2) || fail "the example failed: $out"
echo "$out"
[ "$(head -c 4 "$work/cornell.exr" | od -An -tx1 | tr -d ' ')" = "762f3101" ] || fail "no OpenEXR written"
# The box is lit: every mean channel of the image is positive.
awk '{ if (!($(NF-2) > 0 && $(NF-1) > 0 && $NF > 0)) exit 1 }' <<<"$out" || fail "the render is black: $out"
# The installed command line reads it back.
"$work/prefix/bin/prism" tonemap "$work/cornell.exr" -o "$work/cornell.png" >/dev/null ||
  fail "the installed prism cannot read the example's EXR"
[ -s "$work/cornell.png" ] || fail "prism tonemap wrote nothing"
echo "install: find_package(Prism) example built and ran"
