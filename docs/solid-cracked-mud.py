#!/usr/bin/python3
# Regenerates docs/solid-cracked-mud.png: GIMP's ground1 pattern (cracked
# mud), then the middle slices across x and z of a 128^3 solid texture
# synthesised from it without the cell structure (cell-structure=off),
# then the same two with it (on, which the default, automatic, chooses
# for this exemplar), all at the same scale. Run from the source root
# after building:  docs/solid-cracked-mud.py [BUILD_DIR]
# Needs the system python3 (PyGObject + Gegl typelib).
# SPDX-License-Identifier: LGPL-3.0-or-later

import os

from panels import ROOT, node, save_row

SIZE = 128
SEED = 1
SCALE = 1.5

load = node("gegl:load", path=os.path.join(ROOT, "tests", "exemplars", "ground1.png"))
panels = [load]
# The ops' cell-structure values: off, on.
for cells in (0, 1):
    for axis in ("x", "z"):
        cut = node("texsynth:volume-slice", size=SIZE, seed=SEED, axis=axis, index=SIZE // 2,
                   cell_structure=cells)
        load.connect_to("output", cut, "input")
        panels.append(cut)
save_row(panels, [SCALE] * len(panels), os.path.join(ROOT, "docs", "solid-cracked-mud.png"))
print("wrote docs/solid-cracked-mud.png")
