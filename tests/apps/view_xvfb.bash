# Shared by the viewer's GUI tests (sourced, not run): starts Xvfb on a free display
# number and stops it on exit. Needs xvfb (scripts/install-deps.sh).
start_xvfb() {
  if ! command -v Xvfb >/dev/null; then echo "SKIP: Xvfb not installed"; exit 77; fi
  local n
  for n in $(seq 90 199); do
    [ -e "/tmp/.X${n}-lock" ] || [ -e "/tmp/.X11-unix/X${n}" ] && continue
    Xvfb ":${n}" -screen 0 1600x1000x24 -nolisten tcp >/dev/null 2>&1 &
    XVFB_PID=$!
    for _ in $(seq 1 50); do
      [ -e "/tmp/.X11-unix/X${n}" ] && break
      kill -0 "$XVFB_PID" 2>/dev/null || break
      sleep 0.1
    done
    if kill -0 "$XVFB_PID" 2>/dev/null && [ -e "/tmp/.X11-unix/X${n}" ]; then
      export DISPLAY=":${n}"
      trap 'kill "$XVFB_PID" 2>/dev/null; wait "$XVFB_PID" 2>/dev/null' EXIT
      return 0
    fi
  done
  echo "FAIL: could not start Xvfb"; exit 1
}

# PNG width and height from the IHDR chunk (bytes 16..23, big-endian).
png_size() {
  local bytes
  bytes=$(od -An -tu1 -j16 -N8 "$1" | tr -s ' ' | sed 's/^ //')
  set -- $bytes
  echo "$(( ($1 << 24) + ($2 << 16) + ($3 << 8) + $4 ))x$(( ($5 << 24) + ($6 << 16) + ($7 << 8) + $8 ))"
}
