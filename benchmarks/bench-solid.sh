#!/usr/bin/env bash
# Solid (volume) synthesis time and peak memory through the gegl tool, per
# exemplar, volume size and thread count.
# SPDX-License-Identifier: LGPL-3.0-or-later
#
# Time = median wall time of
#   gegl -i EXEMPLAR -o slice.png -- texsynth:volume-slice size=N
# minus the median of the same command with a trivial op (gegl:crop),
# which leaves GEGL's start-up, loading and PNG writing out. Peak memory
# is the largest maximum resident set size (/usr/bin/time) of those runs,
# and "extra" its excess over the trivial op's (GEGL alone takes a few
# hundred MiB here, most of it before any pixel is processed; the engine
# alone is measured at the end with build/benchmarks/solid-memory).
# GEGL_THREADS=1 throughout; OMP_NUM_THREADS varies.
#
# Usage: benchmarks/bench-solid.sh [-b BUILD_DIR] [-e EXEMPLAR_DIR]
#          [-s "64 128 256"] [-t "1 2"] [-r RUNS] [-x "granite1 java"] [-c SIDE]
# -c 128 (the default) measures on 128x128 central crops of the exemplars at
# least that large and skips smaller ones; -c 0 uses them whole.

set -euo pipefail

here=$(cd "$(dirname "$0")/.." && pwd)
. "$here/benchmarks/bench-lib.sh"
build="$here/build"
exemplars="$here/tests/exemplars"
sizes="64 128 256"
threads="2"
runs=3
only=""
crop=128

while getopts "b:e:s:t:r:x:c:h" opt; do
  case "$opt" in
    b) build=$OPTARG ;;
    e) exemplars=$OPTARG ;;
    s) sizes=$OPTARG ;;
    t) threads=$OPTARG ;;
    r) runs=$OPTARG ;;
    x) only=$OPTARG ;;
    c) crop=$OPTARG ;;
    *) sed -n '2,17p' "$0"; exit 2 ;;
  esac
done

use_ops "$build" texsynth:volume-slice
[ -x /usr/bin/time ] || { echo "/usr/bin/time is missing (Debian package 'time')" >&2; exit 1; }

tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT


# Runs gegl ARGS... RUNS times; prints "median_seconds peak_kib".
measure() {
  local i start end times="" peak=0 rss
  for ((i = 0; i < runs; i++)); do
    start=$(date +%s.%N)
    env $run_env /usr/bin/time -f %M -o "$tmp/rss" gegl "$@" >/dev/null 2>"$tmp/err" ||
      { cat "$tmp/err" >&2; exit 1; }
    end=$(date +%s.%N)
    grep -q "texsynth" "$tmp/err" && { cat "$tmp/err" >&2; exit 1; }
    times="$times $(echo "$end - $start" | bc -l)"
    rss=$(tail -1 "$tmp/rss")
    [ "$rss" -gt "$peak" ] && peak=$rss
  done
  echo "$(echo "$times" | median) $peak"
}

files=()
if [ -n "$only" ]; then
  for name in $only; do files+=("$exemplars/$name.png"); done
else
  files=("$exemplars"/*.png)
fi
if [ "$crop" -gt 0 ]; then
  mapfile -t files < <(crop_central "$crop" "$tmp" "${files[@]}")
fi

echo "# texsynth solid synthesis, $(date -u +%Y-%m-%d), $(nproc) cores, $runs runs, GEGL_THREADS=1"
printf '%-12s %6s %8s %9s %10s %10s\n' exemplar size threads seconds peak-MiB extra-MiB
declare -A all peaks extras
for size in $sizes; do
  for t in $threads; do
    run_env="OMP_NUM_THREADS=$t"
    for ex in "${files[@]}"; do
      name=$(basename "$ex" .png)
      read -r base base_peak < <(measure -i "$ex" -o "$tmp/base.png" -- gegl:crop width="$size" height="$size")
      read -r full peak < <(measure -i "$ex" -o "$tmp/slice.png" -- texsynth:volume-slice size="$size")
      synth=$(echo "$full - $base" | bc -l)
      extra=$(( peak > base_peak ? peak - base_peak : 0 ))
      printf '%-12s %6s %8s %9.2f %10.1f %10.1f\n' "$name" "${size}^3" "$t" "$synth" \
        "$(echo "$peak / 1024" | bc -l)" "$(echo "$extra / 1024" | bc -l)"
      all[$size,$t]="${all[$size,$t]:-} $synth"
      peaks[$size,$t]="${peaks[$size,$t]:-} $peak"
      extras[$size,$t]="${extras[$size,$t]:-} $extra"
    done
    printf '%-12s %6s %8s %9.2f %10.1f %10.1f\n' median "${size}^3" "$t" \
      "$(echo "${all[$size,$t]}" | median)" "$(echo "$(echo "${peaks[$size,$t]}" | median) / 1024" | bc -l)" \
      "$(echo "$(echo "${extras[$size,$t]}" | median) / 1024" | bc -l)"
  done
done

# GEGL's start-up alone peaks at a few hundred MiB of RSS here, which hides
# the engine's own needs: measure those without GEGL too.
if [ -x "$build/benchmarks/solid-memory" ]; then
  echo
  echo "# engine alone (build/benchmarks/solid-memory, generated 128x128 exemplar, OMP_NUM_THREADS=$(echo "$threads" | awk '{ print $NF }'))"
  for size in $sizes; do
    OMP_NUM_THREADS=$(echo "$threads" | awk '{ print $NF }') "$build/benchmarks/solid-memory" "$size" 128
  done
fi

# Shapes: the slices (x, y, z, diagonal) of volumes synthesised from the
# ground-truth solids' exemplars beside the truth's own, and granite1's
# central crop (axis-edges, sharpness, coherence, completeness, seam).
if [ -x "$build/benchmarks/solid-shapes" ]; then
  for size in $sizes; do
    [ "$size" -le 128 ] || continue
    echo
    echo "# shapes (build/benchmarks/solid-shapes $size 1 cells blobs grains granite1.png)"
    OMP_NUM_THREADS=$(echo "$threads" | awk '{ print $NF }') "$build/benchmarks/solid-shapes" "$size" 1 \
      cells blobs grains "$exemplars/granite1.png"
  done
fi
