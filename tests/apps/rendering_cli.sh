#!/usr/bin/env bash
# `--rendering` on `prism tonemap` and `prism render`, its metadata, the refusals (exit 2,
# one line), `tonemap --help`'s table, and the OpenColorIO path chosen by $OCIO.
# Usage: rendering_cli.sh PATH_TO_PRISM.
set -u
prism="$1"
failures=0
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*" >&2; failures=$((failures + 1)); }
unset OCIO

if ! "$prism" render cornell-box --width 24 --height 16 --spp 2 -o "$work/in.exr" >/dev/null 2>&1; then
  echo "FAIL: could not render the input EXR" >&2
  exit 1
fi

# expect_usage_error OUT args...: exit 2, one line on stderr, no output file.
expect_usage_error() {
  local out="$1"; shift
  rm -f "$work/$out"
  "$prism" tonemap "$work/in.exr" "$@" -o "$work/$out" >/dev/null 2>"$work/err"
  local rc=$?
  [ "$rc" -eq 2 ] || fail "tonemap $* -o $out: exit $rc, expected 2 ($(cat "$work/err"))"
  [ "$(wc -l <"$work/err")" -eq 1 ] || fail "tonemap $*: stderr is not one line: $(cat "$work/err")"
  grep -q '^prism: error: ' "$work/err" || fail "tonemap $*: stderr lacks 'prism: error:'"
  [ ! -e "$work/$out" ] || fail "tonemap $*: wrote $out despite the error"
}

# Every rendering with every SDR target, and aces1 with an HDR one; the PNG names both.
for rendering in aces1 aces2 agx pbr-neutral; do
  for odt in srgb-100nit rec709-100nit p3d65-100nit rec2020-100nit; do
    out="$work/$rendering-$odt.png"
    "$prism" tonemap "$work/in.exr" --rendering "$rendering" --odt "$odt" -o "$out" >"$work/log" 2>&1 ||
      fail "tonemap --rendering $rendering --odt $odt: $(cat "$work/log")"
    grep -q -a "prism:rendering.$rendering" "$out" || fail "$out: no prism:rendering $rendering text"
    grep -q -a "prism:displayTarget.$odt" "$out" || fail "$out: no prism:displayTarget $odt text"
    grep -q "rendering $rendering, target $odt" "$work/log" || fail "tonemap summary: $(cat "$work/log")"
  done
done
"$prism" tonemap "$work/in.exr" --rendering aces1 --odt rec2020-pq-1000nit -o "$work/hdr.png" >/dev/null 2>&1 ||
  fail "aces1 with an HDR target"
for odt in rec2020-pq-1000nit rec2020-pq-2000nit rec2020-pq-4000nit p3d65-pq-1000nit; do
  "$prism" tonemap "$work/in.exr" --rendering aces2 --odt "$odt" -o "$work/aces2-$odt.png" >/dev/null 2>"$work/err" ||
    fail "aces2 with $odt: $(cat "$work/err")"
done
"$prism" tonemap "$work/in.exr" --rendering aces2 --odt rec2020-pq-1000nit --peak-nits 600 -o "$work/peak.avif" \
  >/dev/null 2>"$work/err" || fail "aces2 --peak-nits 600: $(cat "$work/err")"

# ACES 2.0's inverse: the display image back to ACES2065-1, from a PNG or tonemap's scRGB EXR.
"$prism" tonemap "$work/in.exr" --rendering aces2 -o "$work/fwd.png" >/dev/null 2>&1 &&
  "$prism" tonemap "$work/fwd.png" --inverse --rendering aces2 -o "$work/back.exr" >/dev/null 2>"$work/err" &&
  [ -s "$work/back.exr" ] || fail "tonemap --inverse from PNG: $(cat "$work/err")"
"$prism" tonemap "$work/in.exr" --rendering aces2 --odt rec2020-pq-1000nit -o "$work/fwd.exr" >/dev/null 2>&1 &&
  "$prism" tonemap "$work/fwd.exr" --inverse --rendering aces2 --odt rec2020-pq-1000nit -o "$work/back2.exr" \
    >/dev/null 2>"$work/err" && [ -s "$work/back2.exr" ] || fail "tonemap --inverse from scRGB EXR: $(cat "$work/err")"
grep -q -a "prism:inverseOf" "$work/back.exr" || fail "inverse EXR lacks prism:inverseOf"

# Pairs that make no sense, unknown names.
expect_usage_error e1.png --rendering agx --odt rec2020-pq-1000nit
grep -q "valid: srgb-100nit" "$work/err" || fail "agx + PQ error does not list the valid targets: $(cat "$work/err")"
expect_usage_error e2.png --rendering pbr-neutral --odt p3d65-pq-1000nit
expect_usage_error e3.png --rendering pbr-neutral --odt none
expect_usage_error e4.png --rendering filmic
expect_usage_error e5.png --rendering agx --blue-correction 0.5
expect_usage_error e6.exr --display-primaries adobe-rgb
expect_usage_error e8.png --rendering aces2 --odt none
expect_usage_error e9.png --rendering aces2 --peak-nits 50
expect_usage_error e10.png --rendering aces2 --peak-nits 20000
expect_usage_error e11.png --rendering agx --peak-nits 400
expect_usage_error e12.png --inverse --rendering agx
expect_usage_error e13.png --inverse --rendering aces2

# --help lists every valid rendering × target pair.
help=$("$prism" tonemap --help)
echo "$help" | grep -q "agx: srgb-100nit rec709-100nit p3d65-100nit rec2020-100nit$" || fail "--help lacks agx's targets"
echo "$help" | grep -q "pbr-neutral: srgb-100nit rec709-100nit p3d65-100nit rec2020-100nit$" ||
  fail "--help lacks pbr-neutral's targets"
echo "$help" | grep -q "aces1: none srgb-100nit .* p3d65-pq-1000nit$" || fail "--help lacks aces1's targets"
echo "$help" | grep -q "aces2: srgb-100nit .* p3d65-pq-1000nit$" || fail "--help lacks aces2's targets"

# prism render takes --rendering for its display outputs.
"$prism" render cornell-box --width 16 --height 12 --spp 1 --rendering agx -o "$work/r.png" >"$work/log" 2>&1 ||
  fail "render --rendering agx: $(cat "$work/log")"
grep -q -a "prism:rendering.agx" "$work/r.png" || fail "render: no prism:rendering agx text"
grep -q "rendering agx, target srgb-100nit" "$work/log" || fail "render summary: $(cat "$work/log")"

# prism view checks --rendering against --odt before it opens a window (a prism built
# without the viewer, -DPRISM_VIEWER=OFF, has no view options to check).
if env -u DISPLAY -u WAYLAND_DISPLAY "$prism" view cornell-box 2>&1 | grep -q "built without the viewer"; then
  echo "skip: prism view --rendering (built without the viewer)"
else
  for args in "--rendering agx --odt rec2020-pq-1000nit" "--rendering filmic"; do
    # shellcheck disable=SC2086
    env -u DISPLAY -u WAYLAND_DISPLAY "$prism" view cornell-box $args >/dev/null 2>"$work/err"
    rc=$?
    [ "$rc" -eq 2 ] && grep -q "rendering" "$work/err" || fail "view $args: exit $rc ($(cat "$work/err"))"
  done
fi

# $OCIO: its default display and view unless --rendering or --odt is named.
cat >"$work/config.ocio" <<'OCIO'
ocio_profile_version: 2
roles:
  default: linear
  scene_linear: linear
displays:
  sRGB:
    - !<View> {name: Standard, colorspace: srgb_display}
colorspaces:
  - !<ColorSpace>
    name: linear
    isdata: false
  - !<ColorSpace>
    name: srgb_display
    isdata: false
    from_scene_reference: !<ExponentWithLinearTransform> {gamma: 2.4, offset: 0.055, direction: inverse}
OCIO
for ext in png avif; do
  OCIO="$work/config.ocio" "$prism" tonemap "$work/in.exr" -o "$work/ocio.$ext" >"$work/log" 2>&1 ||
    fail "tonemap with \$OCIO -o .$ext: $(cat "$work/log")"
  grep -q "OpenColorIO config .*config.ocio (\$OCIO), display 'sRGB', view 'Standard'" "$work/log" ||
    fail "\$OCIO summary: $(cat "$work/log")"
done
grep -q -a "prism:ocioView.Standard" "$work/ocio.png" || fail "OCIO PNG: no prism:ocioView text"
OCIO="$work/config.ocio" "$prism" tonemap "$work/in.exr" --odt srgb-100nit -o "$work/named.png" >"$work/log" 2>&1 ||
  fail "tonemap with \$OCIO and --odt: $(cat "$work/log")"
grep -q "rendering aces1, target srgb-100nit" "$work/log" || fail "--odt did not override \$OCIO: $(cat "$work/log")"
OCIO="$work/config.ocio" "$prism" tonemap "$work/in.exr" --rendering agx -o "$work/named2.png" >"$work/log" 2>&1 ||
  fail "tonemap with \$OCIO and --rendering: $(cat "$work/log")"
grep -q "rendering agx" "$work/log" || fail "--rendering did not override \$OCIO: $(cat "$work/log")"
OCIO="$work/config.ocio" "$prism" render cornell-box --width 16 --height 12 --spp 1 -o "$work/r-ocio.png" \
  >"$work/log" 2>&1 || fail "render with \$OCIO: $(cat "$work/log")"
grep -q "OpenColorIO config" "$work/log" || fail "render with \$OCIO: $(cat "$work/log")"
OCIO="$work/config.ocio" expect_usage_error e7.exr

if [ "$failures" -ne 0 ]; then
  echo "$failures failure(s)" >&2
  exit 1
fi
echo "rendering_cli: all checks passed"
