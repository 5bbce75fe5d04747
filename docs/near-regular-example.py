#!/usr/bin/python3
# Regenerates docs/near-regular-example.png: per near-regular exemplar (a
# central crop of a bundled test exemplar, at most 128x128), one row of it,
# texsynth:synthesize's 256x256 result (seed 1) and GIMP Texturize's
# (overlap 50, as benchmarks/run). Run from the source root after building:
#   docs/near-regular-example.py [BUILD_DIR]
# Needs the system python3 (PyGObject + Gegl typelib), the gegl tool, and
# GIMP 2.10 with Texturize (Debian packages gimp and gimp-texturize).
# SPDX-License-Identifier: LGPL-3.0-or-later

import os
import shutil
import subprocess
import sys
import tempfile

from panels import ROOT, node, save_on_white, save_row

EXEMPLARS = ("brick", "3dweave", "burlap")
CROP = 128
SIDE = 256
GAP = 8
OUT = os.path.join(ROOT, "docs", "near-regular-example.png")

if not shutil.which("gimp-console-2.10") or not os.path.exists("/usr/lib/gimp/2.0/plug-ins/texturize"):
    sys.exit("near-regular-example.py: needs gimp-console-2.10 and GIMP Texturize "
             "(apt-get install gimp gimp-texturize)")

tmp = tempfile.mkdtemp(prefix="texsynth-picture-")


def texturize(exemplar, out):
    """GIMP Texturize's SIDE x SIDE result from `exemplar`, in a throwaway profile."""
    script = ("(let* ((img (car (gimp-file-load RUN-NONINTERACTIVE \"%s\" \"x.png\")))"
              " (drw (car (gimp-image-get-active-drawable img))))"
              " (gimp-plugin-texturize RUN-NONINTERACTIVE img drw %d %d 50 FALSE)"
              " (let ((new (vector-ref (cadr (gimp-image-list)) 0)))"
              " (gimp-file-save RUN-NONINTERACTIVE new (car (gimp-image-get-active-drawable new))"
              " \"%s\" \"t.png\")))" % (exemplar, SIDE, SIDE, out))
    env = dict(os.environ, HOME=os.path.join(tmp, "home"))
    os.makedirs(env["HOME"], exist_ok=True)
    subprocess.run(["gimp-console-2.10", "-i", "-d", "-f", "-b", script, "-b", "(gimp-quit 0)"],
                   env=env, check=True, capture_output=True, timeout=600)
    if not os.path.exists(out):
        sys.exit("near-regular-example.py: Texturize wrote no image for " + exemplar)


rows = []
for name in EXEMPLARS:
    source = os.path.join(ROOT, "tests", "exemplars", name + ".png")
    crop = os.path.join(tmp, name + "-crop.png")
    ours = os.path.join(tmp, name + "-texsynth.png")
    theirs = os.path.join(tmp, name + "-texturize.png")
    # The central crop, written without colour chunks: GIMP 2.10 reads PNG
    # values raw, GEGL by their tags, and both must see the same pixels.
    box = node("gegl:load", path=source).get_bounding_box()
    side = min(CROP, box.width, box.height)
    subprocess.run(["gegl", "-i", source, "-o", crop, "--", "gegl:crop",
                    "x=%d" % ((box.width - side) // 2), "y=%d" % ((box.height - side) // 2),
                    "width=%d" % side, "height=%d" % side], check=True, capture_output=True)
    subprocess.run(["gegl", "-i", crop, "-o", ours, "--", "texsynth:synthesize",
                    "width=%d" % SIDE, "height=%d" % SIDE, "seed=1"], check=True, capture_output=True)
    texturize(crop, theirs)
    panels = []
    for path in (crop, ours, theirs):
        panels.append(node("gegl:load", path=path))
    row = os.path.join(tmp, name + "-row.png")
    save_row(panels, [1.0, 1.0, 1.0], row, gap=GAP)
    rows.append(row)

canvas, y, width = None, 0, 0
for row in rows:
    image = node("gegl:load", path=row)
    box = image.get_bounding_box()
    moved = node("gegl:translate", x=0.0, y=float(y))
    image.connect_to("output", moved, "input")
    if canvas is None:
        canvas = moved
    else:
        over = node("gegl:over")
        canvas.connect_to("output", over, "input")
        moved.connect_to("output", over, "aux")
        canvas = over
    y += box.height + GAP
    width = max(width, box.width)
save_on_white(canvas, width, y - GAP, OUT)
shutil.rmtree(tmp)
print(OUT)
