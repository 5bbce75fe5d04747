#!/usr/bin/python3
# How well does a solid texture's recorded source volume reproduce it, and
# how much would its colours alone say? For each
# exemplar and seed, texsynth:volume-save writes the colour volume and the
# source volume (content=source: x, y, orientation per voxel) as .dds
# files. The sources applied to the exemplar's 8-bit pixels must give the
# colour volume exactly (100 % of voxels). For comparison, the fraction of
# voxels whose colour occurs once in the exemplar: the only ones whose
# source the colours alone would name for certain (8-bit exemplars repeat
# colours), so a map laid out from colours would be wrong elsewhere.
# Usage: benchmarks/solid-sources.py [-b BUILD] [-s SIZE] [--seeds 1,2]
#        [--exemplars brick.png,bark.png]
# SPDX-License-Identifier: LGPL-3.0-or-later
import argparse
import os
import struct
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
import tsops  # noqa: E402
tsops.use_build_ops(args.build)

DDS_DATA = 148  # "DDS ", DDS_HEADER, DDS_HEADER_DXT10
work = tempfile.mkdtemp()
size = args.size
voxels = size ** 3


def save(path, exemplar, seed, *extra):
    code, _, err = tsops.run_gegl(["-i", exemplar, "--", "texsynth:volume-save", "path=" + path,
                                   "size=%d" % size, "seed=%s" % seed] + list(extra))
    if code != 0 or not os.path.isfile(path):
        tsops.die("volume-save failed: %s" % err)
    with open(path, "rb") as f:
        return f.read()[DDS_DATA:]


print("size %d^3, seeds %s; per exemplar and seed: voxels the recorded sources reproduce "
      "exactly, and voxels whose colour alone names a single exemplar pixel" % (size, args.seeds))
failed = False
for name in args.exemplars.split(","):
    path = tsops.exemplar(name)
    ew, eh, rgba = tsops.load_bytes(path, "R'G'B'A u8")
    count = {}
    for i in range(ew * eh):
        key = bytes(rgba[4 * i:4 * i + 4])
        count[key] = count.get(key, 0) + 1
    for seed in args.seeds.split(","):
        colour = save(os.path.join(work, "colour.dds"), path, seed)
        sources = save(os.path.join(work, "sources.dds"), path, seed, "content=source")
        values = struct.unpack("<%dH" % (voxels * 4), sources)
        exact = 0
        for v in range(voxels):
            x, y = values[4 * v], values[4 * v + 1]
            i = 4 * (y * ew + x)
            exact += x < ew and y < eh and rgba[i:i + 4] == colour[4 * v:4 * v + 4]
        unique = sum(1 for v in range(voxels) if count.get(colour[4 * v:4 * v + 4]) == 1)
        failed = failed or exact != voxels
        print("%-13s seed %s: sources exact for %6.2f %% of voxels; colour alone certain "
              "for %6.2f %%" % (name, seed, 100 * exact / voxels, 100 * unique / voxels))
sys.exit(1 if failed else 0)
