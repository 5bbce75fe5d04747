#!/usr/bin/python3
# Does a feature map help the match? A material whose structure
# is clearer in its height map than in its albedo: albedo = brick.png at a
# quarter of its contrast under per-pixel colour noise (the brick courses
# hard to see), height = brick.png's grey (courses and mortar plain).
# For each feature weight, texsynth:synthesize lays out the albedo (with
# the height map as aux, or without), the same layout is applied to the
# height map with gegl:map-absolute, and texsynth-measure compares the
# laid-out height map with the height exemplar: coherence (lower is
# better: every window of the result has a close window in the exemplar)
# and completeness. Medians over seeds.
# Usage: benchmarks/feature-match.py [-b BUILD] [-s SIDE] [--seeds 1,2,3] [-k DIR]
# SPDX-License-Identifier: LGPL-3.0-or-later
import argparse
import os
import statistics
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(ROOT, "tests", "ops"))
parser = argparse.ArgumentParser()
parser.add_argument("-b", "--build", default=os.path.join(ROOT, "build"))
parser.add_argument("-s", "--side", type=int, default=192)
parser.add_argument("--seeds", default="1,2,3,4,5")
parser.add_argument("--weights", default="none,0.5,1,2")
parser.add_argument("-k", "--keep", help="keep the images in this folder")
args = parser.parse_args()
import tsops  # noqa: E402
tsops.use_build_ops(args.build)

Gegl = tsops.gegl()
work = args.keep or tempfile.mkdtemp()
os.makedirs(work, exist_ok=True)
brick = os.path.join(ROOT, "tests", "exemplars", "brick.png")
granite = os.path.join(ROOT, "tests", "exemplars", "granite1.png")


albedo, height = os.path.join(work, "albedo.png"), os.path.join(work, "height.png")
g = Gegl.Node()
tsops.save_node(tsops.load_chain(g, granite, ("gegl:crop", {"width": 96.0, "height": 96.0})), albedo)
tsops.save_node(tsops.load_chain(g, brick, ("gegl:gray", {})), height)

measure = os.path.join(args.build, "tools", "texsynth-measure")
print("albedo %s (granite1.png, 96x96), height %s (brick.png's grey), %dx%d, seeds %s"
      % (albedo, height, args.side, args.side, args.seeds))
print("| feature weight | height coherence | height completeness | albedo coherence |")
print("|---|---|---|---|")
for weight in args.weights.split(","):
    rows = []
    for seed in (int(s) for s in args.seeds.split(",")):
        graph = Gegl.Node()
        ex = tsops.load_chain(graph, albedo)
        synth = graph.create_child("texsynth:synthesize")
        for key, value in (("width", args.side), ("height", args.side), ("seed", seed),
                           ("source-map", True)):
            synth.set_property(key, value)
        ex.connect_to("output", synth, "input")
        if weight != "none":
            synth.set_property("feature-weight", float(weight))
            tsops.load_chain(graph, height).connect_to("output", synth, "aux")
        outputs = {}
        for name, path in (("height", height), ("albedo", albedo)):
            outputs[name] = os.path.join(work, "%s-w%s-s%d.png" % (name, weight, seed))
            tsops.save_node(tsops.apply_layout(graph, tsops.load_chain(graph, path), synth),
                            outputs[name])
        h = tsops.run_measure(measure, height, outputs["height"])
        a = tsops.run_measure(measure, albedo, outputs["albedo"])
        rows.append((h["coherence"], h["completeness"], a["coherence"]))
    print("| %s | %.3f | %.3f | %.3f |" % (
        weight, *(statistics.median(r[i] for r in rows) for i in range(3))))
    sys.stdout.flush()
