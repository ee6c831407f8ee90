#!/bin/bash
# Before/after timing on a noisy machine: runs two prism binaries alternately, ROUNDS times
# each, on the same render, and prints each one's minimum and median wall seconds (from the
# summary line `prism render` prints). Alternating spreads the machine's slow phases over
# both; the minimum is the run least disturbed (BENCHMARKS.md "How to measure a change").
#
#   scripts/bench/alternate_renders.sh ROUNDS BINARY_A BINARY_B -- RENDER ARGUMENTS...
#   scripts/bench/alternate_renders.sh 10 /tmp/old/prism build/release/prism -- \
#       cornell-box --width 256 --height 256 --spp 32 --threads 1
set -euo pipefail
if [ $# -lt 5 ] || [ "$4" != "--" ]; then
  echo "usage: $0 ROUNDS BINARY_A BINARY_B -- RENDER ARGUMENTS..." >&2
  exit 2
fi
rounds=$1 a=$2 b=$3
shift 4
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
for _ in $(seq "$rounds"); do
  for bin in "$a" "$b"; do
    seconds=$("$bin" render "$@" --output "$out/image.exr" 2>&1 | grep -o 'in [0-9.]* s' | awk '{print $2}')
    [ -n "$seconds" ] || { echo "$bin: no timing in its output" >&2; exit 1; }
    echo "$bin $seconds" >> "$out/times"
  done
done
python3 - "$out/times" <<'PY'
import collections, statistics, sys
times = collections.defaultdict(list)
for line in open(sys.argv[1]):
    binary, seconds = line.rsplit(maxsplit=1)
    times[binary].append(float(seconds))
for binary, t in times.items():
    print(f"{binary}: min {min(t):.3f} s, median {statistics.median(t):.3f} s, {len(t)} runs")
PY
