#!/usr/bin/python3
# Regenerates docs/solid-example.png: an exemplar, the middle slices across
# x, y and z of a 128^3 solid texture synthesised from it, at the same
# scale, and the atlas of all its slices across z (scaled down). Run from the source root after
# building:  docs/solid-example.py [BUILD_DIR] [EXEMPLAR]
# (default exemplar: the bundled tests/exemplars/land1.png).
# Needs the system python3 (PyGObject + Gegl typelib).
# SPDX-License-Identifier: LGPL-3.0-or-later

import os
import sys

from panels import ROOT, node, save_row

exemplar = sys.argv[2] if len(sys.argv) > 2 else os.path.join(ROOT, "tests", "exemplars", "land1.png")

SIZE = 128      # edge of the volume
SCALE = 1.25    # every panel but the atlas, at the same scale
SEED = 2

load = node("gegl:load", path=exemplar)
panels = [load]
for axis in ("x", "y", "z"):
    cut = node("texsynth:volume-slice", size=SIZE, seed=SEED, axis=axis, index=SIZE // 2)
    load.connect_to("output", cut, "input")
    panels.append(cut)
atlas = node("texsynth:volume-slice", size=SIZE, seed=SEED, axis="z", layout="atlas")
load.connect_to("output", atlas, "input")
panels.append(atlas)
# The atlas as tall as the tallest panel.
save_row(panels, [SCALE] * 4 + [None], os.path.join(ROOT, "docs", "solid-example.png"))
print("wrote docs/solid-example.png")
