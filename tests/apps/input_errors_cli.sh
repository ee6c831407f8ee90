#!/usr/bin/env bash
# What a new user met with scene files: a glTF of another major version, a garbage .glb
# (its bytes must not reach the terminal), a buffer uri outside the scene's folder (the
# message must say it was refused, why, and how to allow it), and pbrt-v4's Film
# "filename" (written without -o; overriding it with -o is said).
# Usage: input_errors_cli.sh PATH_TO_PRISM
set -u
prism="$1"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }

# expect_error PATTERN ARGS...: exit 1, one stderr line "prism: error: ...PATTERN" of
# printable ASCII only.
expect_error() {
  local pattern="$1"; shift
  (cd "$work" && timeout 60 "$prism" "$@") >"$work/stdout" 2>"$work/stderr"
  local rc=$?
  [ "$rc" -eq 1 ] || fail "'$*': exit $rc, expected 1 ($(cat "$work/stderr"))"
  [ "$(wc -l <"$work/stderr")" -eq 1 ] || fail "'$*': stderr is not one line: $(cat "$work/stderr")"
  grep -q -- "^prism: error: .*$pattern" "$work/stderr" || fail "'$*': stderr '$(cat "$work/stderr")' lacks '$pattern'"
  ! LC_ALL=C grep -q '[^[:print:]]' "$work/stderr" || fail "'$*': stderr has bytes that are not printable ASCII"
}

mkdir -p "$work/scene" "$work/secret"
# A triangle, its buffer in a data: uri.
triangle='"buffers": [{"uri": "data:application/octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA", "byteLength": 36}],
 "bufferViews": [{"buffer": 0, "byteLength": 36}],
 "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3", "min": [0, 0, 0], "max": [1, 1, 0]}],
 "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}], "nodes": [{"mesh": 0}], "scenes": [{"nodes": [0]}]}'
printf '{"asset": {"version": "2.0"}, %s\n' "$triangle" >"$work/scene/v2.gltf"
printf '{"asset": {"version": "7.0"}, %s\n' "$triangle" >"$work/scene/v7.gltf"
( cd "$work" && "$prism" info scene/v2.gltf >/dev/null 2>&1 ) || fail "the glTF 2.0 triangle does not load"
expect_error "v7.gltf: glTF version 7.0 (asset.version) is not supported; Prism reads glTF 2.0" info scene/v7.gltf
expect_error "v7.gltf: glTF version 7.0" render scene/v7.gltf --spp 1 --width 8 --height 8 -o x.exr
[ ! -e "$work/x.exr" ] || fail "a glTF 7.0 file was rendered"

# Garbage: a binary glTF header over bytes that are not JSON (nor UTF-8), and bytes alone.
printf 'glTF\x02\x00\x00\x00\x30\x00\x00\x00\x20\x00\x00\x00JSON\xff\xfe\x80{\x1b[31m\xc3\x28 "a\n\x9b\xe2\x82\xac\x01\xc0\xaf' \
  >"$work/scene/garbage.glb"
head -c 48 "$work/scene/garbage.glb" | tail -c 32 >"$work/scene/garbage.gltf"
for f in garbage.glb garbage.gltf; do expect_error "$f" info "scene/$f"; done
printf '\xff\xfe\x80{\x1b[31m\xc3\x28' >"$work/scene/bytes.gltf"
expect_error 'bytes.gltf: .*\\x' info scene/bytes.gltf  # the message quotes the bytes, escaped

# A buffer outside the scene's folder: refused, saying why and how to allow it.
cp "$work/scene/v2.gltf" "$work/secret/v2.gltf"
printf 'AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA' | base64 -d >"$work/secret/triangle.bin"
sed 's|"uri": "data:[^"]*"|"uri": "../secret/triangle.bin"|' "$work/scene/v2.gltf" >"$work/scene/escape.gltf"
sed "s|\"uri\": \"data:[^\"]*\"|\"uri\": \"$work/secret/triangle.bin\"|" "$work/scene/v2.gltf" >"$work/scene/absolute.gltf"
expect_error "escape.gltf: buffer or image uri: path '../secret/triangle.bin' leads outside the scene's folder (refused; use --allow-external-paths to permit it)" \
  info scene/escape.gltf
expect_error "absolute.gltf: buffer or image uri: absolute path '$work/secret/triangle.bin' refused (scene files may only refer to files in their own folder; use --allow-external-paths to permit it)" \
  info scene/absolute.gltf
for f in escape absolute; do
  ( cd "$work" && "$prism" info --allow-external-paths "scene/$f.gltf" >/dev/null 2>&1 ) ||
    fail "--allow-external-paths does not let $f.gltf read its buffer"
done

# pbrt-v4's Film "filename": written when no -o is given; -o overrides it, with a note.
pbrt() {  # pbrt FILM_PARAMETERS: a small lit scene
  cat <<PBRT
LookAt 0 0 5  0 0 0  0 1 0
Camera "perspective" "float fov" [ 40 ]
Film "rgb" "integer xresolution" [ 8 ] "integer yresolution" [ 8 ] $1
WorldBegin
AttributeBegin
  AreaLightSource "diffuse" "rgb L" [ 4 4 4 ]
  Shape "trianglemesh" "point3 P" [ -1 -1 0  1 -1 0  1 1 0 ] "integer indices" [ 0 1 2 ]
AttributeEnd
PBRT
}
pbrt '"string filename" "own.exr"' >"$work/scene/own.pbrt"
pbrt '"string filename" "../own.exr"' >"$work/scene/folder.pbrt"
pbrt '"string filename" "own.pfm"' >"$work/scene/pfm.pbrt"
mkdir "$work/run"
( cd "$work/run" && "$prism" render ../scene/own.pbrt --spp 1 >/dev/null 2>"$work/stderr" ) || fail "render own.pbrt"
[ -s "$work/run/own.exr" ] || fail "Film \"filename\" own.exr was not written: $(ls "$work/run")"
[ "$(ls "$work/run")" = "own.exr" ] || fail "rendering own.pbrt wrote $(ls "$work/run")"
grep -q "note" "$work/stderr" && fail "a note where Film \"filename\" was used: $(cat "$work/stderr")"
( cd "$work/run" && "$prism" render ../scene/own.pbrt --spp 1 -o given.exr >/dev/null 2>"$work/stderr" ) ||
  fail "render own.pbrt -o given.exr"
[ -s "$work/run/given.exr" ] || fail "-o given.exr was not written"
grep -qx "prism: note: -o overrides the scene's output file 'own.exr' (Film \"filename\")" "$work/stderr" ||
  fail "no note that -o overrides Film \"filename\": $(cat "$work/stderr")"
rm -f "$work/run/"*
( cd "$work/run" && "$prism" render ../scene/folder.pbrt --spp 1 >/dev/null 2>"$work/stderr" ) || fail "render folder.pbrt"
[ ! -e "$work/own.exr" ] || fail "a scene's Film \"filename\" wrote outside the current folder"
grep -q "^prism: note: the scene's output file '../own.exr' (Film \"filename\") names a folder" "$work/stderr" ||
  fail "no note for a Film \"filename\" with a folder: $(cat "$work/stderr")"
( cd "$work/run" && "$prism" render ../scene/pfm.pbrt --spp 1 >/dev/null 2>"$work/stderr" ) || fail "render pfm.pbrt"
grep -q "^prism: note: prism does not write the scene's output file 'own.pfm'" "$work/stderr" ||
  fail "no note for a Film \"filename\" prism cannot write: $(cat "$work/stderr")"

if [ "$failures" -ne 0 ]; then echo "$failures failure(s)"; exit 1; fi
echo "input errors CLI: all checks passed"
