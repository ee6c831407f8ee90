#!/usr/bin/env bash
# Plots `prism bench convergence --json FILE` as PNGs (gnuplot, from Debian; this script
# installs gnuplot-nox and jq if they are missing — install-deps.sh does not).
#   scripts/bench/plot.sh bench/results/convergence-1024.json [OUT_DIR (default bench/plots)]
# Writes OUT_DIR/convergence-relmse-spp.png, convergence-relmse-time.png and
# convergence-chromaticity.png.
set -euo pipefail
json="${1:?usage: plot.sh CONVERGENCE_JSON [OUT_DIR]}"
out="${2:-bench/plots}"

need=()
command -v gnuplot >/dev/null || need+=(gnuplot-nox)
command -v jq >/dev/null || need+=(jq)
if [ ${#need[@]} -gt 0 ]; then
  sudo_cmd=()
  [ "$(id -u)" -ne 0 ] && sudo_cmd=(sudo)
  "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${need[@]}"
fi

mkdir -p "$out"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

suite='.suites[] | select(.suite == "convergence")'
strategies=$(jq -r "$suite | .data.series | keys[]" "$json")
[ -n "$strategies" ] || { echo "plot.sh: no convergence series in $json" >&2; exit 1; }
size=$(jq -r "$suite | .data.size" "$json")
ref=$(jq -r "$suite | .data.reference_spp" "$json")
for s in $strategies; do
  jq -r --arg s "$s" "$suite"' | .data.series[$s][] | "\(.spp) \(.seconds) \(.rel_mse) \(.xy_error_per_pixel) \(.xy_error_region_mean)"' \
    "$json" >"$work/$s.dat"
done

plot_lines() {  # column_x column_y
  local first=1 cmd=""
  for s in $strategies; do
    [ $first -eq 1 ] || cmd+=", "
    cmd+="'$work/$s.dat' using $1:$2 with linespoints title '$s'"
    first=0
  done
  echo "$cmd"
}

common="set terminal pngcairo size 900,600 font 'sans,11'; set logscale xy; set grid; set key top right"
gnuplot -e "$common; set output '$out/convergence-relmse-spp.png';
  set title 'Cornell box ${size}², spectral, strategy-N wavelengths: relative MSE vs spp (reference 2 × ${ref} spp)';
  set xlabel 'samples per pixel'; set ylabel 'relMSE'; plot $(plot_lines 1 3)"
gnuplot -e "$common; set output '$out/convergence-relmse-time.png';
  set title 'Cornell box ${size}², spectral, strategy-N wavelengths: relative MSE vs render time';
  set xlabel 'seconds'; set ylabel 'relMSE'; plot $(plot_lines 2 3)"
gnuplot -e "$common; set output '$out/convergence-chromaticity.png';
  set title 'Back-wall chromaticity error vs spp (mean per-pixel CIE xy distance to the reference)';
  set xlabel 'samples per pixel'; set ylabel 'xy distance';
  plot $(plot_lines 1 4), 0.003 with lines dashtype 2 lc rgb 'gray' title 'xy = 0.003'"
echo "wrote $out/convergence-relmse-spp.png $out/convergence-relmse-time.png $out/convergence-chromaticity.png"
