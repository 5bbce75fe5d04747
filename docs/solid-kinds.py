#!/usr/bin/python3
# Regenerates docs/solid-kinds.png: one row per kind of truth solid
# (benchmarks/truth-solids.h, the tuning half first, then the checking
# half), each with the exemplar (the truth's z = 0 slice), the truth's
# middle slice across x, and the middle slices across x, y and z of the
# solid the engine synthesises from that exemplar (the cell structure
# chosen automatically), all 64^3, seed 1, one pixel per voxel. The
# volumes come from build/benchmarks/solid-shapes -o, whose strip holds
# exactly those slices; --strips DIR takes the strips that
# benchmarks/solid-kinds.py -s 64 -o DIR kept (KIND-1-slices.png), the
# same images, instead of synthesising again. Run from the source root
# after building:
#   docs/solid-kinds.py [BUILD_DIR] [--strips DIR]
# Needs the system python3 (PyGObject + Gegl typelib).
# SPDX-License-Identifier: LGPL-3.0-or-later

import argparse
import os
import re
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
_parser = argparse.ArgumentParser(description="Regenerates docs/solid-kinds.png.")
_parser.add_argument("build", nargs="?", default=os.path.join(ROOT, "build"))
_parser.add_argument("--strips", help="solid-shapes' strips kept by benchmarks/solid-kinds.py -o")
_args = _parser.parse_args()
BUILD, STRIPS = _args.build, _args.strips
sys.path.insert(0, os.path.join(ROOT, "tests", "ops"))
import tsops  # noqa: E402

SIZE = 64
SEED = 1
GAP = 4               # white pixels between panels and rows
STRIP_GAP = 4         # solid-shapes' gap between the panels of its strip
COLUMNS = (0, 1, 2, 3, 4)  # exemplar, truth across x, ours across x, y, z


def kinds():
    with open(os.path.join(ROOT, "benchmarks", "truth-solids.h")) as f:
        text = f.read()
    names = []
    for half in ("TUNING", "CHECKING"):
        names += re.findall(r'"(\w+)"', re.search(r"#define TRUTH_SOLID_%s (.*)" % half, text).group(1))
    return names


def main():
    shapes = os.path.join(BUILD, "benchmarks", "solid-shapes")
    if not STRIPS and not os.access(shapes, os.X_OK):
        sys.exit("%s: not built" % shapes)
    names = kinds()
    width = len(COLUMNS) * (SIZE + GAP) - GAP
    height = len(names) * (SIZE + GAP) - GAP
    canvas = bytearray(b"\xff" * (width * height * 3))
    with tempfile.TemporaryDirectory() as scratch:
        for row, kind in enumerate(names):
            if STRIPS:
                path = os.path.join(STRIPS, "%s-%d-slices.png" % (kind, SEED))
            else:
                path = os.path.join(scratch, kind + "-slices.png")
                subprocess.run([shapes, str(SIZE), str(SEED), "-o", scratch, kind], check=True,
                               stdout=subprocess.DEVNULL)
            strip_width, strip_height, strip = tsops.load_bytes(path, "R'G'B' u8")
            if strip_height != SIZE:
                sys.exit("%s: %d pixels tall, not %d" % (path, strip_height, SIZE))
            for place, column in enumerate(COLUMNS):
                for y in range(SIZE):
                    src = (y * strip_width + column * (SIZE + STRIP_GAP)) * 3
                    dst = ((row * (SIZE + GAP) + y) * width + place * (SIZE + GAP)) * 3
                    canvas[dst:dst + SIZE * 3] = strip[src:src + SIZE * 3]
            print("%s done" % kind, flush=True)
    Gegl = tsops.gegl()
    buf = Gegl.Buffer.new("R'G'B' u8", 0, 0, width, height)
    buf.set(Gegl.Rectangle.new(0, 0, width, height), "R'G'B' u8", bytes(canvas))
    graph = Gegl.Node()
    source = graph.create_child("gegl:buffer-source")
    source.set_property("buffer", buf)
    save = graph.create_child("gegl:png-save")
    save.set_property("path", os.path.join(ROOT, "docs", "solid-kinds.png"))
    save.set_property("bitdepth", 8)
    save.set_property("compression", 9)
    source.connect_to("output", save, "input")
    save.process()
    print("wrote docs/solid-kinds.png (rows: %s)" % ", ".join(names))


if __name__ == "__main__":
    main()
