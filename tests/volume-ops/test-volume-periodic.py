# Slices of a periodic texsynth:volume-slice volume tile: texsynth-measure's
# seam figure (wrap-around neighbourhoods over the others), median over
# three slices across each axis, is at most 1.10 as for tileable 2D
# results; a non-periodic volume of the same settings measures worse, so
# the figure does see the difference.
# SPDX-License-Identifier: LGPL-3.0-or-later
#
# Usage: test-volume-periodic.py --measure PATH/texsynth-measure

import argparse
import json
import os
import statistics
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import volops  # noqa: E402
from volops import SLICE, node, tsops  # noqa: E402
from tsops import check, note  # noqa: E402

SEAM_MAX = 1.10  # tests/ops/test-quality.py's bound for tileable results
SIZE, SEED = 32, 2

parser = argparse.ArgumentParser()
parser.add_argument("--measure", default=os.environ.get("TEXSYNTH_MEASURE"))
args = parser.parse_args()
if not args.measure or not os.access(args.measure, os.X_OK):
    tsops.die("texsynth-measure not found (give --measure): %s" % args.measure)

volops.require_ops(SLICE)
Gegl = tsops.gegl()
tmp = tsops.workdir()
bark = tsops.exemplar("bark.png")


def seams(periodic):
    """The seam of three slices across each axis, measured in one run."""
    paths = []
    for axis in ("x", "y", "z"):
        for index in (3, SIZE // 2, SIZE - 4):
            path = os.path.join(tmp, "%s-%s-%d.png" % (periodic, axis, index))
            graph = Gegl.Node()
            n = node(graph, SLICE, size=SIZE, seed=SEED, periodic=periodic, axis=axis,
                     index=index)
            volops.loader(graph, bark).connect_to("output", n, "input")
            save = node(graph, "gegl:png-save", path=path, bitdepth=8)
            n.connect_to("output", save, "input")
            save.process()
            paths.append(path)
    proc = subprocess.run([args.measure, "--json", "--tileable", bark] + paths,
                          capture_output=True, text=True)
    if proc.returncode != 0:
        tsops.die("texsynth-measure failed on %s: %s" % (" ".join(paths), proc.stderr))
    return [json.loads(line)["seam"] for line in proc.stdout.splitlines()]


periodic, plain = seams(True), seams(False)
note("seam per slice (x, y, z; 3 each): periodic %s" % " ".join("%.2f" % s for s in periodic))
note("                               not periodic %s" % " ".join("%.2f" % s for s in plain))
check(statistics.median(periodic) <= SEAM_MAX,
      "periodic %d^3: median seam %.3f <= %.2f" % (SIZE, statistics.median(periodic), SEAM_MAX))
check(statistics.median(plain) > statistics.median(periodic),
      "not periodic: median seam %.3f, worse than periodic" % statistics.median(plain))

tsops.finish()
