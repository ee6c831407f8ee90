#!/usr/bin/env bash
# Submits a Prism farm render to Slurm (docs/farm-rendering.md): a job array of TASKS tasks,
# each rendering one sample range of SCENE (render-array.sbatch), and a merge job that runs
# once every task has succeeded (merge.sbatch, --dependency=afterok). Slurm does all the
# scheduling; this only writes the two sbatch commands.
#
# Usage: submit.sh [--prism PATH] [--sbatch-option OPT]... SCENE SPP TASKS OUTDIR [-- PRISM_RENDER_ARGS...]
#   --prism PATH          the prism binary, as every node sees it (default: `prism` on PATH)
#   --sbatch-option OPT   passed to both sbatch commands (repeatable), e.g.
#                         --sbatch-option=--partition=render --sbatch-option=--time=4:00:00
#   OUTDIR                a folder on the filesystem every node shares; created if missing
# Prints the array and merge job ids ("array <id>" and "merge <id>" lines). Resubmitting
# with the same OUTDIR renders only the parts that are missing.
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
usage="usage: submit.sh [--prism PATH] [--sbatch-option OPT]... SCENE SPP TASKS OUTDIR [-- PRISM_RENDER_ARGS...]"

prism=prism
sbatch_options=()
while [ $# -gt 0 ]; do
  case "$1" in
    --prism) prism=${2:?$usage}; shift 2 ;;
    --prism=*) prism=${1#--prism=}; shift ;;
    --sbatch-option) sbatch_options+=("${2:?$usage}"); shift 2 ;;
    --sbatch-option=*) sbatch_options+=("${1#--sbatch-option=}"); shift ;;
    -h | --help) echo "$usage"; exit 0 ;;
    --) break ;;
    -*) echo "submit.sh: unknown option '$1'" >&2; echo "$usage" >&2; exit 2 ;;
    *) break ;;
  esac
done
if [ $# -lt 4 ]; then echo "$usage" >&2; exit 2; fi
scene=$1 spp=$2 tasks=$3 outdir=$4
shift 4
if [ $# -gt 0 ]; then
  if [ "$1" != -- ]; then echo "$usage" >&2; exit 2; fi
  shift
fi
if ! [[ "$spp" =~ ^[1-9][0-9]*$ && "$tasks" =~ ^[1-9][0-9]*$ ]] || [ "$tasks" -gt "$spp" ]; then
  echo "submit.sh: SPP and TASKS must be positive integers with TASKS <= SPP (got $spp, $tasks)" >&2
  exit 2
fi

# Compute nodes see absolute paths only.
prism_path=$(command -v "$prism" || true)
if [ -z "$prism_path" ]; then echo "submit.sh: prism binary '$prism' not found" >&2; exit 2; fi
prism_path=$(realpath "$prism_path")
case "$scene" in
  */* | *.*) [ -e "$scene" ] && scene=$(realpath "$scene") ;;  # a file; a built-in name stays as it is
esac
mkdir -p "$outdir/parts" "$outdir/checkpoints" "$outdir/logs"
outdir=$(realpath "$outdir")

array_id=$(sbatch --parsable --array="0-$((tasks - 1))" --output="$outdir/logs/render-%A_%a.log" \
  "${sbatch_options[@]}" "$here/render-array.sbatch" "$prism_path" "$scene" "$spp" "$tasks" "$outdir" "$@")
array_id=${array_id%%;*}  # --parsable prints "id" or "id;cluster"
merge_id=$(sbatch --parsable --dependency="afterok:$array_id" --output="$outdir/logs/merge-%j.log" \
  "${sbatch_options[@]}" "$here/merge.sbatch" "$prism_path" "$tasks" "$outdir")
merge_id=${merge_id%%;*}
echo "array $array_id"
echo "merge $merge_id"
echo "submit.sh: $tasks tasks of $scene ($spp spp); logs in $outdir/logs, the image will be $outdir/merged.exr" >&2
