# A row of GEGL image nodes on a white backdrop, saved as PNG, for the
# scripts that regenerate the pictures of the README and docs/. Importing it points GEGL
# at the build's ops (BUILD: the script's first argument, else build/
# under the source root) and GEGL's own, before Gegl.init reads GEGL_PATH.
# SPDX-License-Identifier: LGPL-3.0-or-later

import os
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
BUILD = sys.argv[1] if len(sys.argv) > 1 else os.path.join(ROOT, "build")
sys.path.insert(0, os.path.join(ROOT, "tests", "ops"))
import tsops  # noqa: E402

tsops.use_build_ops(BUILD)
Gegl = tsops.gegl()
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


def save_row(panels, ratios, path, gap=8):
    """Place the panels left to right, each scaled by its ratio (a ratio of
    None: as tall as the tallest panel before it), and save them."""
    canvas, x, top = None, 0, 0
    for panel, ratio in zip(panels, ratios):
        if ratio is None:
            ratio = top / panel.get_bounding_box().height
        placed, width, height = fit(panel, ratio, x)
        top = max(top, height)
        if canvas is None:
            canvas = placed
        else:
            over = node("gegl:over")
            canvas.connect_to("output", over, "input")
            placed.connect_to("output", over, "aux")
            canvas = over
        x += width + gap
    save_on_white(canvas, x - gap, top, path)


def save_on_white(canvas, width, height, path):
    """`canvas` over a white width x height backdrop, saved as 8-bit PNG."""
    white = node("gegl:color", value=Gegl.Color.new("white"))
    backdrop = node("gegl:crop", width=float(width), height=float(height))
    white.connect_to("output", backdrop, "input")
    flat = node("gegl:over")
    backdrop.connect_to("output", flat, "input")
    canvas.connect_to("output", flat, "aux")
    save = node("gegl:png-save", path=path, bitdepth=8)
    flat.connect_to("output", save, "input")
    save.process()
