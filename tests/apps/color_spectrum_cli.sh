#!/usr/bin/env bash
# `prism color spectrum` and `prism color wavelengths`: output shape, a few known values,
# and usage errors (exit 2). $1 is the prism binary.
set -u
prism="$1"
fail() { echo "FAIL: $*" >&2; exit 1; }

# Reflectance spectrum: 401 lines "lambda value", 380..780 nm, values in [0, 1].
out=$("$prism" color spectrum --space srgb 0.8 0.3 0.1) || fail "spectrum exited $?"
[ "$(echo "$out" | wc -l)" -eq 401 ] || fail "spectrum: expected 401 lines"
echo "$out" | awk 'NR==1 && $1!=380 {exit 1} NR==401 && $1!=780 {exit 1} NF!=2 || $2<0 || $2>1 {exit 1}' \
  || fail "spectrum: bad line format or range"

# A grey is flat and exact: S(λ) = 0.5 everywhere.
"$prism" color spectrum 0.5 0.5 0.5 | awk '$2!=0.5 {exit 1}' || fail "grey spectrum not flat 0.5"

# Mallett–Yuksel: white albedo is the partition of unity, 1 at every wavelength.
"$prism" color spectrum --method mallett-yuksel 1 1 1 | awk '($2<0.999999 || $2>1.000001) {exit 1}' \
  || fail "mallett-yuksel white is not 1"

# Emission: white light is flat, and 683 * sum(S * ybar) = nits. A flat spectrum of 100 nit
# has S = 100 / (683 * 106.857) = 0.00137020 (∫ȳ over 380–780 nm, 1 nm trapezoid).
"$prism" color spectrum --emission --nits 100 1 1 1 | awk '{ if ($2 < 0.0013695 || $2 > 0.0013709) exit 1 }' \
  || fail "emission white is not the flat 100-nit spectrum"

# Wavelengths: K lines of 2N numbers; wavelengths in [380, 780], pdfs positive.
out=$("$prism" color wavelengths --strategy cosh3 --n 4 --count 50 --seed 3) || fail "wavelengths exited $?"
[ "$(echo "$out" | wc -l)" -eq 50 ] || fail "wavelengths: expected 50 lines"
echo "$out" | awk 'NF!=8 {exit 1} {for (i=1;i<=4;i++) if ($i<380 || $i>780 || $(i+4)<=0) exit 1}' \
  || fail "wavelengths: bad record"
# Hero: partners are evenly rotated by 400/N nm, all with pdf 1/400.
"$prism" color wavelengths --strategy hero --n 4 --count 20 --seed 9 | awk '{
  for (i=2;i<=4;i++) { d = $i - $(i-1); if (d < 0) d += 400; if (d < 99.999 || d > 100.001) exit 1 }
  for (i=5;i<=8;i++) if ($i != 0.0025) exit 1 }' || fail "hero partners not rotated by 100 nm"
# Same seed, same output.
[ "$("$prism" color wavelengths --strategy cosh --count 5 --seed 1)" = "$("$prism" color wavelengths --strategy cosh --count 5 --seed 1)" ] \
  || fail "wavelengths not reproducible for a seed"

# Usage errors exit 2 with one line on stderr.
expect_usage_error() {
  err=$("$prism" "$@" 2>&1 >/dev/null); rc=$?
  [ "$rc" -eq 2 ] || fail "'$*' exited $rc, expected 2"
  [ "$(echo "$err" | wc -l)" -eq 1 ] || fail "'$*' printed more than one error line"
}
expect_usage_error color spectrum 1 abc 0
expect_usage_error color spectrum --space nowhere 1 1 1
expect_usage_error color spectrum --method magic 1 1 1
expect_usage_error color spectrum --method mallett-yuksel --space rec2020 1 1 1
expect_usage_error color spectrum --emission --nits -5 1 1 1
expect_usage_error color spectrum --emission --nits lots 1 1 1
expect_usage_error color wavelengths --strategy uniform
expect_usage_error color wavelengths --n 4x
expect_usage_error color wavelengths --count -1
echo "color_spectrum_cli: ok"
