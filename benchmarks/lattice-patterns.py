#!/usr/bin/python3
# 2D synthesis on GIMP's own patterns (Debian's gimp-data), most of which
# the bundled exemplars do not hold: per pattern, the lattice figure of
# each seed, and the medians over the seeds of coherence + completeness
# (bds), copy and sharpness (texsynth-measure).
# SPDX-License-Identifier: LGPL-3.0-or-later
#
#   benchmarks/lattice-patterns.py [-b BUILD] [--size N] [--seeds 1,2,3]
#                                  [--out DIR] [NAME...]
#
# NAME is a pattern file's name without .pat (default: the near-regular
# patterns that tests/exemplars does not hold, then as many irregular
# ones). The patterns are read from GIMP's .pat files (a big-endian
# header: header size, version, width, height, bytes per pixel, then the
# raw pixels) and written as PNG, the central crop of at most 128x128 is
# the exemplar, and texsynth:synthesize grows it to N x N through the
# gegl tool. Prints a markdown table. The images go to a temporary
# folder, removed at the end, unless --out names one to keep them in.
import argparse
import json
import os
import statistics
import shutil
import struct
import subprocess
import sys
import tempfile
import zlib

from gegl_runs import crop_centre, quiet_runs, synthesize_seeds

PATTERNS = "/usr/share/gimp/2.0/patterns"
NEAR_REGULAR = ["pine", "recessed", "rain", "parque3", "wood3", "choc_swirl", "leaves",
                "nops", "marble3", "wood4", "qube1", "lightning"]
IRREGULAR = ["slate", "leather", "walnut", "corkboard", "terra", "crinklepaper",
             "amethyst", "pastel"]


def write_png(path, width, height, channels, pixels):
    colour_type = {1: 0, 2: 4, 3: 2, 4: 6}[channels]
    stride = width * channels
    raw = b"".join(b"\0" + pixels[y * stride:(y + 1) * stride] for y in range(height))

    def chunk(kind, data):
        return (struct.pack(">I", len(data)) + kind + data
                + struct.pack(">I", zlib.crc32(kind + data) & 0xffffffff))
    with open(path, "wb") as f:
        f.write(b"\x89PNG\r\n\x1a\n"
                + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, colour_type, 0, 0, 0))
                + chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b""))


def pattern_to_png(pat, png):
    with open(pat, "rb") as f:
        data = f.read()
    header, _version, width, height, channels = struct.unpack(">IIIII", data[:20])
    pixels = data[header:header + width * height * channels]
    if channels not in (1, 2, 3, 4) or len(pixels) != width * height * channels:
        sys.exit("%s: not a GIMP pattern this script reads" % pat)
    write_png(png, width, height, channels, pixels)
    return width, height


def find_pattern(name):
    for root, _dirs, files in os.walk(PATTERNS):
        if name + ".pat" in files:
            return os.path.join(root, name + ".pat")
    sys.exit("no pattern %s.pat under %s (Debian package gimp-data)" % (name, PATTERNS))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("-b", "--build", default="build")
    ap.add_argument("--size", type=int, default=256)
    ap.add_argument("--seeds", default="1,2,3")
    ap.add_argument("--out", help="keep the exemplars and results in this folder")
    ap.add_argument("names", nargs="*")
    a = ap.parse_args()
    names = a.names or NEAR_REGULAR + IRREGULAR
    build = os.path.abspath(a.build)
    measure = os.path.join(build, "tools", "texsynth-measure")
    keep = a.out is not None
    a.out = a.out if keep else tempfile.mkdtemp(prefix="lattice-patterns.")
    os.makedirs(a.out, exist_ok=True)
    quiet = quiet_runs(build)
    try:
        table(a, names, measure, quiet)
    finally:
        if not keep:
            shutil.rmtree(a.out, ignore_errors=True)


def table(a, names, measure, quiet):
    print("| pattern | size | strength | lattice, per seed | bds | copy | sharpness |")
    print("|---|---|---|---|---|---|---|")
    for name in names:
        png = os.path.join(a.out, name + ".png")
        width, height = pattern_to_png(find_pattern(name), png)
        exemplar = os.path.join(a.out, name + "-exemplar.png")
        crop_w, crop_h = crop_centre(png, width, height, exemplar, quiet)
        results = synthesize_seeds(exemplar, a.out, name, a.size, a.seeds, quiet)
        out = subprocess.run([measure, "--json", "--lattice", exemplar] + results,
                             capture_output=True, text=True, check=True).stdout
        figures = [json.loads(line) for line in out.splitlines() if line.startswith("{")]
        lattice = " / ".join("%.2f" % f["lattice"] if f["lattice"] is not None else "–"
                             for f in figures)
        print("| %s | %d×%d | %.2f | %s | %.2f | %.2f | %.2f |" % (
            name, crop_w, crop_h, figures[0]["lattice_strength"], lattice,
            statistics.median(f["coherence"] + f["completeness"] for f in figures),
            statistics.median(f["copy"] for f in figures),
            statistics.median(f["sharpness"] for f in figures)), flush=True)


if __name__ == "__main__":
    main()
