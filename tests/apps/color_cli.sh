#!/usr/bin/env bash
# `prism color`: output values and formats, and exit status 2 with a one-line error on bad
# input. Usage: color_cli.sh PATH_TO_PRISM. Exits non-zero on the first failure.
set -u
prism="$1"
failures=0

fail() { echo "FAIL: $*" >&2; failures=$((failures + 1)); }

# expect_numbers "TOLERANCE" "EXPECTED NUMBERS" -- command...
# Output is %.9g, i.e. 9 significant digits: every tolerance below is a few units of the
# 9th digit of the value compared, or half a unit of the last digit of a published value.
expect_numbers() {
  local tol="$1" expected="$2"
  shift 3
  local out
  if ! out=$("$prism" "$@" 2>&1); then fail "$* exited non-zero: $out"; return; fi
  if ! awk -v tol="$tol" -v want="$expected" -v got="$(echo $out)" 'BEGIN {
        ne = split(want, e, " "); ng = split(got, g, " ");
        if (ne != ng) exit 1;
        for (i = 1; i <= ne; ++i) { d = e[i] - g[i]; if (d < 0) d = -d; if (d > tol) exit 1; }
        exit 0 }'; then
    fail "$*: expected '$expected' (±$tol), got '$out'"
  fi
}

# expect_usage_error command...: exit status 2 and exactly one line on stderr, no stdout.
expect_usage_error() {
  local out err rc
  out=$("$prism" "$@" 2>/tmp/prism_color_cli_err.$$); rc=$?
  err=$(cat /tmp/prism_color_cli_err.$$); rm -f /tmp/prism_color_cli_err.$$
  if [ "$rc" -ne 2 ]; then fail "$* exited $rc, expected 2"; fi
  if [ -n "$out" ]; then fail "$* printed to stdout: $out"; fi
  if [ "$(printf '%s\n' "$err" | wc -l)" -ne 1 ] || [[ "$err" != "prism: error: "* ]]; then
    fail "$* stderr is not one 'prism: error:' line: $err"
  fi
}

# Conversions. ACES white is RGB (1,1,1) in ACEScg and must be sRGB white after Bradford.
expect_numbers 5e-9 "1 1 1" -- color convert --from acescg --to srgb 1 1 1
# sRGB red in XYZ: first column of the sRGB matrix (CSS Color 4 exact rationals
# 506752/1228815, 87098/409605, 7918/409605).
expect_numbers 5e-10 "0.412390799 0.212639006 0.0193308187" -- color convert --from sRGB --to xyz 1 0 0
# Negative components pass through, written directly.
expect_numbers 5e-9 "-0.5 0.25 1" -- color convert --from rec2020 --to bt2020 -0.5 0.25 1
# User primaries equal to sRGB's give sRGB's matrix.
expect_numbers 5e-10 "0.412390799 0.212639006 0.0193308187" -- \
  color convert --from xy:0.64,0.33,0.3,0.6,0.15,0.06,0.3127,0.329 --to xyz 1 0 0

# Matrix: 3 lines × 3 numbers. AP1 → AP0 from S-2014-004 (10 decimals).
out=$("$prism" color matrix --from acescg --to aces2065-1)
[ "$(echo "$out" | wc -l)" -eq 3 ] || fail "matrix printed $(echo "$out" | wc -l) lines"
[ "$(echo "$out" | awk '{ print NF }' | sort -u)" = "3" ] || fail "matrix rows must have 3 fields: $out"
expect_numbers 5e-9 "0.6954522414 0.1406786965 0.1638690622 0.0447945634 0.8596711185 0.0955343182
  -0.0055258826 0.0040252103 1.0015006723" -- color matrix --from acescg --to aces2065-1
# Same space: identity (off-diagonal rounding residue ~1e-17).
expect_numbers 5e-9 "1 0 0 0 1 0 0 0 1" -- color matrix --from srgb --to srgb --cat cat02

# Transfer functions (ST 2084: PQ(100) ≈ 0.508078, PQ(1000) ≈ 0.751827, 6 decimals).
expect_numbers 5e-7 "0.751827" -- color encode --transfer pq --nits 1000
expect_numbers 5e-7 "0.508078" -- color encode --transfer PQ --nits 100
expect_numbers 5e-7 "0.508078" -- color encode --transfer pq --value 0.01
expect_numbers 0 "1" -- color encode --transfer pq --nits 10000
expect_numbers 1e-5 "10000" -- color decode --transfer pq --value 1 --nits
expect_numbers 5e-7 "0.214041" -- color decode --transfer srgb --value 0.5
expect_numbers 5e-7 "-0.214041" -- color decode --transfer srgb --value -0.5
expect_numbers 5e-7 "17.1232912" -- color decode --transfer srgb --value 0.5 --nits
expect_numbers 0 "1" -- color encode --transfer scrgb --nits 80
expect_numbers 0 "-0.1" -- color encode --transfer scrgb --nits -8
expect_numbers 1e-9 "0.5" -- color encode --transfer hlg --value 0.0833333333333333
expect_numbers 5e-8 "0.4135884" -- color encode --transfer acescct --value 0.18
# 0.4135884025 = (log2(0.18) + 9.72) / 17.52 to 10 decimals; d(linear)/d(code) ≈ 2.2 at 0.18.
expect_numbers 5e-9 "0.18" -- color decode --transfer acescc --value 0.4135884025
expect_numbers 5e-7 "0.5" -- color encode --transfer bt1886 --nits 18.9464571 --white-nits 100

# Help documents the output format.
"$prism" color --help | grep -q '%.9g' || fail "prism color --help does not state the output format"
for sub in convert matrix encode decode spaces; do
  "$prism" color "$sub" --help | grep -q '%.9g' || fail "prism color $sub --help does not state the output format"
done
[ "$("$prism" color spaces | wc -l)" -eq 9 ] || fail "prism color spaces must list 9 spaces"

# Bad input: exit 2, one line.
expect_usage_error color convert --from prophoto --to srgb 1 1 1
expect_usage_error color convert --from srgb --to srgb 1 1
expect_usage_error color convert --from srgb --to srgb 1 1 x
expect_usage_error color convert --from srgb --to srgb 1 1 nan
expect_usage_error color convert --from xy:0.64,0.33,0.64,0.33,0.15,0.06,0.3127,0.329 --to srgb 1 1 1
expect_usage_error color matrix --from srgb --to acescg --cat cat16
expect_usage_error color matrix --from srgb
expect_usage_error color encode --transfer gamma22 --value 0.5
expect_usage_error color encode --transfer pq --nits 1e3x
expect_usage_error color encode --transfer pq
expect_usage_error color encode --transfer hlg --nits 100
expect_usage_error color decode --transfer acescc --value 0.4 --nits
expect_usage_error color decode --transfer bt1886 --value 0.5 --nits --white-nits 10 --black-nits 20
expect_usage_error color

if [ "$failures" -ne 0 ]; then
  echo "$failures failure(s)" >&2
  exit 1
fi
echo "color_cli: all checks passed"
