#!/usr/bin/env bash
# `prism denoise` and `prism render --denoise` from the shell: good input gives a denoised
# EXR with the noisy beauty and the guides as layers; input without the guides gives one
# error line naming the missing layers, exit 1, and no output file.
# Usage: denoise_cli.sh PATH_TO_PRISM
set -u
prism="$1"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
# has_channel FILE NAME: the EXR header's channel list holds NAME. Each name is stored
# NUL-terminated and followed by 16 bytes that end in NUL (pixel type, linearity, sampling),
# so splitting the file at NULs puts every channel name on a line of its own.
has_channel() { LC_ALL=C tr '\0' '\n' <"$1" | LC_ALL=C grep -aqx -- "$2"; }

small=(cornell-box --width 24 --height 16 --seed 3 --spp 8)

"$prism" render "${small[@]}" --denoise -o "$work/d.exr" -o "$work/d.png" >"$work/out" 2>&1 ||
  fail "render --denoise failed: $(cat "$work/out")"
for ch in R G B noisy.R noisy.G noisy.B albedo.R N.x Z variance.B; do
  has_channel "$work/d.exr" "$ch" || fail "render --denoise: no channel $ch"
done
[ -s "$work/d.png" ] || fail "render --denoise wrote no PNG"

"$prism" render "${small[@]}" --aov albedo,normal,depth,variance -o "$work/n.exr" >"$work/out" 2>&1 ||
  fail "render --aov failed: $(cat "$work/out")"
"$prism" denoise "$work/n.exr" -o "$work/nd.exr" >"$work/out" 2>&1 || fail "denoise failed: $(cat "$work/out")"
has_channel "$work/nd.exr" noisy.G || fail "denoise: no noisy.G layer"
grep -q "^prism: denoised " "$work/out" || fail "denoise: no summary line: $(cat "$work/out")"

"$prism" render "${small[@]}" --aov albedo -o "$work/partial.exr" >"$work/out" 2>&1 || fail "render --aov albedo failed"
"$prism" denoise "$work/partial.exr" -o "$work/bad.exr" >"$work/out" 2>"$work/err"
rc=$?
[ "$rc" -eq 1 ] || fail "denoise without guides: exit $rc, expected 1"
[ "$(wc -l <"$work/err")" -eq 1 ] || fail "denoise without guides: stderr is not one line: $(cat "$work/err")"
grep -q "^prism: error: .*normal (.*depth (.*variance (" "$work/err" || fail "missing layers not named: $(cat "$work/err")"
[ ! -e "$work/bad.exr" ] || fail "denoise without guides wrote an output"

# A farm part must stay noisy (prism merge adds the parts): --denoise with --sample-range is
# a usage error.
"$prism" render cornell-box --width 24 --height 16 --sample-range 0:2 --denoise -o "$work/part.exr" >"$work/out" 2>"$work/err"
rc=$?
[ "$rc" -eq 2 ] || fail "--denoise --sample-range: exit $rc, expected 2"
grep -q "^prism: error: --denoise cannot be combined with --sample-range" "$work/err" || fail "no usage error: $(cat "$work/err")"
[ ! -e "$work/part.exr" ] || fail "--denoise --sample-range wrote an output"

echo "$failures failure(s)"
[ "$failures" -eq 0 ]
