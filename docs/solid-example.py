#!/usr/bin/python3
# Regenerates docs/solid-example.png: an exemplar, the middle slices across
# x, y and z of a 128^3 solid texture synthesised from it, at the same
# scale, and the atlas of all its slices across z (scaled down). Run from the source root after
# building:  docs/solid-example.py [BUILD_DIR] [EXEMPLAR]
# (default exemplar: land1.png from ../shared/exemplars).
# Needs the system python3 (PyGObject + Gegl typelib).
# SPDX-License-Identifier: LGPL-3.0-or-later

import os
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
build = sys.argv[1] if len(sys.argv) > 1 else os.path.join(ROOT, "build")
exemplar = sys.argv[2] if len(sys.argv) > 2 else os.path.join(ROOT, "..", "shared", "exemplars", "land1.png")
plugins = subprocess.run(["pkg-config", "--variable=pluginsdir", "gegl-0.4"],
                         capture_output=True, text=True).stdout.strip()
os.environ["GEGL_PATH"] = os.path.join(build, "operations") + ":" + plugins

import gi  # noqa: E402  (after GEGL_PATH: Gegl.init reads it)
gi.require_version("Gegl", "0.4")
from gi.repository import Gegl  # noqa: E402

SIZE = 128      # edge of the volume
SCALE = 1.25    # every panel but the atlas, at the same scale
GAP = 8
SEED = 2

Gegl.init(None)
graph = Gegl.Node()


def node(op, **props):
    n = graph.create_child(op)
    for key, value in props.items():
        n.set_property(key.replace("_", "-"), value)
    return n


def fit(source, ratio, x):
    """Scale `source` by `ratio` (nearest) and move it to x; returns (node, width, height)."""
    box = source.get_bounding_box()
    scaled = node("gegl:scale-ratio", x=ratio, y=ratio, sampler=Gegl.SamplerType.NEAREST)
    source.connect_to("output", scaled, "input")
    moved = node("gegl:translate", x=float(x), y=0.0)
    scaled.connect_to("output", moved, "input")
    return moved, int(round(box.width * ratio)), int(round(box.height * ratio))


load = node("gegl:load", path=exemplar)
panels = [load]
for axis in ("x", "y", "z"):
    cut = node("texsynth:volume-slice", size=SIZE, seed=SEED, axis=axis, index=SIZE // 2)
    load.connect_to("output", cut, "input")
    panels.append(cut)
atlas = node("texsynth:volume-slice", size=SIZE, seed=SEED, axis="z", layout="atlas")
load.connect_to("output", atlas, "input")
panels.append(atlas)

canvas, x, top = None, 0, 0
for i, panel in enumerate(panels):
    if i == len(panels) - 1:   # the atlas: as tall as the tallest panel
        ratio = top / panel.get_bounding_box().height
    else:
        ratio = SCALE
    placed, width, height = fit(panel, ratio, x)
    top = max(top, height)
    if canvas is None:
        canvas = placed
    else:
        over = node("gegl:over")
        canvas.connect_to("output", over, "input")
        placed.connect_to("output", over, "aux")
        canvas = over
    x += width + GAP
white = node("gegl:color", value=Gegl.Color.new("white"))
backdrop = node("gegl:crop", width=float(x - GAP), height=float(top))
white.connect_to("output", backdrop, "input")
flat = node("gegl:over")
backdrop.connect_to("output", flat, "input")
canvas.connect_to("output", flat, "aux")
save = node("gegl:png-save", path=os.path.join(ROOT, "docs", "solid-example.png"), bitdepth=8)
flat.connect_to("output", save, "input")
save.process()
print("wrote docs/solid-example.png")
