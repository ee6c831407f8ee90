#!/usr/bin/env bash
# GUI test (CTest label gui): `prism view --frames N --screenshot` under Xvfb with Mesa's
# software OpenGL. The screenshot has the window's size, is not blank, and a higher
# --ev100 gives a darker image; --view normal shows the normal AOV. Usage: view_gui.sh PATH/TO/prism
set -u
prism="$1"
source "$(dirname "$0")/view_xvfb.bash"
start_xvfb
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"; kill "$XVFB_PID" 2>/dev/null; wait "$XVFB_PID" 2>/dev/null' EXIT

shot() {  # EV100 → prints the screenshot's mean code value
  local log="$tmp/log_$1.txt"
  if ! timeout 300 "$prism" view cornell-box --frames 4 --screenshot "$tmp/shot_$1.png" --ev100 "$1" \
       --log-events >"$log" 2>"$tmp/err_$1.txt"; then
    echo "FAIL: prism view --ev100 $1 failed: $(cat "$tmp/err_$1.txt")" >&2; exit 1
  fi
  grep -o 'mean=[0-9.]*' "$log" | cut -d= -f2
}

bright=$(shot 1)
dark=$(shot 4)
for ev in 1 4; do
  size=$(png_size "$tmp/shot_$ev.png")
  [ "$size" = "1280x720" ] || { echo "FAIL: screenshot is $size, expected 1280x720"; exit 1; }
  bytes=$(stat -c %s "$tmp/shot_$ev.png")
  [ "$bytes" -gt 20000 ] || { echo "FAIL: screenshot of $bytes bytes looks blank"; exit 1; }
  grep -q 'spp=4 ' "$tmp/log_$ev.txt" || { echo "FAIL: no 4th pass in the log"; exit 1; }
done
sd=$(grep -o 'stddev=[0-9.]*' "$tmp/log_1.txt" | cut -d= -f2)
awk -v s="$sd" 'BEGIN { exit !(s > 0.02) }' || { echo "FAIL: screenshot is flat (stddev $sd)"; exit 1; }
awk -v b="$bright" -v d="$dark" 'BEGIN { exit !(b > d + 0.002) }' ||
  { echo "FAIL: --ev100 4 mean $dark is not darker than --ev100 1 mean $bright"; exit 1; }
# --view normal starts in the normal debug view (the film's normal AOV): it must render
# and show something other than the beauty.
if ! timeout 300 "$prism" view cornell-box --frames 2 --view normal --screenshot "$tmp/shot_normal.png" \
     --log-events >"$tmp/log_normal.txt" 2>"$tmp/err_normal.txt"; then
  echo "FAIL: prism view --view normal failed: $(cat "$tmp/err_normal.txt")" >&2; exit 1
fi
normal=$(grep -o 'mean=[0-9.]*' "$tmp/log_normal.txt" | cut -d= -f2)
nsd=$(grep -o 'stddev=[0-9.]*' "$tmp/log_normal.txt" | cut -d= -f2)
awk -v s="$nsd" 'BEGIN { exit !(s > 0.02) }' || { echo "FAIL: normal view is flat (stddev $nsd)"; exit 1; }
awk -v n="$normal" -v b="$bright" 'BEGIN { d = n - b; exit !(d > 0.01 || d < -0.01) }' ||
  { echo "FAIL: normal view mean $normal looks like the beauty's $bright"; exit 1; }
# The normal-map model: a JSON scene's render.normal_mapping is the viewer's start, and
# --normal-mapping overrides it (the restart line names the one in use).
printf '{"format": "prism-scene/1", "render": {"normal_mapping": "microfacet"},
 "materials": [{"name": "m", "type": "diffuse"}],
 "meshes": [{"name": "q", "material": "m", "positions": [[-1,-1,0],[1,-1,0],[1,1,0],[-1,1,0]],
             "indices": [0,1,2, 0,2,3]}],
 "environment": {"color": [1, 1, 1], "luminance_nits": 1}}\n' >"$tmp/micro.json"
for given in "" classic; do
  if ! timeout 300 "$prism" view "$tmp/micro.json" --frames 1 ${given:+--normal-mapping "$given"} --width 160 \
       --height 120 --log-events >"$tmp/log_nm.txt" 2>"$tmp/err_nm.txt"; then
    echo "FAIL: prism view of a scene choosing microfacet failed: $(cat "$tmp/err_nm.txt")" >&2; exit 1
  fi
  want=${given:-microfacet}
  grep -q "^restart generation=.* normal_mapping=$want " "$tmp/log_nm.txt" ||
    { echo "FAIL: --normal-mapping '$given' did not start with $want: $(grep restart "$tmp/log_nm.txt")"; exit 1; }
done
echo "ok: mean code value $bright at EV100 1, $dark at EV100 4, $normal in the normal view"
