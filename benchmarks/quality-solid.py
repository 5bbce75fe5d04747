#!/usr/bin/env python3
# Quality of solid synthesis (texsynth:volume-save) on every exemplar:
# synthesise a SIZE^3 periodic volume per exemplar, cut the middle slices
# across x, y and z and one diagonal slice (the plane x = z, sampled at
# unit spacing), measure each against the exemplar with texsynth-measure,
# and compare the medians with a 2D texsynth:synthesize result of the same
# size (tileable, since the volume is periodic).
# SPDX-License-Identifier: LGPL-3.0-or-later
#
# Run with the system Python (PyGObject + the Gegl typelib) and GEGL_PATH
# listing build/operations and GEGL's own folder, e.g.
#   GEGL_PATH=build/operations:$(pkg-config --variable=pluginsdir gegl-0.4) \
#     /usr/bin/python3 benchmarks/quality-solid.py --measure build/tools/texsynth-measure
#
# Targets (issue 4): slice coherence median <= 1.5 x the 2D median,
# completeness <= 1.2, copy <= 0.5, seam <= 1.10 across the boundary.

import argparse
import glob
import math
import os
import statistics
import struct
import sys
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "tests", "ops"))
import tsops  # noqa: E402

parser = argparse.ArgumentParser(description="Quality of texsynth solid synthesis")
parser.add_argument("--measure", default=os.environ.get("TEXSYNTH_MEASURE", "build/tools/texsynth-measure"))
parser.add_argument("--size", type=int, default=128)
parser.add_argument("--seed", type=int, default=1)
parser.add_argument("--only", help="comma-separated exemplar names (without .png)")
parser.add_argument("--keep", help="keep volumes and slices in this folder")
args = parser.parse_args()

outdir = args.keep or tsops.workdir()
os.makedirs(outdir, exist_ok=True)
exemplars = sorted(glob.glob(os.path.join(tsops.exemplars_dir(), "*.png")))
if args.only:
    wanted = set(args.only.split(","))
    exemplars = [e for e in exemplars if os.path.basename(e)[:-4] in wanted]


def measure(exemplar, result, tileable):
    return tsops.run_measure(args.measure, exemplar, result, tileable)


def read_vol(path):
    with open(path, "rb") as f:
        data = f.read()
    if data[:4] != b"VOLU":
        tsops.die("%s is not a .vol file" % path)
    size, channels = struct.unpack_from("<ii", data, 268)
    return size, channels, data[4096:]


def save_rgb(path, width, height, pixels):
    """pixels: bytes, 3 per pixel (R'G'B' u8)."""
    Gegl = tsops.gegl()
    buf = Gegl.Buffer.new("R'G'B' u8", 0, 0, width, height)
    buf.set(Gegl.Rectangle.new(0, 0, width, height), "R'G'B' u8", pixels)
    tsops.save_buffer(buf, path)


def axis_slice(vol, axis, index):
    size, channels, data = vol
    out = bytearray(size * size * 3)
    for v in range(size):
        for u in range(size):
            x, y, z = ((index, u, v), (u, index, v), (u, v, index))[axis]
            p = ((z * size + y) * size + x) * channels
            out[(v * size + u) * 3:(v * size + u) * 3 + 3] = data[p:p + 3]
    return bytes(out)


def diagonal_slice(vol):
    """The plane x = z through the volume: u runs along (1, 0, 1) / sqrt(2)
    at unit spacing (bilinear in x and z), v along y."""
    size, channels, data = vol
    out = bytearray(size * size * 3)
    for v in range(size):
        for u in range(size):
            s = u / math.sqrt(2.0)
            f = int(math.floor(s))
            t = s - f
            acc = [0.0, 0.0, 0.0]
            for dx, dz, w in ((0, 0, (1 - t) * (1 - t)), (1, 0, t * (1 - t)),
                              (0, 1, (1 - t) * t), (1, 1, t * t)):
                x, z = (f + dx) % size, (f + dz) % size
                p = ((z * size + v) * size + x) * channels
                for c in range(3):
                    acc[c] += w * data[p + c]
            out[(v * size + u) * 3:(v * size + u) * 3 + 3] = bytes(min(255, int(a + 0.5)) for a in acc)
    return bytes(out)


rows = []
for exemplar in exemplars:
    name = os.path.basename(exemplar)[:-4]
    vol_path = os.path.join(outdir, name + ".vol")
    start = time.time()
    code, out, err = tsops.run_gegl(["-i", exemplar, "--", "texsynth:volume-save", "path=" + vol_path,
                                     "size=%d" % args.size, "seed=%d" % args.seed], timeout=3600)
    seconds = time.time() - start
    if code != 0 or not os.path.exists(vol_path):
        tsops.die("volume-save failed for %s:\n%s%s" % (name, out, err))
    plain = os.path.join(outdir, name + "-2d.png")
    tsops.synthesize_cli(exemplar, plain, width=args.size, height=args.size, seed=args.seed,
                         tileable=True)
    vol = read_vol(vol_path)
    figures = {"2d": measure(exemplar, plain, True)}
    for axis, label in enumerate("xyz"):
        path = os.path.join(outdir, "%s-%s.png" % (name, label))
        save_rgb(path, args.size, args.size, axis_slice(vol, axis, args.size // 2))
        figures[label] = measure(exemplar, path, True)
    path = os.path.join(outdir, name + "-diagonal.png")
    save_rgb(path, args.size, args.size, diagonal_slice(vol))
    figures["diagonal"] = measure(exemplar, path, False)
    slices = [figures[k] for k in ("x", "y", "z", "diagonal")]
    row = {
        "name": name, "seconds": seconds,
        "coherence_2d": figures["2d"]["coherence"],
        "coherence": statistics.median(s["coherence"] for s in slices),
        "completeness": statistics.median(s["completeness"] for s in slices),
        "copy": max(s["copy"] for s in slices),
        "sharpness": statistics.median(s["sharpness"] for s in slices),
        "seam": max(figures[k]["seam"] for k in "xyz"),
    }
    rows.append(row)
    print("%-10s 2D %.3f | slices: coherence %.3f (%.2fx) completeness %.3f copy %.3f sharpness %.3f seam %.3f | %.1f s"
          % (name, row["coherence_2d"], row["coherence"], row["coherence"] / row["coherence_2d"],
             row["completeness"], row["copy"], row["sharpness"], row["seam"], seconds), flush=True)

if not rows:
    tsops.die("no exemplars in %s" % tsops.exemplars_dir())
median = {k: statistics.median(r[k] for r in rows)
          for k in ("coherence_2d", "coherence", "completeness", "copy", "sharpness", "seam", "seconds")}
print("\n| exemplar | 2D coherence | slice coherence | ratio | completeness | copy | sharpness | seam |")
print("|---|---|---|---|---|---|---|---|")
for r in rows:
    print("| %s | %.3f | %.3f | %.2f | %.3f | %.3f | %.3f | %.3f |"
          % (r["name"], r["coherence_2d"], r["coherence"], r["coherence"] / r["coherence_2d"],
             r["completeness"], r["copy"], r["sharpness"], r["seam"]))
print("| **median** | %.3f | %.3f | %.2f | %.3f | %.3f | %.3f | max %.3f |"
      % (median["coherence_2d"], median["coherence"], median["coherence"] / median["coherence_2d"],
         median["completeness"], median["copy"], median["sharpness"], max(r["seam"] for r in rows)))
targets = [
    ("coherence <= 1.5 x 2D", median["coherence"] <= 1.5 * median["coherence_2d"]),
    ("completeness <= 1.2", median["completeness"] <= 1.2),
    ("copy <= 0.5", median["copy"] <= 0.5),
    ("seam <= 1.10", max(r["seam"] for r in rows) <= 1.10),
]
print("\n" + "\n".join("%-24s %s" % (t, "met" if ok else "NOT met") for t, ok in targets))
