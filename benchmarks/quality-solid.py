#!/usr/bin/env python3
# Quality of solid synthesis (texsynth:volume-save) on every exemplar:
# synthesise a SIZE^3 periodic volume per exemplar, cut the middle slices
# across x, y and z and one diagonal slice (the plane x = z, sampled at
# unit spacing), measure each against the exemplar with texsynth-measure,
# and compare the medians with a 2D texsynth:synthesize result of the same
# size (tileable, since the volume is periodic).
# SPDX-License-Identifier: LGPL-3.0-or-later
#
# Two references say what the figures can reach at all:
#   --fresh  an unseen piece of the same photograph: each exemplar's right
#            half measured against its left half, beside a 2D synthesis
#            from the left half of the right half's size;
#   --truth  ground-truth solids (build/benchmarks/solid-truth): periodic,
#            isotropic volumes whose z = 0 slice is the exemplar, so their
#            own middle slices are what a perfect solid scores; the
#            synthesised volume from that exemplar is measured beside them.
#
# Run with the system Python (PyGObject + the Gegl typelib) and GEGL_PATH
# listing build/operations and GEGL's own folder, e.g.
#   GEGL_PATH=build/operations:$(pkg-config --variable=pluginsdir gegl-0.4) \
#     /usr/bin/python3 benchmarks/quality-solid.py --measure build/tools/texsynth-measure
#
# The seam figures are means over 4 slices per axis, across the wrap-around
# edges and, for comparison, across the slices' middle lines.
#
# Targets: slice coherence median <= 1.5 x the 2D median,
# completeness <= 1.2, copy <= 0.5, seam <= 1.10 across the boundary.

import argparse
import glob
import os
import statistics
import subprocess
import time

from solidslices import axis_slice, measure_volume, read_vol, save_rgb, tsops

parser = argparse.ArgumentParser(description="Quality of texsynth solid synthesis")
parser.add_argument("--measure", default=os.environ.get("TEXSYNTH_MEASURE", "build/tools/texsynth-measure"))
parser.add_argument("--size", type=int, default=128)
parser.add_argument("--seed", type=int, default=1)
parser.add_argument("--only", help="comma-separated exemplar names (without .png) or solid kinds")
parser.add_argument("--keep", help="keep volumes and slices in this folder")
parser.add_argument("--fresh", action="store_true", help="add the unseen-half reference per exemplar")
parser.add_argument("--truth", action="store_true", help="measure on ground-truth solids instead")
parser.add_argument("--truth-tool", default="build/benchmarks/solid-truth")
args = parser.parse_args()

outdir = args.keep or tsops.workdir()
os.makedirs(outdir, exist_ok=True)


def measure(exemplar, result, tileable):
    return tsops.run_measure(args.measure, exemplar, result, tileable)


def synthesize_volume(exemplar, vol_path, name):
    start = time.time()
    code, out, err = tsops.run_gegl(["-i", exemplar, "--", "texsynth:volume-save", "path=" + vol_path,
                                     "size=%d" % args.size, "seed=%d" % args.seed], timeout=3600)
    if code != 0 or not os.path.exists(vol_path):
        tsops.die("volume-save failed for %s:\n%s%s" % (name, out, err))
    return time.time() - start


def coherence_2d(exemplar, path, width, height, tileable):
    code, out, err = tsops.synthesize_cli(exemplar, path, width=width, height=height,
                                          seed=args.seed, tileable=tileable)
    if code != 0:
        tsops.die("texsynth:synthesize failed for %s:\n%s%s" % (exemplar, out, err))
    return measure(exemplar, path, tileable)["coherence"]


def fresh_reference(exemplar, name):
    """An unseen piece of the texture against a 2D synthesis: the right half
    measured against the left half, and a synthesis from the left half."""
    w, h, rgb = tsops.load_bytes(exemplar, "R'G'B' u8")
    half = w // 2
    paths = [os.path.join(outdir, "%s-%s.png" % (name, side)) for side in ("left", "right")]
    for path, x0 in zip(paths, (0, half)):
        save_rgb(path, half, h, b"".join(rgb[(y * w + x0) * 3:(y * w + x0 + half) * 3] for y in range(h)))
    fresh = measure(paths[0], paths[1], False)
    synth = coherence_2d(paths[0], os.path.join(outdir, name + "-left-2d.png"), half, h, False)
    return fresh["coherence"], fresh["completeness"], synth


def median_of(rows, key):
    return statistics.median(r[key] for r in rows)


def print_targets(rows, key):
    targets = [
        ("coherence <= 1.5 x 2D", median_of(rows, key + "coherence") <= 1.5 * median_of(rows, "coherence_2d")),
        ("completeness <= 1.2", median_of(rows, key + "completeness") <= 1.2),
        ("copy <= 0.5", median_of(rows, key + "copy") <= 0.5),
        ("seam <= 1.10", max(r[key + "seam"] for r in rows) <= 1.10),
    ]
    print("\n".join("%-24s %s" % (t, "met" if ok else "NOT met") for t, ok in targets))


def run_exemplars():
    exemplars = sorted(glob.glob(os.path.join(tsops.exemplars_dir(), "*.png")))
    if args.only:
        wanted = set(args.only.split(","))
        exemplars = [e for e in exemplars if os.path.basename(e)[:-4] in wanted]
    rows = []
    for exemplar in exemplars:
        name = os.path.basename(exemplar)[:-4]
        vol_path = os.path.join(outdir, name + ".vol")
        row = {"name": name, "seconds": synthesize_volume(exemplar, vol_path, name)}
        row["coherence_2d"] = coherence_2d(exemplar, os.path.join(outdir, name + "-2d.png"),
                                           args.size, args.size, True)
        row.update(measure_volume(args.measure, exemplar, vol_path, outdir, name))
        if args.fresh:
            row["fresh"], row["fresh_completeness"], row["fresh_2d"] = fresh_reference(exemplar, name)
        rows.append(row)
        print("%-10s 2D %.3f | slices: coherence %.3f (%.2fx) completeness %.3f copy %.3f sharpness %.3f"
              " axis-edges %.3f seam %.3f (inner lines %.3f) | %.1f s"
              % (name, row["coherence_2d"], row["coherence"], row["coherence"] / row["coherence_2d"],
                 row["completeness"], row["copy"], row["sharpness"], row["axis_edges"], row["seam"],
                 row["inner_seam"], row["seconds"]), flush=True)
    if not rows:
        tsops.die("no exemplars in %s" % tsops.exemplars_dir())
    fresh = args.fresh
    print("\n| exemplar | 2D coherence | slice coherence | ratio | completeness | copy | sharpness | seam "
          "| seam, inner lines |" + (" unseen half: coherence / 2D (ratio), completeness |" if fresh else ""))
    print("|---" * (9 + fresh) + "|")
    for r in rows:
        extra = (" %.3f / %.3f (%.2f), %.3f |" % (r["fresh"], r["fresh_2d"], r["fresh"] / r["fresh_2d"],
                                                 r["fresh_completeness"]) if fresh else "")
        print("| %s | %.3f | %.3f | %.2f | %.3f | %.3f | %.3f | %.3f | %.3f |%s"
              % (r["name"], r["coherence_2d"], r["coherence"], r["coherence"] / r["coherence_2d"],
                 r["completeness"], r["copy"], r["sharpness"], r["seam"], r["inner_seam"], extra))
    m = {k: median_of(rows, k) for k in ("coherence_2d", "coherence", "completeness", "copy", "sharpness")}
    extra = ""
    if fresh:
        extra = " median ratio %.2f, %.3f |" % (statistics.median(r["fresh"] / r["fresh_2d"] for r in rows),
                                                 median_of(rows, "fresh_completeness"))
    print("| **median** | %.3f | %.3f | %.2f | %.3f | %.3f | %.3f | max %.3f | max %.3f |%s"
          % (m["coherence_2d"], m["coherence"], m["coherence"] / m["coherence_2d"], m["completeness"],
             m["copy"], m["sharpness"], max(r["seam"] for r in rows),
             max(r["inner_seam"] for r in rows), extra))
    print()
    print_targets(rows, "")


def run_truth():
    kinds = args.only.split(",") if args.only else ["cells", "blobs", "grains"]
    rows = []
    for kind in kinds:
        truth_path = os.path.join(outdir, kind + "-truth.vol")
        proc = subprocess.run([args.truth_tool, kind, str(args.size), str(args.seed), truth_path],
                              capture_output=True, text=True)
        if proc.returncode != 0:
            tsops.die("%s failed:\n%s%s" % (args.truth_tool, proc.stdout, proc.stderr))
        truth = read_vol(truth_path)
        exemplar = os.path.join(outdir, kind + ".png")
        save_rgb(exemplar, args.size, args.size, axis_slice(truth, 2, 0))
        vol_path = os.path.join(outdir, kind + ".vol")
        row = {"name": kind, "seconds": synthesize_volume(exemplar, vol_path, kind)}
        row["coherence_2d"] = coherence_2d(exemplar, os.path.join(outdir, kind + "-2d.png"),
                                           args.size, args.size, True)
        row.update(("truth_" + k, v) for k, v in
                   measure_volume(args.measure, exemplar, truth_path, outdir, kind + "-truth").items())
        row.update(measure_volume(args.measure, exemplar, vol_path, outdir, kind))
        rows.append(row)
    print("| solid | 2D coherence | coherence: truth (ratio) / synthesised (ratio) | completeness: truth / "
          "synthesised | copy | sharpness | axis-edges | seam | seam, inner lines |")
    print("|---" * 9 + "|")
    for r in rows:
        print("| %s | %.3f | %.3f (%.2f) / %.3f (%.2f) | %.3f / %.3f | %.3f / %.3f | %.3f / %.3f | %.3f / %.3f "
              "| %.3f / %.3f | %.3f / %.3f |"
              % (r["name"], r["coherence_2d"], r["truth_coherence"], r["truth_coherence"] / r["coherence_2d"],
                 r["coherence"], r["coherence"] / r["coherence_2d"], r["truth_completeness"], r["completeness"],
                 r["truth_copy"], r["copy"], r["truth_sharpness"], r["sharpness"], r["truth_axis_edges"],
                 r["axis_edges"], r["truth_seam"], r["seam"], r["truth_inner_seam"], r["inner_seam"]))
    print("\nThe ground truth itself against the targets:")
    print_targets(rows, "truth_")
    print("\nThe synthesised volumes against the targets:")
    print_targets(rows, "")


if args.truth:
    run_truth()
else:
    run_exemplars()
