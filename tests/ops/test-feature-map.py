# Matching on a feature map: texsynth:synthesize's aux, a map
# aligned with the exemplar, counts in the match. The case where it must
# help: a material whose albedo (granite1.png) says nothing of the
# structure that its height map (brick.png's grey) shows. The height map
# laid out by a synthesis that sees it must be far more coherent than one
# laid out by colour alone. Also: a feature map of another size gets a
# clear message and a transparent result; the same seed, the same result.
# Usage: test-feature-map.py --measure TEXSYNTH_MEASURE
# SPDX-License-Identifier: LGPL-3.0-or-later
import argparse
import os
import subprocess
import statistics

import tsops
from tsops import check, note

parser = argparse.ArgumentParser()
parser.add_argument("--measure", required=True)
args = parser.parse_args()
tsops.require_op()
Gegl = tsops.gegl()
work = tsops.workdir()
SIDE = 64 if tsops.small() else 128


albedo, height = os.path.join(work, "albedo.png"), os.path.join(work, "height.png")
g = Gegl.Node()
tsops.save_node(tsops.load_chain(g, tsops.exemplar("granite1.png"),
                                 ("gegl:crop", {"width": 96.0, "height": 96.0})), albedo)
tsops.save_node(tsops.load_chain(g, tsops.exemplar("brick.png"), ("gegl:gray", {})), height)


def laid_out_height(seed, weight):
    """The height map laid out by a synthesis of the albedo (with the
    height map as aux at `weight`, or without if None); its path."""
    graph = Gegl.Node()
    synth = graph.create_child("texsynth:synthesize")
    for key, value in (("width", SIDE), ("height", SIDE), ("seed", seed), ("source-map", True)):
        synth.set_property(key, value)
    tsops.load_chain(graph, albedo).connect_to("output", synth, "input")
    if weight is not None:
        synth.set_property("feature-weight", weight)
        tsops.load_chain(graph, height).connect_to("output", synth, "aux")
    path = os.path.join(work, "height-%s-%d.png" % (weight, seed))
    tsops.save_node(tsops.apply_layout(graph, tsops.load_chain(graph, height), synth), path)
    return path


note("-- the height map laid out with and without it in the match")
if tsops.small():
    for weight in (None, 1.0):
        laid_out_height(1, weight)
    note("      small-size run: both layouts made, their coherence left to the native run")
else:
    figures = {}
    for weight in (None, 1.0):
        values = [tsops.run_measure(args.measure, height, laid_out_height(seed, weight))["coherence"]
                  for seed in (1, 2)]
        figures[weight] = statistics.median(values)
        note("      feature weight %s: height coherence %s, median %.3f"
             % (weight, ", ".join("%.3f" % v for v in values), figures[weight]))
    # Measured: 3.28 without, 1.50 with (128x128, seeds 1-2); 3.3 and 1.27 at 192x192
    # (seeds 1-3, benchmarks/feature-match.py).
    check(figures[1.0] < 0.6 * figures[None],
          "with the height map in the match its layout is far more coherent: %.3f < 0.6 x %.3f"
          % (figures[1.0], figures[None]))
    check(figures[1.0] < 1.8, "height coherence with features %.3f < 1.8" % figures[1.0])

note("-- the same seed, the same result")
a = tsops.load_bytes(laid_out_height(3, 1.0), "R'G'B'A u16")
b = tsops.load_bytes(laid_out_height(3, 1.0), "R'G'B'A u16")
check(a == b, "two runs with the feature map give the same bytes")

note("-- a feature map of another size")
out = os.path.join(work, "mismatch.png")
code, _, err = tsops.run_gegl(["-i", albedo, "-o", out, "--", "texsynth:synthesize", "width=40",
                               "height=30", "aux=[", "gegl:load", "path=" + tsops.exemplar("java.png"),
                               "]"])
warnings = tsops.op_warnings(err)
check(code == 0 and any("the feature map is 64x64 but the exemplar 96x96" in w for w in warnings),
      "a clear message: %s" % warnings)
w, h, px = tsops.load(out)
check((w, h) == (40, 30) and max(tsops.alphas(px)) == 0.0, "a transparent 40x30 result")

tsops.finish()
