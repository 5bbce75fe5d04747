#!/usr/bin/python3
# What the GIMP dialogs' previews cost against the runs they preview: in
# one process (no gegl start-up), the wall time of texsynth:synthesize at
# the render preview's size (at most PREVIEW px a side) and at the
# result's size, and of texsynth:volume-slice (its volume synthesised
# first) for the solid preview's cube and the result's. Each run has its
# own seed, so the volume cache never answers; medians of RUNS.
# Usage: benchmarks/preview-time.py [-b BUILD] [-r RUNS] [-W WIDTH] [-H HEIGHT]
#                                   [-s SIZE] [EXEMPLAR.png...]
# SPDX-License-Identifier: LGPL-3.0-or-later
import argparse
import os
import statistics
import sys
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
# gimp-plugin/plugin-preview.h: TS_PREVIEW_SIDE, TS_PREVIEW_SOLID_SIZE.
PREVIEW_SIDE, PREVIEW_SOLID = 160, 48
parser = argparse.ArgumentParser()
parser.add_argument("-b", "--build", default=os.path.join(ROOT, "build"))
parser.add_argument("-r", "--runs", type=int, default=3)
parser.add_argument("-W", "--width", type=int, default=1024)
parser.add_argument("-H", "--height", type=int, default=768)
parser.add_argument("-s", "--size", type=int, default=128, help="the solid's edge")
parser.add_argument("exemplars", nargs="*", default=[os.path.join(ROOT, "examples", "bark.png")])
args = parser.parse_args()
sys.path.insert(0, os.path.join(ROOT, "tests", "ops"))
import tsops  # noqa: E402
tsops.use_build_ops(args.build)
Gegl = tsops.gegl()


def timed(path, op, seed, **props):
    """Seconds to render `op` on the exemplar at `path` into a buffer."""
    graph = Gegl.Node()
    load = graph.create_child("gegl:load")
    load.set_property("path", path)
    node = graph.create_child(op)
    node.set_property("seed", seed)
    for key, value in props.items():
        node.set_property(key.replace("_", "-"), value)
    load.link(node)
    load.get_bounding_box()  # the file read before the clock starts
    start = time.perf_counter()
    node.blit_buffer(None, node.get_bounding_box(), 0, Gegl.AbyssPolicy.NONE)
    return time.perf_counter() - start


def median(op, path, **props):
    return statistics.median(timed(path, op, seed, **props) for seed in range(1, args.runs + 1))


pw, ph = min(args.width, PREVIEW_SIDE), min(args.height, PREVIEW_SIDE)
ps = min(args.size, PREVIEW_SOLID)
print("| exemplar | render preview %dx%d (s) | render %dx%d (s) | solid preview %d³ (s) | "
      "solid %d³ (s) |" % (pw, ph, args.width, args.height, ps, args.size))
print("|---|---|---|---|---|")
for path in args.exemplars:
    row = [median("texsynth:synthesize", path, width=pw, height=ph),
           median("texsynth:synthesize", path, width=args.width, height=args.height),
           median("texsynth:volume-slice", path, size=ps, index=ps // 2),
           median("texsynth:volume-slice", path, size=args.size, index=args.size // 2)]
    print("| %s | %s |" % (os.path.basename(path), " | ".join("%.2f" % t for t in row)), flush=True)
