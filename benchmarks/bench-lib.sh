# Shell helpers shared by the benchmark scripts (sourced, not run).
# SPDX-License-Identifier: LGPL-3.0-or-later

# Median of the numbers on standard input (space or newline separated);
# "nan" for none.
median() {
  tr ' ' '\n' | grep . | sort -g |
    awk '{ v[NR] = $1 } END { if (NR == 0) print "nan"; else print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'
}

# png_size FILE: prints "width height" (big-endian 32-bit at bytes 16, 20).
png_size() {
  od -An -tu1 -j16 -N8 "$1" |
    awk '{ print ($1 * 2^24 + $2 * 2^16 + $3 * 256 + $4), ($5 * 2^24 + $6 * 2^16 + $7 * 256 + $8) }'
}

# crop_central SIDE DIR FILE...: writes the SIDE x SIDE central crop of
# every FILE at least that large into DIR (same name) and prints the new
# paths, one a line; smaller files are skipped.
crop_central() {
  local side=$1 dir=$2 ex w h out
  shift 2
  for ex in "$@"; do
    read -r w h < <(png_size "$ex")
    [ "${w:-0}" -ge "$side" ] && [ "${h:-0}" -ge "$side" ] || continue
    out="$dir/$(basename "$ex")"
    gegl -i "$ex" -o "$out" -- gegl:crop x=$(( (w - side) / 2 )) y=$(( (h - side) / 2 )) \
      width="$side" height="$side" >/dev/null 2>&1
    echo "$out"
  done
}

# use_ops BUILD OP...: points gegl at BUILD's op modules (and GEGL's own,
# which GEGL_PATH would otherwise hide), one gegl thread, and exits unless
# every OP is found: an unknown op is no error to gegl, it passes the image
# through.
use_ops() {
  local build=$1 plugins op
  shift
  plugins=$(pkg-config --variable=pluginsdir gegl-0.4 2>/dev/null || echo /usr/lib/x86_64-linux-gnu/gegl-0.4)
  export GEGL_PATH="$build/operations:$plugins" GEGL_THREADS=1
  for op in "$@"; do
    if ! gegl --exists "$op" >/dev/null 2>&1; then
      echo "$op not found in $build/operations: build first (meson setup build && ninja -C build)" >&2
      exit 1
    fi
  done
}
