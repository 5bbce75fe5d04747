# texsynth:heal on the gegl tool's graphs: pixels outside the hole kept
# bit for bit (8 and 16 bits, RGB and RGBA), determinism at 1 and 2 threads,
# heal transparency (partial alpha blended), an aux2 source, the measured
# quality of the bundled cases (texsynth-heal-measure) and bad input. The
# determinism runs are gegl tool runs, one process each (the thread count
# is fixed at start); the others run in this process on the graph the tool
# builds from the same arguments (tsops.run_gegl_here), sparing a GEGL
# start-up each.
# SPDX-License-Identifier: LGPL-3.0-or-later
#
# Usage: test-heal-op.py --measure PATH-OF-texsynth-heal-measure

import argparse
import json
import os
import struct
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "ops"))
sys.path.insert(0, HERE)
import tsops  # noqa: E402
from tsops import check, die, exemplar, finish, note  # noqa: E402
import healcases  # noqa: E402

OP = "texsynth:heal"
tsops.OP = OP
tsops.PREFIX = PREFIX = OP + ": "

# Each limit sits between the figures of the bundled cases over seeds (the
# test's seed 1, then seed 2) and those of a clearly worse fill: the same
# fills blurred by a 5x5 box ("blurred"), or the texture 64 pixels away
# pasted into the hole ("pasted").
# - median boundary: 0.865, 0.844; blurred 1.11, pasted 3.81;
# - worst boundary of a case: 1.19, 1.30; blurred 1.58, pasted at least
#   1.86 in every case;
# - median fill sharpness: 0.914, 0.908; blurred 0.43;
# - median fill_bds: 10.10, 10.30; blurred 10.86, pasted 11.11 (a plain
#   best-patch vote reaches 12.5).
BOUNDARY_MEDIAN_MAX = 1.0
BOUNDARY_EACH_MAX = 1.45
SHARPNESS_MEDIAN_MIN = 0.70
FILL_BDS_MEDIAN_MAX = 10.6

parser = argparse.ArgumentParser()
parser.add_argument("--measure", required=True)
args = parser.parse_args()

tsops.require_op()
Gegl = tsops.gegl()
work = tsops.workdir()


def path(name):
    return os.path.join(work, name)


def heal(src, dst, mask=None, source=None, env=None, **props):
    """gegl -i src -o dst -- texsynth:heal props [aux=mask] [aux2=source],
    in this process, or with `env` through the gegl tool; returns the op's
    warning lines."""
    argv = ["-i", src, "-o", dst, "--", OP]
    argv += ["%s=%s" % (k.replace("_", "-"), v) for k, v in props.items()]
    if mask:
        argv += ["aux=[", "gegl:load", "path=" + mask, "]"]
    if source:
        argv += ["aux2=[", "gegl:load", "path=" + source, "]"]
    code, _, err = tsops.run_gegl(argv, env=env) if env else tsops.run_gegl_here(argv)
    if code != 0 or not os.path.isfile(dst):
        die("gegl %s failed (exit %d):\n%s" % (" ".join(argv), code, err))
    return tsops.op_warnings(err)


def pixels(p, fmt):
    w, h, data = tsops.load_bytes(p, fmt)
    bpp = len(data) // (w * h)
    return w, h, [data[i * bpp:(i + 1) * bpp] for i in range(w * h)]


def mask_of(mask_fn, w, h):
    return [bool(mask_fn(x, y)) for y in range(h) for x in range(w)]


def changed_outside(a, b, hole):
    return sum(1 for pa, pb, inside in zip(a, b, hole) if not inside and pa != pb)


def changed_inside(a, b, hole):
    return sum(1 for pa, pb, inside in zip(a, b, hole) if inside and pa != pb)


def measure_argv(cases, json_output=True):
    """texsynth-heal-measure's arguments for each (original, mask or None,
    result) of `cases`, as lists joined by '+'."""
    argv = [args.measure]
    for original, mask, result in cases:
        argv += (["+"] if len(argv) > 1 else []) + (["--json"] if json_output else [])
        argv += (["--hole-from-alpha", original] if mask is None else [original, mask]) + [result]
    return argv


def measure_all(cases):
    """The figures of every case, in one run (one GEGL start-up)."""
    argv = measure_argv(cases)
    proc = subprocess.run(argv, capture_output=True, text=True)
    figures = [json.loads(line) for line in proc.stdout.splitlines()]
    if proc.returncode != 0 or len(figures) != len(cases):
        die("%s failed:\n%s" % (" ".join(argv), proc.stderr))
    return figures


def measure(original, mask, result):
    return measure_all([(original, mask, result)])[0]


def save_rgba(p, w, h, fn, bitdepth=8):
    """fn(x, y) -> (r, g, b, a) floats."""
    px = []
    for y in range(h):
        for x in range(w):
            px.extend(fn(x, y))
    buf = Gegl.Buffer.new("R'G'B'A float", 0, 0, w, h)
    buf.set(Gegl.Rectangle.new(0, 0, w, h), "R'G'B'A float", struct.pack("%df" % len(px), *px))
    tsops.save_buffer(buf, p, bitdepth)


# --- the bundled cases: quality, outside pixels, determinism -----------------
gegl_tool = tsops.gegl_binary()
texture = lambda *a, **k: healcases.make_texture(gegl_tool, *a, run_gegl=tsops.run_gegl_here, **k)
masks = {}
for name, make in healcases.HOLES.items():
    masks[name] = path("mask-%s.png" % name)
    healcases.write_grey_png(masks[name], 128, 128, make())

cases = []
for tex in healcases.TEXTURES:
    src = path("%s.png" % tex)
    texture(exemplar(tex + ".png"), src)
    w, h, before = pixels(src, "R'G'B' u16")
    for hole_name, make in healcases.HOLES.items():
        dst = path("%s-%s.png" % (tex, hole_name))
        warnings = heal(src, dst, masks[hole_name], seed=1)
        check(not warnings, "%s %s: no warning (%s)" % (tex, hole_name, warnings))
        _, _, after = pixels(dst, "R'G'B' u16")
        hole = mask_of(make(), w, h)
        check(changed_outside(before, after, hole) == 0,
              "%s %s: every pixel outside the hole is bit-identical (16-bit RGB)" % (tex, hole_name))
        check(changed_inside(before, after, hole) > 0.5 * sum(hole),
              "%s %s: the hole was filled" % (tex, hole_name))
        cases.append(("%s %s" % (tex, hole_name), (src, masks[hole_name], dst)))

if tsops.small():
    note("      small-size run: the cases' quality is not measured here")
else:
    # Measured all in one run.
    figures = measure_all([case for _, case in cases])
    for (label, _), m in zip(cases, figures):
        note("      %s: fill_bds %.2f boundary %.3f (original %.3f) sharpness %.3f"
             % (label, m["fill_bds"], m["boundary"], m["boundary_original"], m["sharpness"]))
        check(m["outside_changed"] == 0, "%s: the measure sees no change outside" % label)
        check(m["boundary"] <= BOUNDARY_EACH_MAX, "%s: boundary %.3f <= %.2f"
              % (label, m["boundary"], BOUNDARY_EACH_MAX))
    # A case's figures do not depend on the others measured in the same run;
    # in text, each list's figures follow a line naming its result.
    (label, first), (_, second) = cases[0], cases[1]
    check(measure(*first) == figures[0], "%s: the same figures measured alone" % label)
    proc = subprocess.run(measure_argv([first, second], json_output=False),
                          capture_output=True, text=True)
    check(proc.returncode == 0 and [line for line in proc.stdout.splitlines()
                                    if line.startswith("result: ")]
          == ["result: " + first[2], "result: " + second[2]],
          "two argument lists in text: each after its 'result: PATH' line")

    med = {k: healcases.median([m[k] for m in figures]) for k in ("fill_bds", "boundary", "sharpness")}
    note("      medians: fill_bds %.2f boundary %.3f sharpness %.3f"
         % (med["fill_bds"], med["boundary"], med["sharpness"]))
    check(med["boundary"] <= BOUNDARY_MEDIAN_MAX, "median boundary %.3f <= %.2f"
          % (med["boundary"], BOUNDARY_MEDIAN_MAX))
    check(med["sharpness"] >= SHARPNESS_MEDIAN_MIN, "median fill sharpness %.3f >= %.2f"
          % (med["sharpness"], SHARPNESS_MEDIAN_MIN))
    check(med["fill_bds"] <= FILL_BDS_MEDIAN_MAX, "median fill_bds %.2f <= %.1f"
          % (med["fill_bds"], FILL_BDS_MEDIAN_MAX))

# Same seed, same result at 1 and 2 threads (two processes each).
brick = path("brick.png")
texture(exemplar("brick.png"), brick, tile=True)
runs = []
for threads in ("1", "2", "2"):
    dst = path("brick-threads-%s-%d.png" % (threads, len(runs)))
    heal(brick, dst, masks["blob"], env={"OMP_NUM_THREADS": threads}, seed=7, quality=3)
    runs.append(tsops.load_bytes(dst, "R'G'B' u16")[2])
check(runs[0] == runs[1] == runs[2], "seed 7: bit-identical results at 1, 2 and 2 threads")
other = path("brick-seed-8.png")
heal(brick, other, masks["blob"], seed=8, quality=3)
check(tsops.load_bytes(other, "R'G'B' u16")[2] != runs[0], "another seed gives another fill")

# Options: context, sample-from, patch sizes; outside kept with each.
_, _, before = pixels(brick, "R'G'B' u16")
square_hole = mask_of(healcases.square(128, 128, 40), 128, 128)
for props in ({"context": 30}, {"sample_from": "sides"}, {"sample_from": "above-below"},
              {"patch_size": 9, "fine_patch_size": 5}, {"quality": 1}):
    dst = path("brick-options.png")
    warnings = heal(brick, dst, masks["square"], seed=2, **props)
    _, _, after = pixels(dst, "R'G'B' u16")
    check(not warnings and changed_outside(before, after, square_hole) == 0
          and changed_inside(before, after, square_hole) > 800,
          "%s: fills the hole, nothing outside changes" % props)

# --- 8-bit RGBA and heal transparency -------------------------------------------
w8, h8, rgb = tsops.load(brick, "R'G'B'A float")


def transparent_square(x, y):
    i = (y * 128 + x) * 4
    inside = 40 <= x < 80 and 40 <= y < 80
    ring = 36 <= x < 84 and 36 <= y < 84 and not inside
    return (rgb[i], rgb[i + 1], rgb[i + 2], 0.0 if inside else 0.5 if ring else 1.0)


holed = path("brick-holed-rgba8.png")
save_rgba(holed, 128, 128, transparent_square)
healed = path("brick-healed-rgba8.png")
warnings = heal(holed, healed, seed=1)
_, _, before = pixels(holed, "R'G'B'A u8")
_, _, after = pixels(healed, "R'G'B'A u8")
transparent = [before[p][3] < 255 for p in range(128 * 128)]
check(not warnings, "heal transparency: no warning (%s)" % warnings)
check(changed_outside(before, after, transparent) == 0,
      "heal transparency: every opaque pixel is bit-identical (8-bit RGBA)")
check(all(after[p][3] == 255 for p in range(128 * 128) if transparent[p]),
      "heal transparency: the filled and the half transparent pixels become opaque")
# A half transparent pixel keeps what it showed: its colour is between
# the original's and the fill's, so it stays near the original on average.
ring = [p for p in range(128 * 128) if 0 < before[p][3] < 255]
diff = sum(abs(after[p][c] - before[p][c]) for p in ring for c in range(3)) / (3.0 * len(ring))
check(diff < 40, "heal transparency: half transparent pixels are blended (mean step %.1f of 255)" % diff)
m = measure(holed, None, healed)
check(m["outside_changed"] == 0 and m["hole_pixels"] == 48 * 48,
      "heal transparency: the measure finds the %d transparent pixels (of %d) and nothing else "
      "changed (%d)" % (m["hole_pixels"], 48 * 48, m["outside_changed"]))

# aux2: another image to copy from.
source = path("bark-source.png")
texture(exemplar("bark.png"), source, side=96, tile=True)
dst = path("brick-from-bark.png")
warnings = heal(brick, dst, masks["square"], source=source, seed=1)
_, _, before = pixels(brick, "R'G'B' u16")
_, _, after = pixels(dst, "R'G'B' u16")
check(not warnings and changed_outside(before, after, square_hole) == 0
      and changed_inside(before, after, square_hole) > 800,
      "aux2: fills the hole from another image, nothing outside changes")

# --- bad input: a clear message and the input back untouched ------------------


def expect_unchanged(label, src, mask, fragment, fmt="R'G'B' u16", **props):
    dst = path("bad.png")
    if os.path.exists(dst):
        os.remove(dst)
    warnings = heal(src, dst, mask, **props)
    same = tsops.load_bytes(src, fmt)[2] == tsops.load_bytes(dst, fmt)[2]
    if fragment is None:
        check(same and not warnings, "%s: the input comes back unchanged, silently" % label)
    else:
        check(same, "%s: the input comes back unchanged" % label)
        check(any(PREFIX in w and fragment in w for w in warnings),
              "%s: warning mentions %r (%s)" % (label, fragment, warnings))


empty = path("mask-empty.png")
healcases.write_grey_png(empty, 128, 128, lambda x, y: 0)
full = path("mask-full.png")
healcases.write_grey_png(full, 128, 128, lambda x, y: 255)
expect_unchanged("empty mask", brick, empty, None)
expect_unchanged("mask covering everything", brick, full, "nothing to fill the hole from")
expect_unchanged("context too small to hold a patch", brick, masks["square"], "too small",
                 context=3)
expect_unchanged("opaque image without a mask", brick, None, None)
clear = path("clear.png")
save_rgba(clear, 64, 64, lambda x, y: (0.5, 0.5, 0.5, 0.0))
expect_unchanged("fully transparent image", clear, None, "no fully opaque pixel",
                 fmt="R'G'B'A u8")
expect_unchanged("sides of a hole spanning the width", brick,
                 path("mask-band.png"), "nothing to fill", sample_from="sides") \
    if healcases.write_grey_png(path("mask-band.png"), 128, 128,
                                lambda x, y: 255 if 50 <= y < 70 else 0) is None else None

# A mask of another size is read at the image's coordinates: a 64x64 mask
# with a 20x20 square heals that square; the rest of the image is kept.
small = path("mask-small.png")
healcases.write_grey_png(small, 64, 64, healcases.square(64, 64, 20, 30, 30))
stone = path("stone33.png")
dst = path("stone-small-mask.png")
warnings = heal(stone, dst, small, seed=1)
_, _, before = pixels(stone, "R'G'B' u16")
_, _, after = pixels(dst, "R'G'B' u16")
small_hole = [20 <= x < 40 and 20 <= y < 40 for y in range(128) for x in range(128)]
check(not warnings and changed_outside(before, after, small_hole) == 0
      and changed_inside(before, after, small_hole) > 200,
      "a smaller mask heals its square at the image's coordinates and keeps the rest")

finish()
