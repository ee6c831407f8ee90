#!/usr/bin/env bash
# Scene loading through the command line: `prism info SCENE` and `prism render` on good and
# bad scene files: exit 0 or 1, one-line errors, never a crash or a hang.
# Usage: loaders_cli.sh PATH_TO_PRISM
set -u
prism="$1"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }

# expect_ok PATTERN ARGS...: exit 0 and stdout matching PATTERN.
expect_ok() {
  local pattern="$1"; shift
  timeout 60 "$prism" "$@" >"$work/stdout" 2>"$work/stderr"
  local rc=$?
  [ "$rc" -eq 0 ] || fail "'$*': exit $rc (stderr: $(cat "$work/stderr"))"
  grep -q -- "$pattern" "$work/stdout" || fail "'$*': stdout lacks '$pattern': $(cat "$work/stdout")"
}

# expect_exit CODE PATTERN ARGS...: exit CODE and exactly one stderr line "prism: error: ...PATTERN".
# expect_error is CODE 1 (bad input), expect_usage_error CODE 2 (a bad command line).
expect_exit() {
  local code="$1" pattern="$2"; shift 2
  timeout 60 "$prism" "$@" >"$work/stdout" 2>"$work/stderr"
  local rc=$?
  [ "$rc" -eq "$code" ] || fail "'$*': exit $rc, expected $code (stderr: $(cat "$work/stderr"))"
  [ "$(wc -l <"$work/stderr")" -eq 1 ] || fail "'$*': stderr is not one line: $(cat "$work/stderr")"
  grep -q "^prism: error: .*$pattern" "$work/stderr" || fail "'$*': stderr '$(cat "$work/stderr")' lacks '$pattern'"
}
expect_error() { expect_exit 1 "$@"; }
expect_usage_error() { expect_exit 2 "$@"; }

mkdir -p "$work/scene"
cat >"$work/scene/good.json" <<'JSON'
{"format": "prism-scene/1", "name": "good",
 "materials": [{"name": "grey", "type": "diffuse"},
               {"name": "lamp", "type": "diffuse", "emission": {"color": [1, 1, 1], "luminance_nits": 10}}],
 "meshes": [{"name": "floor", "material": "grey", "positions": [-1,0,-1, -1,0,1, 1,0,1, 1,0,-1], "indices": [0,1,2, 0,2,3]},
            {"name": "lamp", "material": "lamp", "positions": [-0.2,1,-0.2, 0.2,1,-0.2, 0.2,1,0.2, -0.2,1,0.2],
             "indices": [0,1,2, 0,2,3]}],
 "camera": {"eye": [0, 0.5, 3], "target": [0, 0.3, 0]}}
JSON
printf 'v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n' >"$work/scene/quad.obj"
printf '{"format": "prism-scene/1",\n "materials": [{"name": "m" "type": "diffuse"}]}\n' >"$work/scene/malformed.json"
sed 's/"luminance_nits": 10/"luminance_nits": "bright"/' "$work/scene/good.json" >"$work/scene/schema.json"
sed 's/"indices": \[0,1,2, 0,2,3\]}\]/"indices": [0,1,2, 0,2,7]}]/' "$work/scene/good.json" >"$work/scene/badindex.json"
sed 's/"type": "diffuse"}/"type": "diffuse", "base_color_texture": "..\/..\/..\/..\/..\/..\/etc\/passwd"}/' \
  "$work/scene/good.json" >"$work/scene/escape.json"
printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n' >"$work/scene/badindex.obj"
head -c 20 "$work/scene/good.json" >"$work/scene/truncated.json"
printf '\x89PNG\r\n\x1a\n garbage' >"$work/scene/garbage.json"

expect_ok "built-in scenes: .*material-test" info
expect_ok "^triangles 4 " info "$work/scene/good.json"
expect_ok "materials 2 (2 diffuse; 1 emissive)" info "$work/scene/good.json"
expect_ok "^triangles 2 " info "$work/scene/quad.obj"
expect_ok "warning: .*no emissive material" info "$work/scene/quad.obj"
expect_ok "^scene material-test" info material-test
expect_ok "^scene dispersion-prism" info dispersion-prism
expect_ok "rendered good 16x16" render "$work/scene/good.json" --spp 1 --width 16 --height 16 -o "$work/good.exr"
[ -s "$work/good.exr" ] || fail "render of good.json wrote no image"
expect_ok "rendered quad 16x16" render "$work/scene/quad.obj" --spp 1 --width 16 --height 16 -o "$work/quad.exr"
expect_ok "rendered material-test 16x16" render material-test --spp 1 --width 16 --height 16 -o "$work/mt.exr"

expect_error "malformed.json:2:29: malformed JSON" info "$work/scene/malformed.json"
expect_error "malformed.json:2:29: malformed JSON" render "$work/scene/malformed.json" --spp 1 --width 16 --height 16 -o "$work/x.exr"
expect_error "materials\[1\].emission.luminance_nits: expected a number" info "$work/scene/schema.json"
expect_error "index 7 (at 5) is out of range" render "$work/scene/badindex.json" --spp 1 --width 16 --height 16 -o "$work/x.exr"
expect_error "vertex index 9 is out of range" info "$work/scene/badindex.obj"
expect_error "leads outside the scene's folder" info "$work/scene/escape.json"
expect_error "leads outside the scene's folder" render "$work/scene/escape.json" --spp 1 --width 16 --height 16 -o "$work/x.exr"
expect_error "wrong magic" info --allow-external-paths "$work/scene/escape.json"
expect_error "truncated.json:1:12: malformed JSON: unterminated string" info "$work/scene/truncated.json"
expect_error "garbage.json:1:1: malformed JSON" info "$work/scene/garbage.json"
expect_error "no such file" info "$work/scene/missing.json"
cp "$work/scene/good.json" "$work/scene/good.ply"
expect_error "no loader for '.ply'" info "$work/scene/good.ply"
[ ! -e "$work/x.exr" ] || fail "a failed render left $work/x.exr behind"

# --camera NAME|INDEX chooses among a file's cameras; an unknown one is a usage error
# (exit 2) listing what the scene has, before any rendering.
sed 's/"camera": {"eye": \[0, 0.5, 3\], "target": \[0, 0.3, 0\]}}/"cameras": [{"name": "front", "eye": [0, 0.5, 3], "target": [0, 0.3, 0]}, {"name": "top", "eye": [0, 4, 0.01], "target": [0, 0, 0]}]}/' \
  "$work/scene/good.json" >"$work/scene/cameras.json"
expect_ok "camera top " info "$work/scene/cameras.json"
for spec in top 1 front 0; do
  expect_ok "rendered" render "$work/scene/cameras.json" --camera "$spec" --spp 1 --width 8 --height 8 -o "$work/cam-$spec.png"
done
cmp -s "$work/cam-top.png" "$work/cam-1.png" || fail "--camera top and --camera 1 differ"
cmp -s "$work/cam-front.png" "$work/cam-0.png" || fail "--camera front and --camera 0 differ"
cmp -s "$work/cam-top.png" "$work/cam-front.png" && fail "--camera top and front render the same image"
for spec in side 2; do
  timeout 60 "$prism" render "$work/scene/cameras.json" --camera "$spec" --spp 1 -o "$work/nocam.exr" >"$work/stdout" 2>"$work/stderr"
  rc=$?
  [ "$rc" -eq 2 ] || fail "--camera $spec: exit $rc, expected 2"
  grep -q "^prism: error: .*it has 2 cameras: 0 'front' 1 'top'" "$work/stderr" || fail "--camera $spec: $(cat "$work/stderr")"
  [ ! -e "$work/nocam.exr" ] || fail "--camera $spec wrote an image"
done

# A scene without lights renders black, with one warning naming the way out; --environment
# lights it (uniform sky, or an image map); a bad map is a one-line error and writes nothing.
cat >"$work/scene/dark.json" <<'JSON'
{"format": "prism-scene/1", "name": "dark",
 "materials": [{"name": "grey", "type": "diffuse"}],
 "meshes": [{"name": "floor", "material": "grey", "positions": [-1,0,-1, -1,0,1, 1,0,1, 1,0,-1], "indices": [0,1,2, 0,2,3]}],
 "camera": {"eye": [0, 0.5, 3], "target": [0, 0, 0]}}
JSON
expect_ok "rendered" render "$work/scene/dark.json" --spp 1 --width 8 --height 8 -o "$work/dark.exr"
grep -q "^prism: warning: dark has no lights or emissive surfaces.*--environment" "$work/stderr" ||
  fail "no warning for a scene without lights: $(cat "$work/stderr")"
expect_ok "rendered" render "$work/scene/dark.json" --environment uniform --environment-nits 2 --spp 1 --width 8 --height 8 \
  -o "$work/lit.exr"
grep -q "warning" "$work/stderr" && fail "--environment uniform still warns: $(cat "$work/stderr")"
cmp -s "$work/dark.exr" "$work/lit.exr" && fail "--environment uniform rendered the same image as no lights"
expect_error "cannot read image" render "$work/scene/dark.json" --environment "$work/missing.hdr" --spp 1 -o "$work/nomap.exr"
[ ! -e "$work/nomap.exr" ] || fail "--environment with a missing map wrote an image"
timeout 60 "$prism" render "$work/scene/dark.json" --environment uniform --environment-nits -1 -o "$work/neg.exr" \
  >"$work/stdout" 2>"$work/stderr"
[ "$?" -eq 2 ] || fail "--environment-nits -1: expected a usage error (exit 2): $(cat "$work/stderr")"

# glTF KHR_materials_variants: `prism info` lists the variants, --variant picks one (the
# blue variant's emission lights the image the default one leaves dark), and a name the
# file lacks, or a scene without variants, is a one-line error.
cat >"$work/scene/variants.gltf" <<'JSON'
{"asset": {"version": "2.0"}, "extensionsUsed": ["KHR_materials_variants"],
 "extensions": {"KHR_materials_variants": {"variants": [{"name": "red"}, {"name": "blue"}]}},
 "buffers": [{"uri": "data:application/octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA", "byteLength": 36}],
 "bufferViews": [{"buffer": 0, "byteLength": 36}],
 "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3", "min": [0, 0, 0], "max": [1, 1, 0]}],
 "materials": [{"name": "plain"}, {"name": "red", "pbrMetallicRoughness": {"baseColorFactor": [1, 0, 0, 1]}},
               {"name": "blue-lamp", "emissiveFactor": [0, 0, 1]}],
 "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "material": 0,
   "extensions": {"KHR_materials_variants": {"mappings": [{"material": 1, "variants": [0]}, {"material": 2, "variants": [1]}]}}}]}],
 "cameras": [{"type": "perspective", "perspective": {"yfov": 0.8, "znear": 0.1}}],
 "nodes": [{"mesh": 0}, {"camera": 0, "translation": [0.3, 0.3, 2]}], "scenes": [{"nodes": [0, 1]}]}
JSON
expect_ok "variant blue" info "$work/scene/variants.gltf"
expect_ok "1 emissive" info "$work/scene/variants.gltf" --variant blue
expect_ok "rendered" render "$work/scene/variants.gltf" --variant blue --spp 1 --width 8 --height 8 -o "$work/blue.exr"
expect_ok "rendered" render "$work/scene/variants.gltf" --spp 1 --width 8 --height 8 -o "$work/plain.exr"
cmp -s "$work/blue.exr" "$work/plain.exr" && fail "--variant blue rendered the default materials"
expect_usage_error "no material variant 'green' (variants: red, blue)" render "$work/scene/variants.gltf" \
  --variant green --spp 1 -o "$work/green.exr"
[ ! -e "$work/green.exr" ] || fail "an unknown --variant wrote an image"
expect_usage_error "has no material variants" info "$work/scene/good.json" --variant red

if [ "$failures" -ne 0 ]; then echo "$failures failure(s)"; exit 1; fi
echo "loaders CLI: all checks passed"
