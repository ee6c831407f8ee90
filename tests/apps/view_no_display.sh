#!/usr/bin/env bash
# `prism view` without a display: one line "prism: error: no display; ...", exit 1, no crash.
# Usage: view_no_display.sh PATH/TO/prism
set -u
prism="$1"
out=$(env -u DISPLAY -u WAYLAND_DISPLAY "$prism" view cornell-box 2>&1)
rc=$?
if [ "$rc" -ne 1 ]; then echo "FAIL: exit status $rc, expected 1; output: $out"; exit 1; fi
if [ "$out" != "prism: error: no display; use prism render or run under Xvfb" ]; then
  echo "FAIL: unexpected output: $out"; exit 1
fi
# A display that does not exist is the same case.
out=$(DISPLAY=:9999 "$prism" view cornell-box --frames 1 2>&1)
rc=$?
if [ "$rc" -ne 1 ] || [ "$(printf '%s\n' "$out" | wc -l)" -ne 1 ]; then
  echo "FAIL: DISPLAY=:9999 gave exit $rc: $out"; exit 1
fi
# Options are checked before the display: a bad --normal-mapping is a usage error.
out=$(env -u DISPLAY -u WAYLAND_DISPLAY "$prism" view cornell-box --normal-mapping bent 2>&1)
rc=$?
if [ "$rc" -ne 2 ] || [ "$out" != "prism: error: unknown --normal-mapping 'bent' (classic, microfacet)" ]; then
  echo "FAIL: --normal-mapping bent gave exit $rc: $out"; exit 1
fi
echo "ok"
