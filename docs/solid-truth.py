#!/usr/bin/python3
# Regenerates docs/solid-truth.png: for each ground-truth solid (cells,
# blobs, grains) of
# build/benchmarks/solid-truth (128^3, seed 1), its z = 0 slice (the
# exemplar), its middle slice across x, and the middle slice across x of
# the volume texsynth:volume-slice synthesises from that exemplar (the
# cell structure chosen automatically: on for the cells, off for the
# others); for the cells, a second volume with cell-structure=off (the
# free path) beside it. Run from
# the source root after building:  docs/solid-truth.py [BUILD_DIR]
# Needs the system python3 (PyGObject + Gegl typelib).
# SPDX-License-Identifier: LGPL-3.0-or-later

import os
import subprocess
import tempfile

from panels import BUILD, ROOT, node, save_row

SIZE = 128
SEED = 1
# The ops' cell-structure values (off, on, auto).
CELL_STRUCTURE_OFF = 0
SCALE = 1.5

with tempfile.TemporaryDirectory() as scratch:
    panels = []
    for kind in ("cells", "blobs", "grains"):
        truth = os.path.join(scratch, kind + ".vol")
        subprocess.run([os.path.join(BUILD, "benchmarks", "solid-truth"), kind, str(SIZE), str(SEED), truth],
                       check=True)
        exemplar = node("texsynth:volume-load", path=truth, axis="z", index=0)
        truth_slice = node("texsynth:volume-load", path=truth, axis="x", index=SIZE // 2)
        synthesised = node("texsynth:volume-slice", size=SIZE, seed=SEED, axis="x", index=SIZE // 2)
        exemplar.connect_to("output", synthesised, "input")
        panels += [exemplar, truth_slice, synthesised]
        if kind == "cells":
            free = node("texsynth:volume-slice", size=SIZE, seed=SEED, axis="x", index=SIZE // 2,
                        cell_structure=CELL_STRUCTURE_OFF)
            exemplar.connect_to("output", free, "input")
            panels.append(free)
    save_row(panels, [SCALE] * len(panels), os.path.join(ROOT, "docs", "solid-truth.png"), gap=6)
print("wrote docs/solid-truth.png")
