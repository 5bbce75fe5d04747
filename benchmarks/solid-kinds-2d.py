#!/usr/bin/python3
# Whether the 2D engine keeps each truth kind's shapes, as a baseline for
# the solid engine: per kind of truth-solids.h, the truth's z = 0 slice
# (the exemplar solid-kinds.py grows solids from) is synthesised in 2D by
# texsynth:synthesize at the same size, and each phase's solidity
# (texsynth-measure --shapes) is divided by the median over the truth's
# middle slices across x, y, z and the diagonal. A ratio near 1 here and
# below 0.95 in solid-kinds.py says the shapes are lost between the
# three orientations, not by the patch optimisation itself.
# SPDX-License-Identifier: LGPL-3.0-or-later
#
# Usage: benchmarks/solid-kinds-2d.py [-b BUILD] [-s SIZE] [-k KIND,...] [SEED ...]
# Needs python3-gi with the Gegl typelib (run with /usr/bin/python3).

import argparse
import importlib.util
import json
import os
import statistics
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
_spec = importlib.util.spec_from_file_location("solid_kinds", os.path.join(HERE, "solid-kinds.py"))
solid_kinds = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(solid_kinds)


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("-b", "--build", default="build")
    parser.add_argument("-s", "--size", type=int, default=128)
    parser.add_argument("-k", "--kinds", default="")
    parser.add_argument("seeds", nargs="*", type=int, default=[1, 2, 3])
    args = parser.parse_args()
    tuning, checking = solid_kinds.halves()
    kinds = args.kinds.split(",") if args.kinds else tuning + checking
    plugins = subprocess.run(["pkg-config", "--variable=pluginsdir", "gegl-0.4"], capture_output=True,
                             text=True, check=True).stdout.strip()
    env = dict(os.environ, GEGL_PATH=os.path.join(args.build, "operations") + ":" + plugins)
    size = args.size
    print("2D synthesis of each truth's exemplar at %d^2, seeds %s: solidity over the truth's"
          % (size, " ".join(map(str, args.seeds))))
    with tempfile.TemporaryDirectory(prefix="texsynth-kinds-2d-") as scratch:
        for kind in kinds:
            half = "tuning" if kind in tuning else "checking"
            vol = os.path.join(scratch, kind + ".vol")
            subprocess.run([os.path.join(args.build, "benchmarks", "solid-truth"), kind, str(size), "1", vol],
                           check=True)
            exemplar, truth = solid_kinds.truth_slices(vol, size, scratch, kind)
            os.remove(vol)
            results = []
            for seed in args.seeds:
                result = os.path.join(scratch, "%s-2d-%d.png" % (kind, seed))
                subprocess.run(["gegl", "-i", exemplar, "-o", result, "--", "texsynth:synthesize",
                                "width=%d" % size, "height=%d" % size, "seed=%d" % seed],
                               check=True, env=env, capture_output=True)
                results.append(result)
            phases = 3 if kind in solid_kinds.THREE_PHASES else 2
            middle = truth[:solid_kinds.TRUTH_MIDDLE]
            out = subprocess.run([os.path.join(args.build, "tools", "texsynth-measure"), "--shapes", "--json",
                                  "--phases=%d" % phases, exemplar] + middle + results,
                                 capture_output=True, text=True, check=True)
            images = json.loads(out.stdout)["images"]
            ratios = []
            for p in range(phases):
                reference = statistics.median(i["phases"][p]["solidity"] for i in images[1:1 + len(middle)])
                ours = [i["phases"][p]["solidity"] for i in images[1 + len(middle):]]
                ratios.append(statistics.median(ours) / reference if reference else float("nan"))
            print("%-10s %-8s solidity %s" % (kind, half, ", ".join("%.3f" % r for r in ratios)), flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
