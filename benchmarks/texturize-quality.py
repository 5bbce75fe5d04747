#!/usr/bin/python3
# texsynth beside GIMP Texturize on the same exemplars, in one run: per
# exemplar, coherence + completeness (bds), copy, sharpness and the
# lattice figure of texsynth's results (medians over the seeds; the
# lattice per seed) and of Texturize's one result, the ratio of the bds,
# then their median and the worst.
# SPDX-License-Identifier: LGPL-3.0-or-later
#
#   benchmarks/texturize-quality.py [-b BUILD] [-e EXEMPLAR_DIR] [--size N]
#                                   [--seeds 1,2,3] [--overlap 50]
#                                   [--texturize-dir DIR] [--out DIR]
#
# The exemplar is the central crop of at most 128x128 of each PNG of
# EXEMPLAR_DIR (default tests/exemplars), saved without colour-space
# chunks: GIMP reads PNG values raw, GEGL would apply them. Texturize
# (Debian's gimp-texturize, GIMP 2.10's batch mode, one start for all
# exemplars) and texsynth:synthesize (the gegl tool) grow it to N x N.
# --texturize-dir takes Texturize's results (NAME.png) from an earlier
# run instead. Prints a markdown table.
import argparse
import glob
import json
import os
import statistics
import struct
import subprocess
import sys
import tempfile

from gegl_runs import crop_centre, quiet_runs, synthesize_seeds

CRITICAL_CHUNKS = (b"IHDR", b"PLTE", b"IDAT", b"IEND", b"tRNS")


def png_size(path):
    with open(path, "rb") as f:
        return struct.unpack(">II", f.read(24)[16:24])


def strip_colour_chunks(path):
    """Keeps only the chunks that hold the pixels (no gAMA, cHRM, iCCP)."""
    with open(path, "rb") as f:
        data = f.read()
    out, i = [data[:8]], 8
    while i < len(data):
        length, = struct.unpack(">I", data[i:i + 4])
        if data[i + 4:i + 8] in CRITICAL_CHUNKS:
            out.append(data[i:i + 12 + length])
        i += 12 + length
    with open(path, "wb") as f:
        f.write(b"".join(out))


def run_texturize(crops, out_dir, size, overlap):
    if not os.path.exists("/usr/lib/gimp/2.0/plug-ins/texturize"):
        sys.exit("GIMP Texturize is not installed (Debian packages gimp, gimp-texturize)")
    calls = []
    for name, crop in crops:
        result = os.path.join(out_dir, name + ".png")
        # Texturize opens its result as a new image, the newest in the list
        calls.append(
            '(let* ((img (car (gimp-file-load RUN-NONINTERACTIVE "%s" "%s")))'
            ' (drw (car (gimp-image-get-active-drawable img))))'
            ' (gimp-plugin-texturize RUN-NONINTERACTIVE img drw %d %d %d FALSE)'
            ' (let ((new (vector-ref (cadr (gimp-image-list)) 0)))'
            ' (gimp-file-save RUN-NONINTERACTIVE new (car (gimp-image-get-active-drawable new))'
            ' "%s" "%s")))' % (crop, crop, size, size, overlap, result, result))
    with tempfile.TemporaryDirectory() as home:   # a throwaway GIMP profile
        subprocess.run(["gimp-console-2.10", "-i", "-d", "-f",
                        "-b", "(begin %s)" % " ".join(calls), "-b", "(gimp-quit 0)"],
                       env=dict(os.environ, HOME=home), stdout=subprocess.DEVNULL,
                       stderr=subprocess.DEVNULL, timeout=3600)
    for name, _crop in crops:
        if not os.path.exists(os.path.join(out_dir, name + ".png")):
            sys.exit("Texturize produced no image for %s" % name)


def measure(tool, crop, results):
    out = subprocess.run([tool, "--json", "--lattice", crop] + results,
                         capture_output=True, text=True, check=True).stdout
    return [json.loads(line) for line in out.splitlines() if line.startswith("{")]


def lattice_text(figure):
    return "%.2f" % figure["lattice"] if figure["lattice"] is not None else "–"


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("-b", "--build", default="build")
    ap.add_argument("-e", "--exemplars", default="tests/exemplars")
    ap.add_argument("--size", type=int, default=256)
    ap.add_argument("--seeds", default="1,2,3")
    ap.add_argument("--overlap", type=int, default=50)
    ap.add_argument("--texturize-dir")
    ap.add_argument("--out", default="texturize-quality")
    a = ap.parse_args()
    build = os.path.abspath(a.build)
    tool = os.path.join(build, "tools", "texsynth-measure")
    quiet = quiet_runs(build)
    files = sorted(glob.glob(os.path.join(a.exemplars, "*.png")))
    if not files:
        sys.exit("no PNG in %s" % a.exemplars)
    crop_dir = os.path.join(a.out, "crops")
    tex_dir = a.texturize_dir or os.path.join(a.out, "texturize")
    os.makedirs(crop_dir, exist_ok=True)
    os.makedirs(tex_dir, exist_ok=True)

    crops = []
    for path in files:
        name = os.path.basename(path)[:-4]
        width, height = png_size(path)
        crop = os.path.abspath(os.path.join(crop_dir, name + ".png"))
        crop_centre(path, width, height, crop, quiet)
        strip_colour_chunks(crop)
        crops.append((name, crop))
    if not a.texturize_dir:
        run_texturize(crops, os.path.abspath(tex_dir), a.size, a.overlap)

    print("| exemplar | bds texsynth | bds Texturize | ratio | lattice texsynth | lattice Texturize "
          "| copy texsynth | copy Texturize | sharpness texsynth | sharpness Texturize |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    ratios = []
    for name, crop in crops:
        results = synthesize_seeds(crop, a.out, name, a.size, a.seeds, quiet)
        ours = measure(tool, crop, results)
        theirs = measure(tool, crop, [os.path.join(tex_dir, name + ".png")])[0]
        bds = statistics.median(f["coherence"] + f["completeness"] for f in ours)
        their_bds = theirs["coherence"] + theirs["completeness"]
        ratios.append((bds / their_bds, name))
        print("| %s | %.3f | %.3f | %.2f | %s | %s | %.2f | %.2f | %.2f | %.2f |" % (
            name, bds, their_bds, bds / their_bds, " / ".join(lattice_text(f) for f in ours),
            lattice_text(theirs), statistics.median(f["copy"] for f in ours), theirs["copy"],
            statistics.median(f["sharpness"] for f in ours), theirs["sharpness"]), flush=True)
    worst = max(ratios)
    print("\nmedian bds ratio %.2f, worst %.2f (%s)" % (
        statistics.median(r for r, _ in ratios), worst[0], worst[1]))


if __name__ == "__main__":
    main()
