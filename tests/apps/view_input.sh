#!/usr/bin/env bash
# GUI test (CTest label gui): drives the real viewer window under Xvfb with synthetic X
# input (xdotool/XTEST) and checks, in the --log-events output, that a left drag orbits the
# camera and restarts accumulation (a new generation renders from 1 spp again), that R
# resets the camera, and that Ctrl+Q closes the window cleanly.
# Usage: view_input.sh PATH/TO/prism
set -u
prism="$1"
source "$(dirname "$0")/view_xvfb.bash"
command -v xdotool >/dev/null || { echo "SKIP: xdotool not installed"; exit 77; }
start_xvfb
tmp=$(mktemp -d)
log="$tmp/log.txt"
"$prism" view cornell-box --log-events --width 800 --height 600 >"$log" 2>"$tmp/err.txt" &
viewer=$!
trap 'kill "$viewer" 2>/dev/null; rm -rf "$tmp"; kill "$XVFB_PID" 2>/dev/null; wait "$XVFB_PID" 2>/dev/null' EXIT

wait_for() {  # PATTERN SECONDS
  for _ in $(seq 1 $(( $2 * 10 ))); do
    grep -qE "$1" "$log" && return 0
    kill -0 "$viewer" 2>/dev/null || { echo "FAIL: viewer exited: $(cat "$tmp/err.txt")"; exit 1; }
    sleep 0.1
  done
  echo "FAIL: no '$1' in the log after $2 s:"; cat "$log"; exit 1
}

wait_for '^pass generation=1 spp=1 ' 120
window=$(xdotool search --sync --name '^Prism - ' | head -1)
[ -n "$window" ] || { echo "FAIL: no viewer window"; exit 1; }
eval "$(xdotool getwindowgeometry --shell "$window")"  # X, Y, WIDTH, HEIGHT
# Left drag across the image, left of the control panel and below the stats overlay.
xdotool mousemove $((X + 150)) $((Y + 300))
sleep 0.3
xdotool mousedown 1
for step in 1 2 3 4 5 6; do xdotool mousemove $((X + 150 + step * 15)) $((Y + 300 + step * 3)); sleep 0.05; done
xdotool mouseup 1
wait_for '^camera what=orbit ' 20
wait_for '^restart generation=[0-9]+ reason=camera' 20
g=$(grep -E '^restart generation=[0-9]+ reason=camera' "$log" | tail -1 | sed -E 's/.*generation=([0-9]+).*/\1/')
# The camera restart reuses the scene prepared (flattened, BVH built) for the first render.
grep -qE '^restart generation=[0-9]+ reason=camera .*scene_prepared=1$' "$log" || {
  echo "FAIL: the camera restart did not reuse the prepared scene"; grep '^restart' "$log"; exit 1; }
wait_for "^pass generation=$g spp=1 " 120
eye_orbit=$(grep '^camera what=orbit' "$log" | tail -1 | sed -E 's/.*eye=([^ ]*).*/\1/')
grep -q '^camera what=orbit eye=278,273,-800 ' "$log" && { echo "FAIL: orbit did not move the eye"; exit 1; }

xdotool key r
wait_for '^camera what=reset eye=278,273,-800 ' 20

xdotool key ctrl+q
for _ in $(seq 1 300); do kill -0 "$viewer" 2>/dev/null || break; sleep 0.1; done
if kill -0 "$viewer" 2>/dev/null; then echo "FAIL: Ctrl+Q did not close the viewer"; exit 1; fi
wait "$viewer"; rc=$?
[ "$rc" -eq 0 ] || { echo "FAIL: viewer exit status $rc"; exit 1; }
grep -q '^ui frames=' "$log" || { echo "FAIL: no UI statistics at exit"; exit 1; }
# The viewer's own peak resident set (what its stats overlay shows): some MiB, never none.
grep -Eq '^ui frames=.* peak_memory_mib=[1-9][0-9]*$' "$log" || { echo "FAIL: no peak memory at exit"; exit 1; }
echo "ok: orbit moved the eye to $eye_orbit, accumulation restarted as generation $g; $(grep '^ui frames=' "$log")"
