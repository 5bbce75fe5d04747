#!/usr/bin/env bash
# Style transfer's figures: texsynth:guided (no aux2) restyles a 192x192
# crop (the top left) of a picture with each exemplar, seed 1, and
# texsynth-measure --style-target prints the blurred-lightness
# correlation with the picture (1 = its layout followed) and the
# sharpness against the exemplar (1 = the exemplar's grain kept).
# Tuning half: land1 restyled by bark, granite1, rock and wood1; checking
# half: canyons2 restyled by cracked, stone33, java and burlap.
# SPDX-License-Identifier: LGPL-3.0-or-later
#
# With -s "1 2 3", each figure is the median over those seeds, each
# seed's after it.
#
# Usage: benchmarks/style-transfer.sh [-b BUILD_DIR] [-e EXEMPLAR_DIR] [-s SEEDS]

set -euo pipefail

here=$(cd "$(dirname "$0")/.." && pwd)
build="$here/build"
exemplars="$here/tests/exemplars"
seeds=1
while getopts "b:e:s:" opt; do
  case $opt in
    b) build=$(cd "$OPTARG" && pwd) ;;
    e) exemplars=$(cd "$OPTARG" && pwd) ;;
    s) seeds=$OPTARG ;;
    *) echo "usage: $0 [-b BUILD_DIR] [-e EXEMPLAR_DIR] [-s SEEDS]" >&2; exit 2 ;;
  esac
done
measure="$build/tools/texsynth-measure"
for f in "$measure" "$build/operations/texsynth-guided.so"; do
  [ -e "$f" ] || { echo "$0: $f is missing (build first)" >&2; exit 1; }
done
for name in land1 canyons2 bark granite1 rock wood1 cracked stone33 java burlap; do
  [ -f "$exemplars/$name.png" ] || { echo "$0: $exemplars/$name.png is missing" >&2; exit 1; }
done
export GEGL_PATH="$build/operations:$(pkg-config --variable=pluginsdir gegl-0.4)"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# GEGL prints a harmless leak warning after every run (README).
quiet_gegl() { gegl "$@" > "$work/gegl.log" 2>&1 || { cat "$work/gegl.log" >&2; exit 1; }; }

restyle() {  # half picture exemplar
  : > "$work/all"
  for seed in $seeds; do
    quiet_gegl -i "$work/$2.png" -o "$work/$2-$3.png" -- texsynth:guided seed="$seed" \
      aux=[ gegl:load path="$exemplars/$3.png" ]
    "$measure" --style-target="$work/$2.png" "$exemplars/$3.png" "$work/$2-$3.png" \
      > "$work/figures" 2> "$work/measure.log" || { cat "$work/measure.log" >&2; exit 1; }
    awk '/^style-correlation:/ { r = $2 } /^sharpness:/ { s = $2 } END { print r, s }' \
      "$work/figures" >> "$work/all"
  done
  awk -v half="$1" -v what="$2 by $3" '
      function median(v, n,   i, j, t) {
        for (i = 2; i <= n; i++) for (j = i; j > 1 && v[j - 1] > v[j]; j--) { t = v[j]; v[j] = v[j - 1]; v[j - 1] = t }
        return n % 2 ? v[(n + 1) / 2] : (v[n / 2] + v[n / 2 + 1]) / 2 }
      { n++; r[n] = $1; s[n] = $2; rs = rs sprintf("%s%.3f", n > 1 ? " / " : "", $1)
        ss = ss sprintf("%s%.2f", n > 1 ? " / " : "", $2) }
      END { if (n == 1) printf "| %s | %s | %.3f | %.2f |\n", half, what, r[1], s[1]
            else printf "| %s | %s | %.3f (%s) | %.2f (%s) |\n", half, what, median(r, n), rs, median(s, n), ss }' \
    "$work/all"
}

echo "| half | picture by exemplar | correlation | sharpness |"
echo "|---|---|---|---|"
for picture in land1 canyons2; do
  quiet_gegl -i "$exemplars/$picture.png" -o "$work/$picture.png" -- gegl:crop width=192 height=192
done
for e in bark granite1 rock wood1; do restyle tuning land1 "$e"; done
for e in cracked stone33 java burlap; do restyle checking canyons2 "$e"; done
