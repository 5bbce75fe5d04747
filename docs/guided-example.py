#!/usr/bin/python3
# Regenerates docs/guided-example.png (texture by numbers: a two-texture
# exemplar, its label map, a target map with text and a disc, the result)
# and docs/guided-style.png (style transfer: a picture, the style
# exemplar, the picture restyled), from tests/exemplars. Run from the
# source root after building:
#   docs/guided-example.py [BUILD_DIR]
# Needs the system python3 (PyGObject + Gegl typelib) and the gegl tool.
# SPDX-License-Identifier: LGPL-3.0-or-later

import os
import subprocess
import tempfile

from panels import ROOT, node, save_row

EXEMPLARS = os.path.join(ROOT, "tests", "exemplars")
tmp = tempfile.mkdtemp(prefix="texsynth-picture-")


def gegl(output, *chain, source=None):
    path = os.path.join(tmp, output)
    args = ["gegl"] + (["-i", source] if source else []) + ["-o", path, "--"] + list(chain)
    subprocess.run(args, check=True, capture_output=True)
    return path


def load(path):
    return node("gegl:load", path=path)


exemplar = gegl("exemplar.png", "gegl:crop", "width=128", "height=96", "gegl:over", "aux=[",
                "gegl:load", "path=" + os.path.join(EXEMPLARS, "wood1.png"), "gegl:crop",
                "width=64", "height=96", "gegl:translate", "x=64", "]",
                source=os.path.join(EXEMPLARS, "cracked.png"))
# Two flat colours that show on the white backdrop.
labels = gegl("labels.png", "gegl:color", "value=#5a6e8c", "gegl:crop", "width=128", "height=96",
              "gegl:over", "aux=[", "gegl:color", "value=#e0a040", "gegl:crop", "width=64",
              "height=96", "gegl:translate", "x=64", "]")
target = gegl("target.png", "gegl:color", "value=#5a6e8c", "gegl:crop", "width=384", "height=192",
              "gegl:over", "aux=[", "gegl:text", "string=guided", "size=80", "color=#e0a040",
              "gegl:translate", "x=40", "y=40", "]", "gegl:crop", "width=384", "height=192")
result = gegl("result.png", "texsynth:guided", "seed=3", "aux=[", "gegl:load",
              "path=" + exemplar, "]", "aux2=[", "gegl:load", "path=" + labels, "]",
              source=target)
save_row([load(exemplar), load(labels), load(target), load(result)], [2.0, 2.0, 1.0, 1.0],
         os.path.join(ROOT, "docs", "guided-example.png"))

picture = gegl("picture.png", "gegl:crop", "width=256", "height=192",
               source=os.path.join(EXEMPLARS, "land1.png"))
style = os.path.join(EXEMPLARS, "bark.png")
restyled = gegl("restyled.png", "texsynth:guided", "seed=3", "aux=[", "gegl:load",
                "path=" + style, "]", source=picture)
save_row([load(picture), load(style), load(restyled)], [1.0, None, 1.0],
         os.path.join(ROOT, "docs", "guided-style.png"))
