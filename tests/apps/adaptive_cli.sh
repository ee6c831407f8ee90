#!/usr/bin/env bash
# `prism render --noise-threshold` (adaptive sampling) and `--aov sample-count` from the
# shell: the EXR carries the threshold and minimum in its metadata, the variance layer the
# rule reads and the sampleCount layer; the PNG's text says the same; a checkpoint made
# with another threshold is refused; bad values and --sample-range are one-line usage
# errors (exit 2) that write nothing.
# Usage: adaptive_cli.sh PATH_TO_PRISM
set -u
prism="$1"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
# has_channel FILE NAME: the EXR header's channel list holds NAME (names are stored
# NUL-terminated, so splitting the file at NULs puts each on a line of its own).
has_channel() { LC_ALL=C tr '\0' '\n' <"$1" | LC_ALL=C grep -aqx -- "$2"; }
# exr_attribute FILE NAME TYPE OD_FORMAT BYTES: the value of a scalar header attribute,
# stored as NAME\0 TYPE\0 size (4 bytes) value (OpenEXR file layout, "Header Attributes").
exr_attribute() {
  local offset
  offset=$(LC_ALL=C grep -obUaP -- "$2\\x00$3\\x00" "$1" | head -1 | cut -d: -f1)
  [ -n "$offset" ] || return 1
  od -An -t "$4" -j $((offset + ${#2} + ${#3} + 2 + 4)) -N "$5" "$1" | head -1 | tr -d ' '
}

small=(cornell-box --width 24 --height 16 --seed 3 --spp 32)

"$prism" render "${small[@]}" --noise-threshold 0.05 --adaptive-min-samples 8 --aov sample-count \
  -o "$work/a.exr" -o "$work/a.png" >"$work/out" 2>&1 || fail "render --noise-threshold failed: $(cat "$work/out")"
for ch in R G B sampleCount variance.R variance.G variance.B; do
  has_channel "$work/a.exr" "$ch" || fail "adaptive render: no channel $ch"
done
threshold=$(exr_attribute "$work/a.exr" prism:noiseThreshold double f8 8)
[ "$threshold" = "0.05" ] || fail "prism:noiseThreshold is '$threshold', expected 0.05"
min_samples=$(exr_attribute "$work/a.exr" prism:adaptiveMinSamples int d4 4)
[ "$min_samples" = "8" ] || fail "prism:adaptiveMinSamples is '$min_samples', expected 8"
# tEXt: keyword NUL text (PNG 11.3.4.3); the chunk's length and type precede the keyword.
LC_ALL=C tr '\0' '\n' <"$work/a.png" | LC_ALL=C grep -aA1 "prism:noiseThreshold$" | LC_ALL=C grep -aq "^0\.05" ||
  fail "the PNG's text has no prism:noiseThreshold 0.05"

# Without the option: no threshold in the file, no sampleCount unless asked for.
"$prism" render "${small[@]}" -o "$work/u.exr" >"$work/out" 2>&1 || fail "uniform render failed: $(cat "$work/out")"
LC_ALL=C grep -aq "prism:noiseThreshold" "$work/u.exr" && fail "a uniform render names a noise threshold"
has_channel "$work/u.exr" sampleCount && fail "a uniform render without --aov sample-count has the layer"
"$prism" render "${small[@]}" --aov sample-count -o "$work/c.exr" >"$work/out" 2>&1 || fail "--aov sample-count failed"
has_channel "$work/c.exr" sampleCount || fail "--aov sample-count: no sampleCount channel"

# A checkpoint remembers the threshold: resuming with another one is refused.
"$prism" render "${small[@]}" --noise-threshold 0.05 --checkpoint "$work/a.ckp" -o "$work/k.exr" >"$work/out" 2>&1 ||
  fail "render --checkpoint failed: $(cat "$work/out")"
"$prism" render "${small[@]}" --noise-threshold 0.1 --resume "$work/a.ckp" -o "$work/r.exr" >"$work/out" 2>"$work/err"
rc=$?
[ "$rc" -eq 2 ] || fail "resume with another threshold: exit $rc, expected 2"
grep -q "^prism: error: checkpoint .* different scene or settings" "$work/err" || fail "resume: $(cat "$work/err")"

# Bad values and the farm split: one line, exit 2, nothing written.
for args in "--noise-threshold -0.1" "--noise-threshold 0.05 --adaptive-min-samples 1"; do
  # shellcheck disable=SC2086
  "$prism" render "${small[@]}" $args -o "$work/bad.exr" >"$work/out" 2>"$work/err"
  rc=$?
  [ "$rc" -eq 2 ] || fail "$args: exit $rc, expected 2"
  [ "$(wc -l <"$work/err")" -eq 1 ] || fail "$args: stderr is not one line: $(cat "$work/err")"
  grep -q "^prism: error: --\(noise-threshold\|adaptive-min-samples\) must be" "$work/err" || fail "$args: $(cat "$work/err")"
  [ ! -e "$work/bad.exr" ] || fail "$args wrote an output"
done
"$prism" render cornell-box --width 24 --height 16 --sample-range 0:8 --noise-threshold 0.05 -o "$work/part.exr" \
  >"$work/out" 2>"$work/err"
rc=$?
[ "$rc" -eq 2 ] || fail "--noise-threshold --sample-range: exit $rc, expected 2"
grep -q "^prism: error: --noise-threshold cannot be combined with --sample-range" "$work/err" ||
  fail "--sample-range: $(cat "$work/err")"
[ ! -e "$work/part.exr" ] || fail "--noise-threshold --sample-range wrote an output"

echo "$failures failure(s)"
[ "$failures" -eq 0 ]
