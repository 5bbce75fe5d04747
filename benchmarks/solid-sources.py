#!/usr/bin/python3
# Can a solid texture's source volume be recovered from its colours? (issue
# 16, part 4) The solid engine's E-step sets every voxel to one exemplar
# pixel (the vote closest to the mode of its votes, common/solid/estep.c),
# so each voxel has one source, but the engine does not output it. This
# measures what the colours alone say: for every voxel of a volume
# (texsynth:volume-slice, atlas of all slices across z, 8-bit), whether
# its colour is an exemplar pixel's, and whether that colour occurs once in
# the exemplar (the source is then certain) or more often (ambiguous: a
# map aligned with the exemplar may differ between the candidates). For
# voxels whose colour is not an exemplar pixel's, the CIE ΔE76 to the
# nearest exemplar colour.
# Usage: benchmarks/solid-sources.py [-b BUILD] [-s SIZE] [--seeds 1,2]
#        [--exemplars brick.png,bark.png]
# SPDX-License-Identifier: LGPL-3.0-or-later
import argparse
import math
import os
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(ROOT, "tests", "ops"))
parser = argparse.ArgumentParser()
parser.add_argument("-b", "--build", default=os.path.join(ROOT, "build"))
parser.add_argument("-s", "--size", type=int, default=32)
parser.add_argument("--seeds", default="1,2")
parser.add_argument("--exemplars", default="brick.png,bark.png,granite1.png")
args = parser.parse_args()
plugins = subprocess.run(["pkg-config", "--variable=pluginsdir", "gegl-0.4"],
                         capture_output=True, text=True, check=True).stdout.strip()
os.environ["GEGL_PATH"] = os.path.join(args.build, "operations") + ":" + plugins
import tsops  # noqa: E402

work = tempfile.mkdtemp()
size = args.size
columns = math.ceil(math.sqrt(size))


def pixels(data, n):
    return [bytes(data[3 * i:3 * i + 3]) for i in range(n)]


def lab(rgb):
    """CIE Lab of 8-bit sRGB (D50, as babl), for ΔE76 only."""
    def linear(c):
        c /= 255.0
        return c / 12.92 if c <= 0.04045 else ((c + 0.055) / 1.055) ** 2.4
    r, g, b = (linear(c) for c in rgb)
    # sRGB to XYZ (D50, Bradford-adapted) over the D50 white.
    x = (0.4360747 * r + 0.3850649 * g + 0.1430804 * b) / 0.9642
    y = 0.2225045 * r + 0.7168786 * g + 0.0606169 * b
    z = (0.0139322 * r + 0.0971045 * g + 0.7141733 * b) / 0.8249

    def f(t):
        return t ** (1 / 3) if t > 216 / 24389 else (24389 / 27 * t + 16) / 116
    return (116 * f(y) - 16, 500 * (f(x) - f(y)), 200 * (f(y) - f(z)))


print("size %d^3, seeds %s; per exemplar and seed: voxels whose colour is an exemplar "
      "pixel's, of those with a unique source, and the max ΔE76 of the others to the "
      "nearest exemplar colour" % (size, args.seeds))
for name in args.exemplars.split(","):
    path = tsops.exemplar(name)
    ew, eh, data = tsops.load_bytes(path, "R'G'B' u8")
    count = {}
    for p in pixels(data, ew * eh):
        count[p] = count.get(p, 0) + 1
    ex_lab = [lab(p) for p in count]
    for seed in args.seeds.split(","):
        atlas = os.path.join(work, "%s-%s.png" % (name, seed))
        code, _, err = tsops.run_gegl(["-i", path, "-o", atlas, "--", "texsynth:volume-slice",
                                       "size=%d" % size, "layout=atlas", "axis=z",
                                       "seed=%s" % seed])
        if code != 0:
            tsops.die("volume-slice failed: %s" % err)
        aw, ah, vdata = tsops.load_bytes(atlas, "R'G'B' u8")
        voxels = []
        for k in range(size):
            cx, cy = (k % columns) * size, (k // columns) * size
            for y in range(size):
                row = 3 * ((cy + y) * aw + cx)
                voxels += pixels(vdata[row:row + 3 * size], size)
        found = [v for v in voxels if v in count]
        unique = sum(1 for v in found if count[v] == 1)
        others = [v for v in voxels if v not in count]
        worst = max((min(math.dist(lab(v), e) for e in ex_lab) for v in set(others)), default=0)
        print("%-13s seed %s: %6.2f %% exemplar colours, %6.2f %% of them unique "
              "(%.2f %% of all voxels certain), %d others, max ΔE76 %.3f"
              % (name, seed, 100 * len(found) / len(voxels), 100 * unique / max(1, len(found)),
                 100 * unique / len(voxels), len(others), worst))
