#!/usr/bin/python3
# texsynth:tileable against gegl:tile-seamless on every exemplar, in one run.
# SPDX-License-Identifier: LGPL-3.0-or-later
#
# For each exemplar (the input), through the gegl tool:
#   ours   gegl -i IN -o OUT -- texsynth:tileable seed=S
#   gegl   gegl -i IN -o OUT -- gegl:tile-seamless
#   fresh  gegl -i IN -o OUT -- texsynth:synthesize width=W height=H tileable=true seed=S
# and prints, measured by texsynth-measure --tileable against the input:
#   seam       about 1 = seamless (target <= 1.10)
#   sharp      sharpness, mean |grad L| over the input's (target >= 0.9)
#   dE         mean CIE76 Lab distance to the input over the central half
#              (the centred rectangle of half the width and height; target <= 5)
#   coher      coherence against the input; ours must not exceed fresh's
#   fresh      coherence of a fresh tileable synthesis of the input's size
# and the time of our op. Needs the system python3 (PyGObject + Gegl typelib).
#
# Usage: benchmarks/compare-tileable.py [-b BUILD_DIR] [-e EXEMPLAR_DIR]
#          [-s SEED] [-o only,these] [-k KEEP_DIR] [-- extra texsynth:tileable properties]

import argparse
import glob
import math
import os
import shutil
import statistics
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)

parser = argparse.ArgumentParser(description="texsynth:tileable vs gegl:tile-seamless")
parser.add_argument("-b", "--build", default=os.path.join(ROOT, "build"))
parser.add_argument("-e", "--exemplars", default=os.environ.get("TEXSYNTH_EXEMPLARS")
                    or os.path.join(ROOT, "tests", "exemplars"))
parser.add_argument("-s", "--seed", type=int, default=1)
parser.add_argument("-o", "--only", help="comma-separated exemplar names (without .png)")
parser.add_argument("-k", "--keep", help="keep the results in this folder")
parser.add_argument("props", nargs="*", help="extra key=value properties of texsynth:tileable")
args = parser.parse_args()

measure_tool = os.path.join(args.build, "tools", "texsynth-measure")
sys.path.insert(0, os.path.join(ROOT, "tests", "ops"))
import tsops  # noqa: E402
tsops.use_build_ops(args.build)
tsops.gegl()


def gegl(*argv):
    start = time.monotonic()
    proc = subprocess.run(["gegl"] + list(argv), capture_output=True, text=True,
                          stdin=subprocess.DEVNULL)
    seconds = time.monotonic() - start
    problems = [l for l in proc.stderr.splitlines() if "texsynth" in l or "No such op" in l]
    if proc.returncode != 0 or problems:
        sys.exit("gegl %s failed:\n%s" % (" ".join(argv), proc.stderr))
    return seconds


def measure(exemplar, result):
    return tsops.run_measure(measure_tool, exemplar, result, tileable=True)


def lab(path):
    return tsops.load(path, "CIE Lab float")


def delta_e_central(a_path, b_path):
    w, h, a = lab(a_path)
    w2, h2, b = lab(b_path)
    if (w, h) != (w2, h2):
        return float("inf")
    x0, y0 = w // 4, h // 4
    x1, y1 = x0 + w // 2, y0 + h // 2
    total, count = 0.0, 0
    for y in range(y0, y1):
        for x in range(x0, x1):
            i = (y * w + x) * 3
            total += math.sqrt(sum((a[i + c] - b[i + c]) ** 2 for c in range(3)))
            count += 1
    return total / count


exemplars = sorted(glob.glob(os.path.join(args.exemplars, "*.png")))
if args.only:
    wanted = set(args.only.split(","))
    exemplars = [e for e in exemplars if os.path.basename(e)[:-4] in wanted]
if not exemplars:
    sys.exit("no exemplars in " + args.exemplars)
outdir = args.keep or tempfile.mkdtemp(prefix="texsynth-tileable-")
os.makedirs(outdir, exist_ok=True)

head = "%-10s %7s | %5s %5s %5s %6s %6s %5s | %6s %5s %5s %6s | %s" % (
    "exemplar", "size", "seam", "sharp", "dE", "coher", "fresh", "secs",
    "seam", "sharp", "dE", "coher", "ours better")
print("%-18s | %-39s | %-26s |" % ("", "texsynth:tileable".center(39), "gegl:tile-seamless".center(26)))
print(head)
print("-" * len(head))
rows = []
for path in exemplars:
    name = os.path.basename(path)[:-4]
    ours_png = os.path.join(outdir, name + "-tileable.png")
    gegl_png = os.path.join(outdir, name + "-tile-seamless.png")
    fresh_png = os.path.join(outdir, name + "-fresh.png")
    w, h, _ = lab(path)
    secs = gegl("-i", path, "-o", ours_png, "--", "texsynth:tileable", "seed=%d" % args.seed,
                *args.props)
    gegl("-i", path, "-o", gegl_png, "--", "gegl:tile-seamless")
    gegl("-i", path, "-o", fresh_png, "--", "texsynth:synthesize", "width=%d" % w,
         "height=%d" % h, "tileable=true", "seed=%d" % args.seed)
    ours, other, fresh = measure(path, ours_png), measure(path, gegl_png), measure(path, fresh_png)
    ours["dE"] = delta_e_central(path, ours_png)
    other["dE"] = delta_e_central(path, gegl_png)
    better = ours["seam"] < other["seam"] and ours["sharpness"] > other["sharpness"]
    ok = (ours["seam"] <= 1.10 and ours["sharpness"] >= 0.9 and ours["dE"] <= 5
          and ours["coherence"] <= fresh["coherence"])
    rows.append((name, ours, other, fresh, secs, better, ok))
    print("%-10s %7s | %5.3f %5.3f %5.2f %6.3f %6.3f %5.1f | %6.2f %5.3f %5.2f %6.3f | %s%s" % (
        name, "%dx%d" % (w, h), ours["seam"], ours["sharpness"], ours["dE"], ours["coherence"],
        fresh["coherence"], secs, other["seam"], other["sharpness"], other["dE"],
        other["coherence"], "yes" if better else "no", "" if ok else "  (misses a target)"),
        flush=True)

print("-" * len(head))


def med(key, which):
    return statistics.median(r[which][key] for r in rows)


print("%-10s %7s | %5.3f %5.3f %5.2f %6.3f %6.3f %5.1f | %6.2f %5.3f %5.2f %6.3f |" % (
    "median", "", med("seam", 1), med("sharpness", 1), med("dE", 1), med("coherence", 1),
    med("coherence", 3), statistics.median(r[4] for r in rows), med("seam", 2),
    med("sharpness", 2), med("dE", 2), med("coherence", 2)))
print()
print("targets met on %d of %d exemplars (seam <= 1.10, sharpness >= 0.9, dE <= 5, "
      "coherence <= fresh synthesis)" % (sum(r[6] for r in rows), len(rows)))
print("better seam and sharpness than gegl:tile-seamless on %d of %d"
      % (sum(r[5] for r in rows), len(rows)))
if args.keep:
    print("results in " + outdir)
else:
    shutil.rmtree(outdir, True)
