#!/usr/bin/env python3
# Image completion benchmark: heals the bundled texture cases (central
# 128x128 crops, a 40x40 square and a ~1600 px blob) and three object
# removals in GIMP's splash photo (Debian gimp-data), prints per case the
# engine time (heal-time: ts_heal alone, median of 3), the op's time
# through gegl minus that of gegl:copy on the same files, and the measures
# of texsynth-heal-measure, then the medians; then the speed and memory of
# a 1024x1024 crop with a 200x200 hole, with the whole image as context
# and with a 64-pixel context.
#
# Usage: benchmarks/heal-bench.py [BUILD_DIR]   (default: build)
# SPDX-License-Identifier: LGPL-3.0-or-later
import json
import os
import subprocess
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(ROOT, "tests", "heal"))
sys.path.insert(0, os.path.join(ROOT, "tests", "ops"))
import healcases  # noqa: E402
import tsops  # noqa: E402

build = os.path.abspath(sys.argv[1] if len(sys.argv) > 1 else os.path.join(ROOT, "build"))
heal_time = os.path.join(build, "benchmarks", "heal-time")
measure = os.path.join(build, "tools", "texsynth-heal-measure")
tsops.use_build_ops(build)
work = tempfile.mkdtemp(prefix="texsynth-heal-bench-")
exemplars = os.path.join(ROOT, "tests", "exemplars")
if not os.path.isfile(healcases.SPLASH):
    sys.exit("%s is missing: install Debian's gimp-data" % healcases.SPLASH)


def run(argv):
    proc = subprocess.run(argv, capture_output=True, text=True)
    if proc.returncode != 0:
        sys.exit("%s failed:\n%s" % (" ".join(argv), proc.stderr))
    return proc.stdout


def wall(argv, runs=3):
    times = []
    for _ in range(runs):
        t0 = time.monotonic()
        run(argv)
        times.append(time.monotonic() - t0)
    return sorted(times)[runs // 2]


def case(label, image, mask, context=0):
    out = os.path.join(work, label + "-healed.png")
    t = json.loads(run([heal_time, "-r", "3", "-c", str(context), "-o", out, image, mask]))
    op = wall(["gegl", "-i", image, "-o", os.path.join(work, "op.png"), "--", "texsynth:heal",
               "seed=1", "context=%d" % context, "aux=[", "gegl:load", "path=" + mask, "]"])
    base = wall(["gegl", "-i", image, "-o", os.path.join(work, "op.png"), "--", "gegl:copy",
                 "aux=[", "gegl:load", "path=" + mask, "]"])
    m = json.loads(run([measure, "--json", image, mask, out]))
    m.update(engine_s=t["seconds"], op_s=max(op - base, 0.0), mib=t["peak_growth_mib"])
    print("%-22s %8.2f %8.3f %8.3f %8.3f %8.3f %7.3f %7.3f %5d"
          % (label, m["fill_bds"], m["boundary"], m["boundary_original"], m["sharpness"],
             m["sharpness_original"], m["engine_s"], m["op_s"], m["outside_changed"]), flush=True)
    return m


header = "%-22s %8s %8s %8s %8s %8s %7s %7s %5s" % (
    "case", "fill_bds", "boundary", "(orig)", "sharp", "(orig)", "engine", "op", "out")
print("threads: %s, load average %.1f" % (os.environ.get("OMP_NUM_THREADS", "all"),
                                          os.getloadavg()[0]))
groups = {"textures": [], "photos": []}
print(header)
for name, make in healcases.HOLES.items():
    healcases.write_grey_png(os.path.join(work, "mask-%s.png" % name), 128, 128, make())
for tex in healcases.TEXTURES:
    image = os.path.join(work, tex + ".png")
    healcases.make_texture("gegl", os.path.join(exemplars, tex + ".png"), image)
    for name in healcases.HOLES:
        groups["textures"].append(case("%s %s" % (tex, name), image,
                                       os.path.join(work, "mask-%s.png" % name)))
for name, ((x, y), fn) in healcases.PHOTOS.items():
    image, mask = os.path.join(work, "photo-%s.png" % name), os.path.join(work, "pmask-%s.png" % name)
    run(["gegl", "-i", healcases.SPLASH, "-o", image, "--", "gegl:crop", "x=%d" % x, "y=%d" % y,
         "width=512", "height=512"])
    healcases.write_grey_png(mask, 512, 512, fn)
    groups["photos"].append(case("splash " + name, image, mask))

print()
print("%-10s %8s %8s %8s %8s %8s %7s %7s" % ("medians", "fill_bds", "boundary", "(orig)", "sharp",
                                             "(orig)", "engine", "op"))
for group, rows in groups.items():
    med = lambda k: healcases.median([r[k] for r in rows])  # noqa: E731
    print("%-10s %8.2f %8.3f %8.3f %8.3f %8.3f %7.3f %7.3f   worst boundary %.3f"
          % (group, med("fill_bds"), med("boundary"), med("boundary_original"), med("sharpness"),
             med("sharpness_original"), med("engine_s"), med("op_s"),
             max(r["boundary"] for r in rows)))

(x, y), fn = healcases.BIG
image, mask = os.path.join(work, "big.png"), os.path.join(work, "big-mask.png")
run(["gegl", "-i", healcases.SPLASH, "-o", image, "--", "gegl:crop", "x=%d" % x, "y=%d" % y,
     "width=1024", "height=1024"])
healcases.write_grey_png(mask, 1024, 1024, fn)
print()
for context in (0, 64):
    t = json.loads(run([heal_time, "-r", "3", "-c", str(context), image, mask]))
    print("1024x1024, 200x200 hole, context %-3d: engine %.3f s, memory estimate %.1f MiB "
          "(peak growth %.1f MiB)" % (context, t["seconds"], t["estimate_mib"], t["peak_growth_mib"]))
