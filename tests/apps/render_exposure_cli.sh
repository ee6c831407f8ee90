#!/usr/bin/env bash
# `prism render`'s exposure (docs/display-pipeline.md "Exposure metering"): without an
# exposure option it meters the film, prints the EV100 in its summary line and writes it to
# the EXR and PNG; `--ev100` with that value gives the same PNG byte for byte; an explicit
# EV100 is used as given. Usage: render_exposure_cli.sh PATH_TO_PRISM
set -u
prism="$1"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }

args=(cornell-box --width 64 --height 64 --spp 4 --threads 2)
"$prism" render "${args[@]}" -o "$work/a.exr" -o "$work/a.png" >"$work/out_a" 2>"$work/err_a" ||
  fail "metered render failed: $(cat "$work/err_a")"
ev=$(grep -Eo 'EV100 -?[0-9.]+ metered' "$work/out_a" | awk '{print $2}')
[ -n "$ev" ] || fail "summary line names no metered EV100: $(cat "$work/out_a")"
grep -aq "prism:ev100" "$work/a.exr" || fail "the EXR has no prism:ev100 attribute"
grep -aq "prism:ev100.$ev" "$work/a.png" || fail "the PNG has no prism:ev100 text chunk of $ev"

"$prism" render "${args[@]}" --ev100 "$ev" -o "$work/b.png" >"$work/out_b" 2>"$work/err_b" ||
  fail "render --ev100 $ev failed: $(cat "$work/err_b")"
grep -q "EV100 $ev)" "$work/out_b" || fail "an explicit EV100 is not reported as given: $(cat "$work/out_b")"
cmp -s "$work/a.png" "$work/b.png" || fail "--ev100 $ev does not repeat the metered picture"

# A different exposure gives a different picture (the check above can fail).
"$prism" render "${args[@]}" --ev100 5 -o "$work/c.png" >/dev/null 2>&1 || fail "render --ev100 5 failed"
cmp -s "$work/a.png" "$work/c.png" && fail "--ev100 5 gives the metered picture"

[ "$failures" -eq 0 ] && echo "ok: metered EV100 $ev, repeated exactly with --ev100"
exit $((failures > 0))
