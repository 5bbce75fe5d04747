#!/usr/bin/python3
# What the layout output costs: texsynth:synthesize rendered to
# a buffer with colours and with source-map=true, median wall time of
# RUNS each, alternating, in one process (no gegl start-up); then
# gegl:map-absolute applying that map to the exemplar.
# Usage: benchmarks/source-map-cost.py [-b BUILD] [-r RUNS] [-s SIDE] EXEMPLAR.png...
# SPDX-License-Identifier: LGPL-3.0-or-later
import argparse
import os
import statistics
import sys
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
parser = argparse.ArgumentParser()
parser.add_argument("-b", "--build", default=os.path.join(ROOT, "build"))
parser.add_argument("-r", "--runs", type=int, default=5)
parser.add_argument("-s", "--side", type=int, default=1024)
parser.add_argument("exemplars", nargs="*",
                    default=[os.path.join(ROOT, "tests", "exemplars", n) for n in ("bark.png", "brick.png")])
args = parser.parse_args()
sys.path.insert(0, os.path.join(ROOT, "tests", "ops"))
import tsops  # noqa: E402
tsops.use_build_ops(args.build)
Gegl = tsops.gegl()


def timed(build):
    """Seconds to render the node that build() returns, in a new graph."""
    graph = Gegl.Node()
    node = build(graph)
    box = node.get_bounding_box()
    start = time.perf_counter()
    node.blit_buffer(None, box, 0, Gegl.AbyssPolicy.NONE)
    return time.perf_counter() - start


print("| exemplar | side | colours (s) | source map (s) | extra | map-absolute (s) |")
print("|---|---|---|---|---|---|")
for path in args.exemplars:
    def synth(source_map):
        def build(graph):
            load = graph.create_child("gegl:load")
            load.set_property("path", path)
            op = graph.create_child("texsynth:synthesize")
            for key, value in (("width", args.side), ("height", args.side), ("seed", 1),
                               ("source-map", source_map)):
                op.set_property(key, value)
            load.connect_to("output", op, "input")
            return op
        return build

    def apply_map(graph):
        load = graph.create_child("gegl:load")
        load.set_property("path", path)
        layout = synth(True)(graph)
        mapper = graph.create_child("gegl:map-absolute")
        mapper.set_property("sampler-type", Gegl.SamplerType.NEAREST)
        load.connect_to("output", mapper, "input")
        layout.connect_to("output", mapper, "aux")
        return mapper

    colours, maps, applied = [], [], []
    for _ in range(args.runs):
        colours.append(timed(synth(False)))
        maps.append(timed(synth(True)))
        applied.append(timed(apply_map) - maps[-1])
    c, m = statistics.median(colours), statistics.median(maps)
    print("| %s | %d | %.3f | %.3f | %+.1f %% | %.3f |" % (
        os.path.basename(path), args.side, c, m, 100.0 * (m - c) / c, statistics.median(applied)))
sys.stdout.flush()
