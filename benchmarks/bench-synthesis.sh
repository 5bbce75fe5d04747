#!/usr/bin/env bash
# Synthesis time of texsynth:synthesize through the gegl tool, per exemplar,
# output size and thread count, and the speed-up from more threads.
# SPDX-License-Identifier: LGPL-3.0-or-later
#
# Time = median wall time of
#   gegl -i EXEMPLAR -o out.png -- texsynth:synthesize width=W height=H
# minus the median of the same command with a trivial op of the same output
# size (gegl:tile + gegl:crop), which leaves GEGL's start-up, loading and
# PNG writing out. GEGL_THREADS=1 throughout; OMP_NUM_THREADS varies.
#
# Usage: benchmarks/bench-synthesis.sh [-b BUILD_DIR] [-e EXEMPLAR_DIR]
#          [-s "256 1024"] [-t "1 2"] [-r RUNS] [-x "brick wood1"] [-c SIDE]
# -c 128 measures on SIDE x SIDE central crops of the exemplars at least
# that large (the issue's "128x128 exemplars") and skips smaller ones.
# The defaults (every exemplar, 256 and 1024, 1 and 2 threads, 5 runs)
# take a long while; -x and -s cut it down.

set -euo pipefail

here=$(cd "$(dirname "$0")/.." && pwd)
. "$here/benchmarks/bench-lib.sh"
build="$here/build"
exemplars="$here/tests/exemplars"
sizes="256 1024"
threads="1 2"
runs=5
only=""
crop=""

while getopts "b:e:s:t:r:x:c:h" opt; do
  case "$opt" in
    b) build=$OPTARG ;;
    e) exemplars=$OPTARG ;;
    s) sizes=$OPTARG ;;
    t) threads=$OPTARG ;;
    r) runs=$OPTARG ;;
    x) only=$OPTARG ;;
    c) crop=$OPTARG ;;
    *) sed -n '2,18p' "$0"; exit 2 ;;
  esac
done

use_ops "$build" texsynth:synthesize

tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

# Median wall time in seconds of RUNS runs of: gegl ARGS... (env in $run_env)
median_time() {
  local i start end
  for ((i = 0; i < runs; i++)); do
    start=$(date +%s.%N)
    env $run_env gegl "$@" >/dev/null 2>"$tmp/err" || { cat "$tmp/err" >&2; exit 1; }
    end=$(date +%s.%N)
    echo "$end - $start" | bc -l
  done | median
}

files=()
if [ -n "$only" ]; then
  for name in $only; do files+=("$exemplars/$name.png"); done
else
  files=("$exemplars"/*.png)
fi
if [ -n "$crop" ]; then
  mapfile -t files < <(crop_central "$crop" "$tmp" "${files[@]}")
fi

printf '%-12s %9s' exemplar size
for t in $threads; do printf ' %9s' "${t}thr(s)"; done
printf ' %8s\n' speed-up
declare -A total
declare -A all
for size in $sizes; do
  for ex in "${files[@]}"; do
    name=$(basename "$ex" .png)
    printf '%-12s %9s' "$name" "${size}x$size"
    first="" last=""
    for t in $threads; do
      run_env="OMP_NUM_THREADS=$t"
      base=$(median_time -i "$ex" -o "$tmp/base.png" -- gegl:tile gegl:crop width="$size" height="$size")
      full=$(median_time -i "$ex" -o "$tmp/out.png" -- texsynth:synthesize width="$size" height="$size")
      synth=$(echo "$full - $base" | bc -l)
      printf ' %9.2f' "$synth"
      total[$size,$t]=$(echo "${total[$size,$t]:-0} + $synth" | bc -l)
      all[$size,$t]="${all[$size,$t]:-} $synth"
      [ -n "$first" ] || first=$synth
      last=$synth
    done
    printf ' %7.2fx\n' "$(echo "$first / $last" | bc -l)"
  done
  printf '%-12s %9s' median "${size}x$size"
  first="" last=""
  for t in $threads; do
    m=$(echo "${all[$size,$t]}" | median)
    printf ' %9.2f' "$m"
    [ -n "$first" ] || first=$m
    last=$m
  done
  printf ' %7.2fx\n' "$(echo "$first / $last" | bc -l)"
  printf '%-12s %9s' total "${size}x$size"
  first="" last=""
  for t in $threads; do
    printf ' %9.2f' "${total[$size,$t]}"
    [ -n "$first" ] || first=${total[$size,$t]}
    last=${total[$size,$t]}
  done
  printf ' %7.2fx\n' "$(echo "$first / $last" | bc -l)"
done
