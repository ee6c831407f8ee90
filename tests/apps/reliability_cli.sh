#!/usr/bin/env bash
# Faults while `prism render` runs: the output directory removed mid-render, a full disk
# (a small tmpfs, where mounting is permitted; skipped otherwise) and --memory-limit.
# Each must give one error line, a non-zero exit, and leave the checkpoint and previous
# outputs intact. Usage: reliability_cli.sh PATH_TO_PRISM
set -u
prism="$1"
work=$(mktemp -d)
mounted=""
cleanup() {
  [ -n "$mounted" ] && umount "$mounted" 2>/dev/null
  rm -rf "$work"
}
trap cleanup EXIT
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }

# one_error_line FILE PATTERN: FILE holds exactly one line, "prism: error: ...PATTERN...".
one_error_line() {
  [ "$(wc -l <"$1")" -eq 1 ] || fail "stderr is not one line: $(cat "$1")"
  grep -q "^prism: error: .*$2" "$1" || fail "stderr '$(cat "$1")' lacks '$2'"
}

small=(cornell-box --width 24 --height 16 --seed 3)

# --- 1. The output directory is removed while rendering --------------------------------
mkdir -p "$work/out" "$work/ckp"
"$prism" render "${small[@]}" --spp 100000 --time-limit 4 --checkpoint "$work/ckp/r.ckp" --checkpoint-every 0.1 \
  -o "$work/out/r.exr" -o "$work/out/r.png" >"$work/stdout" 2>"$work/stderr" &
pid=$!
# Wait until the render is under way (its first periodic checkpoint exists).
for _ in $(seq 100); do [ -e "$work/ckp/r.ckp" ] && break; sleep 0.1; done
[ -e "$work/ckp/r.ckp" ] || fail "render wrote no periodic checkpoint within 10 s"
kill -0 "$pid" 2>/dev/null || fail "render ended before the directory was removed"
rm -rf "$work/out"
wait "$pid"
rc=$?
[ "$rc" -eq 1 ] || fail "directory removed: exit $rc, expected 1 (stderr: $(cat "$work/stderr"))"
one_error_line "$work/stderr" "cannot write '$work/out/r.exr'"
[ ! -e "$work/out" ] || fail "directory removed: prism recreated it"
# The checkpoint (elsewhere) was written when the render ended and resumes.
[ -s "$work/ckp/r.ckp" ] || fail "directory removed: no checkpoint"
ls -A "$work/ckp" | grep -q tmp && fail "directory removed: temporary file left in $work/ckp"
mkdir -p "$work/out2"
"$prism" render "${small[@]}" --spp 100000 --time-limit 0.2 --resume "$work/ckp/r.ckp" \
  -o "$work/out2/r.exr" >/dev/null 2>"$work/stderr" || fail "resume after removed directory: $(cat "$work/stderr")"

# --- 2. Disk full on a small tmpfs (root and mount permitted; otherwise skipped) --------
mkdir -p "$work/disk"
if mount -t tmpfs -o size=256k tmpfs "$work/disk" 2>/dev/null; then
  mounted="$work/disk"
  "$prism" render "${small[@]}" --spp 2 --checkpoint "$work/disk/r.ckp" -o "$work/disk/r.exr" \
    >/dev/null 2>"$work/stderr" || fail "tmpfs: first render failed: $(cat "$work/stderr")"
  cp "$work/disk/r.exr" "$work/prev.exr"
  cp "$work/disk/r.ckp" "$work/prev.ckp"
  # Fill the disk to the last block.
  dd if=/dev/zero of="$work/disk/filler" bs=4k >/dev/null 2>&1
  # A new image and the checkpoint update (resume to more samples) cannot fit.
  "$prism" render "${small[@]}" --spp 4 --resume "$work/disk/r.ckp" -o "$work/disk/r.exr" \
    >"$work/stdout" 2>"$work/stderr"
  rc=$?
  [ "$rc" -eq 1 ] || fail "tmpfs full: exit $rc, expected 1 (stderr: $(cat "$work/stderr"))"
  one_error_line "$work/stderr" "No space left on device"
  cmp -s "$work/disk/r.exr" "$work/prev.exr" || fail "tmpfs full: previous image changed"
  cmp -s "$work/disk/r.ckp" "$work/prev.ckp" || fail "tmpfs full: previous checkpoint changed"
  ls -A "$work/disk" | grep -q tmp && fail "tmpfs full: temporary file left: $(ls -A "$work/disk")"
  # Only the image cannot fit (no checkpoint): same guarantees.
  "$prism" render "${small[@]}" --spp 3 -o "$work/disk/r.exr" >"$work/stdout" 2>"$work/stderr"
  rc=$?
  [ "$rc" -eq 1 ] || fail "tmpfs full (image): exit $rc, expected 1 (stderr: $(cat "$work/stderr"))"
  one_error_line "$work/stderr" "cannot write '$work/disk/r.exr'"
  cmp -s "$work/disk/r.exr" "$work/prev.exr" || fail "tmpfs full (image): previous image changed"
  # Space again: the intact checkpoint resumes.
  rm -f "$work/disk/filler"
  "$prism" render "${small[@]}" --spp 4 --resume "$work/disk/r.ckp" -o "$work/disk/r.exr" \
    >/dev/null 2>"$work/stderr" || fail "tmpfs: resume after freeing space failed: $(cat "$work/stderr")"
  umount "$work/disk" && mounted=""
else
  echo "skipped: tmpfs disk-full test (mount not permitted here)"
fi

# --- 3. --memory-limit -------------------------------------------------------------------
mkdir -p "$work/mem"
start=$(date +%s)
"$prism" render cornell-box --width 30000 --height 30000 --spp 1 --memory-limit 1G -o "$work/mem/x.exr" \
  >/dev/null 2>"$work/stderr"
rc=$?
[ "$rc" -eq 1 ] || fail "memory limit: exit $rc, expected 1 (stderr: $(cat "$work/stderr"))"
one_error_line "$work/stderr" "more than the memory limit of 1.00 GiB"
[ $(($(date +%s) - start)) -le 5 ] || fail "memory limit: refusal took more than 5 s (allocated first?)"
[ -z "$(ls -A "$work/mem")" ] || fail "memory limit: left files: $(ls -A "$work/mem")"
"$prism" render cornell-box --width 30000 --height 30000 --spp 1 --memory-limit 12X -o "$work/mem/x.exr" \
  >/dev/null 2>"$work/stderr"
rc=$?
[ "$rc" -eq 2 ] || fail "bad --memory-limit: exit $rc, expected 2"
one_error_line "$work/stderr" "memory-limit '12X'"
"$prism" render "${small[@]}" --spp 1 --memory-limit 256M -o "$work/mem/ok.exr" >/dev/null 2>"$work/stderr" ||
  fail "ordinary render under --memory-limit 256M failed: $(cat "$work/stderr")"
"$prism" render --help | grep -q -- --memory-limit || fail "render --help does not document --memory-limit"
# The limit applies while loading: a tiny PNG whose header declares 8000 x 8000 pixels
# (732 MiB of float texels) is refused from its header, naming the file, within seconds.
"$prism" render cornell-box --width 2 --height 2 --spp 1 -o "$work/mem/tex.png" >/dev/null 2>&1 ||
  fail "cannot make a small PNG"
printf '\000\000\037\100\000\000\037\100' | dd of="$work/mem/tex.png" bs=1 seek=16 conv=notrunc 2>/dev/null
cat >"$work/mem/bomb.json" <<'JSON'
{"format": "prism-scene/1", "name": "bomb",
 "materials": [{"name": "tex", "type": "diffuse", "base_color_texture": "tex.png"},
               {"name": "lamp", "type": "diffuse", "emission": {"color": [1, 1, 1], "luminance_nits": 10}}],
 "meshes": [{"name": "floor", "material": "tex", "positions": [-1,0,-1, -1,0,1, 1,0,1, 1,0,-1], "indices": [0,1,2, 0,2,3],
             "uvs": [0,0, 0,1, 1,1, 1,0]},
            {"name": "lamp", "material": "lamp", "positions": [-0.2,1,-0.2, 0.2,1,-0.2, 0.2,1,0.2, -0.2,1,0.2],
             "indices": [0,1,2, 0,2,3]}]}
JSON
start=$(date +%s)
"$prism" render "$work/mem/bomb.json" --spp 1 --width 8 --height 8 --memory-limit 256M -o "$work/mem/bomb.exr" \
  >/dev/null 2>"$work/stderr"
rc=$?
[ "$rc" -eq 1 ] || fail "texture over the memory limit: exit $rc, expected 1 (stderr: $(cat "$work/stderr"))"
one_error_line "$work/stderr" "tex.png' (8000x8000, 3 channels) needs .* more than the memory limit of 256 MiB"
[ $(($(date +%s) - start)) -le 5 ] || fail "texture over the memory limit: refusal took more than 5 s"
[ ! -e "$work/mem/bomb.exr" ] || fail "texture over the memory limit: an image was written"

if [ "$failures" -gt 0 ]; then
  echo "$failures failure(s)"
  exit 1
fi
echo "reliability_cli: all passed"
