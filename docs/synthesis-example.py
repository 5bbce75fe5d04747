#!/usr/bin/python3
# Regenerates docs/synthesis-example.png: examples/bark.png and
# examples/brick.png, each beside texsynth:synthesize width=320 height=256
# seed=3 grown from it. Run from the source root after building:
#   docs/synthesis-example.py [BUILD_DIR]
# Needs the system python3 (PyGObject + Gegl typelib).
# SPDX-License-Identifier: LGPL-3.0-or-later

import os

from panels import ROOT, node, save_row

panels = []
for name in ("bark", "brick"):
    exemplar = node("gegl:load", path=os.path.join(ROOT, "examples", name + ".png"))
    grown = node("texsynth:synthesize", width=320, height=256, seed=3)
    exemplar.connect_to("output", grown, "input")
    panels += [exemplar, grown]
save_row(panels, [1.0] * len(panels), os.path.join(ROOT, "docs", "synthesis-example.png"), gap=8)
