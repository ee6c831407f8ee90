#!/usr/bin/env bash
# Command-line behaviour of `prism render` and `prism info`: exit codes, one-line errors,
# no partial outputs, help text. Usage: render_cli.sh PATH_TO_PRISM
set -u
prism="$1"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0

fail() { echo "FAIL: $*"; failures=$((failures + 1)); }

# expect_error CODE PATTERN ARGS...: exit status CODE, exactly one stderr line starting
# with "prism: error:" and matching PATTERN, and no files left in $work/out.
expect_error() {
  local code="$1" pattern="$2"; shift 2
  rm -rf "$work/out"; mkdir -p "$work/out"
  "$prism" "$@" >"$work/stdout" 2>"$work/stderr"
  local rc=$?
  [ "$rc" -eq "$code" ] || fail "'$*': exit $rc, expected $code (stderr: $(cat "$work/stderr"))"
  [ "$(wc -l <"$work/stderr")" -eq 1 ] || fail "'$*': stderr is not one line: $(cat "$work/stderr")"
  grep -q "^prism: error: .*$pattern" "$work/stderr" || fail "'$*': stderr '$(cat "$work/stderr")' lacks '$pattern'"
  [ -z "$(ls -A "$work/out")" ] || fail "'$*': left files behind: $(ls -A "$work/out")"
}

o=(-o "$work/out/x.exr" -o "$work/out/x.png")
expect_error 1 "does-not-exist.json" render "$work/does-not-exist.json" "${o[@]}"
expect_error 2 "unknown scene 'nosuchscene'" render nosuchscene "${o[@]}"
expect_error 2 "spp" render cornell-box --spp 0 "${o[@]}"
expect_error 2 "spp" render cornell-box --spp -3 "${o[@]}"
expect_error 2 "spp" render cornell-box --spp abc "${o[@]}"
expect_error 2 "threads" render cornell-box --threads 0 "${o[@]}"
expect_error 2 "max-depth" render cornell-box --max-depth -1 "${o[@]}"
expect_error 2 "unknown output extension '.jpg'" render cornell-box -o "$work/out/x.jpg"
expect_error 1 "does not exist" render cornell-box -o "$work/out/missing-dir/x.exr"
expect_error 1 "cannot write" render cornell-box -o /proc/prism-cannot-write-here.exr
expect_error 2 "estimator" render cornell-box --estimator nope "${o[@]}"
expect_error 2 "unknown --aov 'bogus'" render cornell-box --aov bogus "${o[@]}"
expect_error 2 "unknown --aov ''" render cornell-box --aov albedo, "${o[@]}"
expect_error 2 "lists 'depth' twice" render cornell-box --aov depth,normal,depth "${o[@]}"
expect_error 2 "unknown --aov 'Z'" render cornell-box --aov Z "${o[@]}"
expect_error 2 "unknown --sampler 'halton' (independent, sobol, zsobol)" render cornell-box --sampler halton "${o[@]}"
expect_error 2 "unknown --normal-mapping 'bent' (classic, microfacet)" render cornell-box --normal-mapping bent "${o[@]}"
expect_error 2 "" render cornell-box --no-such-option
expect_error 2 "" frobnicate

# A real render writes both files and nothing else, and reports what it wrote.
rm -rf "$work/out"; mkdir -p "$work/out"
if "$prism" render cornell-box --width 32 --height 24 --spp 2 "${o[@]}" >"$work/stdout" 2>"$work/stderr"; then
  [ -s "$work/out/x.exr" ] || fail "render wrote no EXR"
  [ -s "$work/out/x.png" ] || fail "render wrote no PNG"
  [ "$(ls -A "$work/out" | wc -l)" -eq 2 ] || fail "render left extra files: $(ls -A "$work/out")"
  grep -q "2 spp" "$work/stdout" || fail "summary lacks spp: $(cat "$work/stdout")"
  # The process' own peak resident set: a Cornell box render needs some MiB, never none.
  grep -Eq "peak memory [1-9][0-9]* MiB" "$work/stdout" || fail "summary lacks peak memory: $(cat "$work/stdout")"
  [ ! -s "$work/stderr" ] || fail "non-TTY render printed progress: $(cat "$work/stderr")"
else
  fail "small render failed: $(cat "$work/stderr")"
fi

# A .hdr output is the scene-referred image as Radiance RGBE with its primaries named, or
# XYZE for the spectral film's space (--exr-space film); it reads back as an environment.
rm -rf "$work/out"; mkdir -p "$work/out"
if "$prism" render cornell-box --width 16 --height 8 --spp 2 -o "$work/out/w.hdr" >/dev/null 2>"$work/stderr" &&
   "$prism" render cornell-box --width 16 --height 8 --spp 2 --exr-space film -o "$work/out/f.hdr" >/dev/null 2>>"$work/stderr"; then
  head -c 10 "$work/out/w.hdr" | grep -q "#?RADIANCE" || fail ".hdr output lacks the Radiance magic"
  grep -aq "^FORMAT=32-bit_rle_rgbe$" "$work/out/w.hdr" || fail ".hdr output is not RGBE"
  grep -aq "^PRIMARIES= 0.64 0.33 0.3 0.6 0.15 0.06 0.3127 0.329$" "$work/out/w.hdr" || fail ".hdr output names no Rec.709 primaries"
  grep -aq "^FORMAT=32-bit_rle_xyze$" "$work/out/f.hdr" || fail "--exr-space film .hdr output is not XYZE"
  grep -aq "^PRIMARIES=" "$work/out/f.hdr" && fail "an XYZE output names primaries"
  "$prism" render cornell-box --width 8 --height 8 --spp 1 --environment "$work/out/f.hdr" -o "$work/out/e.exr" \
    >/dev/null 2>"$work/stderr" || fail "an XYZE output does not read back as a sky: $(cat "$work/stderr")"
else
  fail ".hdr render failed: $(cat "$work/stderr")"
fi

# --aov with good values: the EXR gains the layers, the PNG stays the beauty; --help says so.
rm -rf "$work/out"; mkdir -p "$work/out"
if "$prism" render cornell-box --width 16 --height 12 --spp 1 --aov albedo,normal,depth "${o[@]}" >"$work/stdout" 2>"$work/stderr"; then
  [ -s "$work/out/x.exr" ] && [ -s "$work/out/x.png" ] || fail "--aov render did not write both files"
  [ "$(ls -A "$work/out" | wc -l)" -eq 2 ] || fail "--aov render left extra files: $(ls -A "$work/out")"
  for channel in albedo.R N.x Z.coverage; do
    grep -aq "$channel" "$work/out/x.exr" || fail "--aov EXR lacks channel $channel"
  done
else
  fail "--aov render failed: $(cat "$work/stderr")"
fi
for subset in normal depth,albedo; do
  "$prism" render cornell-box --width 8 --height 8 --spp 1 --aov "$subset" -o "$work/out/s.exr" >/dev/null 2>&1 ||
    fail "--aov $subset failed"
done
"$prism" render --help | tr -s ' \n' ' ' | grep -q "PNG and AVIF outputs hold the beauty only" ||
  fail "render --help does not say PNG outputs hold the beauty only"
# Every sampler renders, and the EXR says which one made it (prism:sampler).
for sampler in independent sobol zsobol; do
  rm -rf "$work/out"; mkdir -p "$work/out"
  "$prism" render cornell-box --width 16 --height 16 --spp 2 --sampler "$sampler" -o "$work/out/s.exr" \
    >"$work/stdout" 2>"$work/stderr" || fail "--sampler $sampler failed: $(cat "$work/stderr")"
  grep -aq "$sampler" "$work/out/s.exr" || fail "--sampler $sampler: EXR lacks prism:sampler metadata"
done
# The EXR names the direct-light estimator that made it.
rm -rf "$work/out"; mkdir -p "$work/out"
"$prism" render cornell-box --width 8 --height 8 --spp 1 --estimator bsdf -o "$work/out/e.exr" >/dev/null 2>&1 ||
  fail "--estimator bsdf failed"
grep -aq "prism:estimator" "$work/out/e.exr" && grep -aq "bsdf" "$work/out/e.exr" ||
  fail "--estimator bsdf: EXR lacks prism:estimator metadata"
# Either normal-mapping model renders, and the EXR says which one made it.
for model in classic microfacet; do
  rm -rf "$work/out"; mkdir -p "$work/out"
  "$prism" render cornell-box --width 16 --height 16 --spp 2 --normal-mapping "$model" -o "$work/out/n.exr" \
    >"$work/stdout" 2>"$work/stderr" || fail "--normal-mapping $model failed: $(cat "$work/stderr")"
  grep -aq "prism:normalMapping" "$work/out/n.exr" && grep -aq "$model" "$work/out/n.exr" ||
    fail "--normal-mapping $model: EXR lacks prism:normalMapping metadata"
done
# A JSON scene's render.normal_mapping is the default, --normal-mapping overrides it, and
# `prism info` shows the scene's choice.
printf '{"format": "prism-scene/1", "render": {"normal_mapping": "microfacet"},
 "materials": [{"name": "m", "type": "diffuse"}],
 "meshes": [{"name": "q", "material": "m", "positions": [[-1,-1,0],[1,-1,0],[1,1,0],[-1,1,0]],
             "indices": [0,1,2, 0,2,3]}]}\n' >"$work/micro.json"
"$prism" info "$work/micro.json" | grep -qx "normal mapping microfacet" || fail "info does not show the scene's model"
"$prism" info cornell-box | grep -q "normal mapping" && fail "info shows a model for a scene that chose none"
for given in "" classic; do
  rm -rf "$work/out"; mkdir -p "$work/out"
  "$prism" render "$work/micro.json" --width 8 --height 8 --spp 1 ${given:+--normal-mapping "$given"} \
    -o "$work/out/m.exr" >"$work/stdout" 2>"$work/stderr" || fail "render of micro.json failed: $(cat "$work/stderr")"
  if [ "$given" = classic ]; then
    grep -aq microfacet "$work/out/m.exr" && fail "--normal-mapping classic did not override the scene's microfacet"
  else
    grep -aq microfacet "$work/out/m.exr" || fail "the scene's render.normal_mapping was not the default"
  fi
done

# SIGINT/SIGTERM mid-render: exit 128+signal with both images holding the passes so far.
for sig in INT TERM; do
  rm -rf "$work/out"; mkdir -p "$work/out"
  "$prism" render cornell-box --width 64 --height 64 --spp 100000000 "${o[@]}" >"$work/stdout" 2>"$work/stderr" &
  pid=$!
  sleep 1
  kill -"$sig" "$pid"
  wait "$pid"
  rc=$?
  expected=$([ "$sig" = INT ] && echo 130 || echo 143)
  [ "$rc" -eq "$expected" ] || fail "SIG$sig: exit $rc, expected $expected ($(cat "$work/stderr"))"
  [ -s "$work/out/x.exr" ] && [ -s "$work/out/x.png" ] || fail "SIG$sig: images not written"
  grep -q "interrupted" "$work/stdout" || fail "SIG$sig: no interruption notice: $(cat "$work/stdout")"
done

# --camera-json moves the camera: a different view gives a different image; a malformed
# file is a one-line error.
rm -rf "$work/out"; mkdir -p "$work/out"
printf '{"eye": [278, 273, -400], "target": [278, 100, 0]}' >"$work/cam.json"
"$prism" render cornell-box --width 16 --height 16 --spp 1 -o "$work/out/a.exr" >/dev/null 2>&1 || fail "render a"
"$prism" render cornell-box --width 16 --height 16 --spp 1 --camera-json "$work/cam.json" -o "$work/out/b.exr" >/dev/null 2>&1 || fail "render with --camera-json"
cmp -s "$work/out/a.exr" "$work/out/b.exr" && fail "--camera-json did not change the image"
printf '{"eye": [1, 2' >"$work/bad.json"
expect_error 1 "bad.json" render cornell-box --camera-json "$work/bad.json" -o "$work/out/c.exr"

# --help documents every option of render.
"$prism" render --help >"$work/help" 2>&1 || fail "render --help exited non-zero"
for opt in --output --spp --max-depth --seed --threads --time-limit --width --height --estimator --normal-mapping --sampler --mode --wavelengths --wavelength-sampling --upsampling --working-space --camera-json --checkpoint --resume --sample-range --odt --ev100; do
  grep -q -- "$opt" "$work/help" || fail "render --help does not document $opt"
done
"$prism" info >"$work/info" || fail "info failed"
for word in prism embree onetbb cornell-box; do
  grep -q "$word" "$work/info" || fail "info lacks $word"
done
"$prism" --help >/dev/null || fail "--help failed"
"$prism" info --help >/dev/null || fail "info --help failed"

if [ "$failures" -ne 0 ]; then
  echo "$failures failure(s)"
  exit 1
fi
echo "render_cli: all checks passed"
