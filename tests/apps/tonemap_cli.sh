#!/usr/bin/env bash
# `prism tonemap`: SDR/HDR PNG and scRGB EXR outputs, and exit status 2 with one line on
# stderr and no output file for bad input. Usage: tonemap_cli.sh PATH_TO_PRISM.
set -u
prism="$1"
failures=0
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*" >&2; failures=$((failures + 1)); }

# A small scene-linear input rendered by prism itself.
if ! "$prism" render cornell-box --width 24 --height 16 --spp 2 -o "$work/in.exr" >/dev/null 2>&1; then
  echo "FAIL: could not render the input EXR" >&2
  exit 1
fi

# expect_ok OUT args...: exit 0 and the output exists.
expect_ok() {
  local out="$1"; shift
  if ! "$prism" tonemap "$work/in.exr" -o "$work/$out" "$@" >/dev/null 2>"$work/err"; then
    fail "tonemap -o $out $*: $(cat "$work/err")"
  elif [ ! -s "$work/$out" ]; then
    fail "tonemap -o $out $*: no output file"
  fi
}

# expect_usage_error OUT args...: exit 2, one line on stderr, no output file.
expect_usage_error() {
  local out="$1"; shift
  rm -f "$work/$out"
  "$prism" tonemap "$@" -o "$work/$out" >/dev/null 2>"$work/err"
  local rc=$?
  [ "$rc" -eq 2 ] || fail "tonemap $* -o $out: exit $rc, expected 2 ($(cat "$work/err"))"
  [ "$(wc -l <"$work/err")" -eq 1 ] || fail "tonemap $*: stderr is not one line: $(cat "$work/err")"
  grep -q '^prism: error: ' "$work/err" || fail "tonemap $*: stderr lacks 'prism: error:'"
  [ ! -e "$work/$out" ] || fail "tonemap $*: wrote $out despite the error"
}

# png_has_chunk FILE NAME: the chunk name appears in the file (chunk types are ASCII).
png_has_chunk() { grep -q -a "$2" "$1"; }

expect_ok sdr.png
expect_ok sdr8.png --bit-depth 8 --ev100 -2 --blue-correction 0.6
expect_ok rec709.png --odt rec709-100nit
expect_ok p3.png --odt p3d65-100nit
expect_ok hdr.png --odt rec2020-pq-1000nit --max-cll 900
expect_ok hdr4k.png --odt rec2020-pq-4000nit --no-odt-stretch-black --auto-exposure
expect_ok p3pq.png --odt p3d65-pq-1000nit --f-number 2.8 --shutter 0.01 --iso 200
expect_ok scrgb.exr --odt rec2020-pq-1000nit
expect_ok none.png --odt none

png_has_chunk "$work/sdr.png" sRGB || fail "SDR PNG lacks the sRGB chunk"
for c in cICP mDCv cLLi; do
  png_has_chunk "$work/hdr.png" "$c" || fail "HDR PNG lacks $c"
done
png_has_chunk "$work/sdr.png" cICP && fail "SDR sRGB PNG carries a cICP chunk"
# 16-bit PNG by default (float input): IHDR bit depth byte at offset 24.
[ "$(od -An -tu1 -j24 -N1 "$work/sdr.png" | tr -d ' ')" = 16 ] || fail "default SDR PNG is not 16-bit"
[ "$(od -An -tu1 -j24 -N1 "$work/sdr8.png" | tr -d ' ')" = 8 ] || fail "--bit-depth 8 PNG is not 8-bit"
# The cICP payload of the HDR PNG is (9, 16, 0, 1): Rec.2020, PQ, RGB, full range.
cicp=$(od -An -tu1 -v "$work/hdr.png" | tr -s ' \n' ' ' | grep -o '99 73 67 80 9 16 0 1')
[ -n "$cicp" ] || fail "HDR PNG cICP payload is not 9 16 0 1"

echo "not an exr" >"$work/bogus.exr"
head -c 200 "$work/in.exr" >"$work/truncated.exr"
expect_usage_error o1.png "$work/bogus.exr"
expect_usage_error o2.png "$work/truncated.exr"
expect_usage_error o3.png "$work/missing.exr"
expect_usage_error o4.png "$work/in.exr" --odt rec9999-100nit
expect_usage_error o5.png "$work/in.exr" --encoding gamma7
expect_usage_error o6.png "$work/in.exr" --ev100 nan
expect_usage_error o7.png "$work/in.exr" --blue-correction 2
expect_usage_error o8.png "$work/in.exr" --encoding scrgb
expect_usage_error o9.tiff "$work/in.exr"
expect_usage_error o10.png "$work/in.exr" --ev100 1 --auto-exposure

# Issue 6, second round: bloom, display primaries, render scale, views, overlay, AVIF.
expect_ok bloom.png --bloom 0.5 --bloom-threshold-space rgb --ev100 0
expect_ok adobe.png --display-primaries adobe-rgb
# SDR outputs that are not sRGB carry an ICC profile (iCCP), never the sRGB chunk; P3 also
# cICP (12 = P3-D65, 13 = sRGB curve); Adobe RGB has no cICP code point.
png_has_chunk "$work/adobe.png" iCCP || fail "Adobe RGB PNG lacks an ICC profile"
png_has_chunk "$work/adobe.png" sRGB && fail "Adobe RGB PNG carries the sRGB chunk"
png_has_chunk "$work/adobe.png" cICP && fail "Adobe RGB PNG carries a cICP chunk"
png_has_chunk "$work/p3.png" iCCP || fail "P3 PNG lacks an ICC profile"
od -An -tu1 -v "$work/p3.png" | tr -s ' \n' ' ' | grep -q '99 73 67 80 12 13 0 1' || fail "P3 PNG cICP is not 12 13 0 1"
png_has_chunk "$work/sdr.png" iCCP && fail "sRGB PNG carries an ICC profile next to its sRGB chunk"
png_has_chunk "$work/hdr.png" iCCP && fail "PQ PNG carries an ICC profile"
expect_ok custom.png --odt rec2020-pq-1000nit --display-primaries 0.68,0.32,0.265,0.69,0.15,0.06,0.3127,0.329
expect_ok up.png --render-scale 0.5
[ "$(od -An -tu4 --endian=big -j16 -N4 "$work/up.png" | tr -d ' ')" = 48 ] || fail "--render-scale 0.5 did not double the width"
for v in luminance luminance-display chromaticity gamut-clip; do expect_ok "view-$v.png" --view "$v"; done
expect_ok split.png --view sdr-hdr-split --odt rec2020-pq-1000nit --sdr-white 200
expect_ok hdr.avif --odt rec2020-pq-1000nit --bit-depth 12
expect_usage_error o11.png "$work/in.exr" --display-primaries 0.2,0.2,0.3,0.3,0.4,0.4,0.3127,0.329
expect_usage_error o12.png "$work/in.exr" --display-primaries 0.8,0.3,0.21,0.71,0.15,0.06,0.3127,0.329
expect_usage_error o13.png "$work/in.exr" --bloom 3
expect_usage_error o14.png "$work/in.exr" --bloom-threshold-space lab
expect_usage_error o15.png "$work/in.exr" --render-scale 0
expect_usage_error o16.png "$work/in.exr" --view normal
# With the normal AOV in the EXR, --view normal shows it: a different picture from the beauty's.
if "$prism" render cornell-box --width 24 --height 16 --spp 2 --aov normal -o "$work/in-n.exr" >/dev/null 2>&1; then
  if "$prism" tonemap "$work/in-n.exr" -o "$work/beauty-n.png" >/dev/null 2>"$work/err" &&
     "$prism" tonemap "$work/in-n.exr" -o "$work/normal-n.png" --view normal >/dev/null 2>"$work/err"; then
    cmp -s "$work/beauty-n.png" "$work/normal-n.png" && fail "tonemap --view normal wrote the beauty"
  else
    fail "tonemap --view normal with a normal AOV: $(cat "$work/err")"
  fi
else
  fail "could not render the input EXR with a normal AOV"
fi
# Radiance pictures are inputs too, in the space their header names (RGBE with PRIMARIES,
# XYZE); one whose header does not read is a usage error.
if "$prism" render cornell-box --width 24 --height 16 --spp 2 -o "$work/in.hdr" >/dev/null 2>&1 &&
   "$prism" render cornell-box --width 24 --height 16 --spp 2 --exr-space film -o "$work/in-xyz.hdr" >/dev/null 2>&1; then
  for hdr in in.hdr in-xyz.hdr; do
    "$prism" tonemap "$work/$hdr" -o "$work/$hdr.png" >/dev/null 2>"$work/err" && [ -s "$work/$hdr.png" ] ||
      fail "tonemap $hdr: $(cat "$work/err")"
  done
  sed 's/^FORMAT=/EXPOSURE=zero\nFORMAT=/' "$work/in.hdr" > "$work/bad.hdr"
  expect_usage_error o23.png "$work/bad.hdr"
  grep -q "EXPOSURE=zero' is no exposure" "$work/err" || fail "bad .hdr header: $(cat "$work/err")"
else
  fail "could not render the input .hdr files"
fi
expect_usage_error o17.png "$work/in.exr" --view heatmap
expect_usage_error o18.png "$work/in.exr" --view sdr-hdr-split
expect_usage_error o19.avif "$work/in.exr" --bit-depth 8
expect_usage_error o20.png "$work/in.exr" --overlay "$work/missing.png"
expect_usage_error o21.png "$work/in.exr" --ui-nits 1000
expect_usage_error o22.png "$work/in.exr" --ocio-config "$work/missing.ocio" --display sRGB --view Standard

# --auto-exposure meters what the camera saw: the same beauty with a Z.coverage layer (--aov
# depth) meters the box alone, not the black void around it, so it is exposed differently;
# a fixed --ev100 sees no difference between the two files.
if "$prism" render cornell-box --width 24 --height 16 --spp 2 --aov depth -o "$work/in_cov.exr" >/dev/null 2>&1; then
  for input in in in_cov; do
    "$prism" tonemap "$work/$input.exr" -o "$work/${input}_auto.png" --auto-exposure >/dev/null 2>&1 ||
      fail "tonemap $input.exr --auto-exposure"
    "$prism" tonemap "$work/$input.exr" -o "$work/${input}_ev.png" --ev100 6 >/dev/null 2>&1 ||
      fail "tonemap $input.exr --ev100 6"
  done
  cmp -s "$work/in_ev.png" "$work/in_cov_ev.png" || fail "the two renders' beauties differ (--ev100 6)"
  cmp -s "$work/in_auto.png" "$work/in_cov_auto.png" && fail "--auto-exposure ignored the input's Z.coverage"
else
  fail "could not render the input EXR with --aov depth"
fi

if [ "$failures" -ne 0 ]; then
  echo "$failures failure(s)" >&2
  exit 1
fi
echo "tonemap_cli: all checks passed"
