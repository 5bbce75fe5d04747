#!/usr/bin/python3
# Regenerates docs/tileable-before-after.png: a crop of examples/brick.png
# that does not tile (left) and texsynth:tileable's result (right), each
# repeated 2x2 and enlarged 2x. Run from the source root after building:
#   docs/tileable-before-after.py [BUILD_DIR]
# Needs the system python3 (PyGObject + Gegl typelib) and the gegl tool.
# SPDX-License-Identifier: LGPL-3.0-or-later

import os
import subprocess
import tempfile

from panels import ROOT, Gegl, graph

SCALE = 2
GAP = 8
tmp = tempfile.mkdtemp(prefix="texsynth-picture-")
before = os.path.join(tmp, "before.png")
after = os.path.join(tmp, "after.png")
crop = ["gegl:crop", "x=7", "y=11", "width=80", "height=70"]
subprocess.run(["gegl", "-i", os.path.join(ROOT, "examples", "brick.png"), "-o", before,
                "--"] + crop, check=True, capture_output=True)
subprocess.run(["gegl", "-i", before, "-o", after, "--", "texsynth:tileable", "seed=3"],
               check=True, capture_output=True)

canvas = None
x = 0
for path in (before, after):
    image = graph.create_child("gegl:load")
    image.set_property("path", path)
    box = image.get_bounding_box()
    for dx, dy in ((0, 0), (box.width, 0), (0, box.height), (box.width, box.height)):
        moved = graph.create_child("gegl:translate")
        moved.set_property("x", float(x + dx))
        moved.set_property("y", float(dy))
        image.connect_to("output", moved, "input")
        if canvas is None:
            canvas = moved
        else:
            over = graph.create_child("gegl:over")
            canvas.connect_to("output", over, "input")
            moved.connect_to("output", over, "aux")
            canvas = over
    x += 2 * box.width + GAP
white = graph.create_child("gegl:color")
white.set_property("value", Gegl.Color.new("white"))
backdrop = graph.create_child("gegl:crop")
backdrop.set_property("width", float(x - GAP))
backdrop.set_property("height", float(2 * box.height))
white.connect_to("output", backdrop, "input")
flat = graph.create_child("gegl:over")
backdrop.connect_to("output", flat, "input")
canvas.connect_to("output", flat, "aux")
scale = graph.create_child("gegl:scale-ratio")
scale.set_property("x", float(SCALE))
scale.set_property("y", float(SCALE))
scale.set_property("sampler", Gegl.SamplerType.NEAREST)
flat.connect_to("output", scale, "input")
save = graph.create_child("gegl:png-save")
save.set_property("path", os.path.join(ROOT, "docs", "tileable-before-after.png"))
save.set_property("bitdepth", 8)
scale.connect_to("output", save, "input")
save.process()
print("wrote docs/tileable-before-after.png")
