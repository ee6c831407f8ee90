#!/usr/bin/env bash
# A prism built with -DPRISM_VIEWER=OFF: `prism view` is one line saying so, exit 1,
# whatever it is given; `prism render` works. Usage: view_unavailable.sh PATH/TO/prism
set -u
prism="$1"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
for args in "view" "view cornell-box --frames 1"; do
  out=$("$prism" $args 2>&1)
  rc=$?
  [ "$rc" -eq 1 ] || { echo "FAIL: prism $args: exit $rc, expected 1: $out"; exit 1; }
  [ "$out" = "prism: error: this prism was built without the viewer (configure with -DPRISM_VIEWER=ON); use prism render" ] ||
    { echo "FAIL: prism $args: $out"; exit 1; }
done
"$prism" render cornell-box --spp 1 --width 8 --height 8 -o "$work/box.exr" >/dev/null 2>&1 ||
  { echo "FAIL: prism render in a headless build"; exit 1; }
echo "ok"
