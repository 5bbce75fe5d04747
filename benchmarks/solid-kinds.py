#!/usr/bin/python3
# The shape figures on every kind of truth solid (truth-solids.h), per
# half (tuning, checking) and per kind: how well a solid synthesised from
# a truth's exemplar keeps its shapes, beside the truth's own slices.
# SPDX-License-Identifier: LGPL-3.0-or-later
#
# For each seed and kind: solid-truth renders the truth (SIZE^3); its
# z = 0 slice is the exemplar; solid-shapes synthesises a solid of the
# same size from it (-o: our middle slices across x, y, z and the diagonal
# x = z) and gives the figures solid-seeds.py reads (sharpness, coherence,
# completeness, axis-edges, seam) and the time; texsynth-measure --shapes
# measures the exemplar's phases (k-means on its colours, 3 phases for the
# three-mineral kinds, else 2) on our four slices and on ten of the
# truth's (the same four, and across x, y and z at a quarter and three
# quarters of the side), which give the spread a perfect solid shows.
#
# Per kind and phase, medians over our slices of all seeds:
#   solidity   ours / the truth's (median of its middle slices); aim >= 0.95
#   fraction, chord-rows, chord-columns: ours, with the truth's slices'
#              range; aim: inside it, or within 10 % of its mean
#   s2         per slice the largest |S2(r) - the truth's mean S2(r)|, r =
#              1..32; aim: ours no more than the truth's own largest
# and per kind, medians over the seeds: sharpness, coherence and
# completeness over the truth's (aims >= 0.9, <= 1.15, <= 1.15),
# axis-edges and seam (<= 1.08, <= 1.10), the synthesis time (<= 30 s)
# and solid-shapes' peak RSS (which includes GEGL's start-up and both
# volumes; solid-memory gives the engine's own).
#
# The halves come from truth-solids.h (TRUTH_SOLID_TUNING and
# TRUTH_SOLID_CHECKING). Every record is also appended as a JSON line to
# RECORDS (-r), and -R RECORDS prints the tables from such a file alone,
# so a long run can be summarised part way.
#
# -o DIR keeps solid-shapes' strips there as KIND-SEED-slices.png
# (docs/solid-kinds.py --strips DIR makes its picture from them).
#
# Usage: benchmarks/solid-kinds.py [-b BUILD] [-s SIZE] [-k KIND,...] [-r RECORDS] [-o DIR] [SEED ...]
#        benchmarks/solid-kinds.py -R RECORDS
# e.g. OMP_NUM_THREADS=2 nice benchmarks/solid-kinds.py -s 64 1   (a few minutes)
#      OMP_NUM_THREADS=2 nice benchmarks/solid-kinds.py -s 128 1 2 3

import argparse
import importlib.util
import json
import os
import re
import shutil
import statistics
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import solidslices  # noqa: E402

_spec = importlib.util.spec_from_file_location("solid_seeds", os.path.join(HERE, "solid-seeds.py"))
solid_seeds = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(solid_seeds)

# Kinds whose exemplar is split into three phases (three minerals or
# phases by design); the others into two.
THREE_PHASES = ("grains", "threephase")
# Our slices in solid-shapes' strip: exemplar, truth, then ours across
# x, y, z and the diagonal; panels SIZE wide, 4 pixels apart.
OUR_COLUMNS = (2, 3, 4, 5)
STRIP_GAP = 4
# How many of the truth's measured slices are its middle ones (x, y, z,
# diagonal); the rest widen the spread.
TRUTH_MIDDLE = 4
SOLIDITY_AIM = 0.95
NEAR_MEAN = 0.10
# figure, aim, which way, mark when missed
LIMITS = (("sharpness", 0.9, "min", "H"), ("coherence", 1.15, "max", "O"),
          ("completeness", 1.15, "max", "P"), ("axis", 1.08, "max", "A"), ("seam", 1.10, "max", "M"),
          ("seconds", 30.0, "max", "T"))


def halves():
    """(tuning kinds, checking kinds) as truth-solids.h lists them."""
    with open(os.path.join(HERE, "truth-solids.h")) as f:
        text = f.read()
    found = {}
    for half in ("TUNING", "CHECKING"):
        m = re.search(r"#define TRUTH_SOLID_%s (.*)" % half, text)
        if not m:
            sys.exit("truth-solids.h: no TRUTH_SOLID_%s" % half)
        found[half] = re.findall(r'"(\w+)"', m.group(1))
    return found["TUNING"], found["CHECKING"]


def truth_slices(vol_path, size, outdir, stem):
    """The exemplar (z = 0) and the truth's slices to measure, as PNGs."""
    vol = solidslices.read_vol(vol_path)
    cuts = [(a, size // 2) for a in range(3)] + [None] + \
        [(a, i) for i in (size // 4, 3 * size // 4) for a in range(3)]
    paths = []
    for k, cut in enumerate([(2, 0)] + cuts):
        path = os.path.join(outdir, "%s-truth%d.png" % (stem, k))
        pixels = solidslices.diagonal_slice(vol) if cut is None else solidslices.axis_slice(vol, *cut)
        solidslices.save_rgb(path, size, size, pixels)
        paths.append(path)
    return paths[0], paths[1:]


def our_slices(strip_path, size, outdir, stem):
    """Our four middle slices, cut out of solid-shapes' strip."""
    width, height, data = solidslices.tsops.load_bytes(strip_path, "R'G'B' u8")
    paths = []
    for column in OUR_COLUMNS:
        x0 = column * (size + STRIP_GAP)
        pixels = b"".join(data[(y * width + x0) * 3:(y * width + x0 + size) * 3] for y in range(size))
        path = os.path.join(outdir, "%s-ours%d.png" % (stem, column))
        solidslices.save_rgb(path, size, size, pixels)
        paths.append(path)
    return paths


def run_shapes(shapes, size, seed, kind, outdir):
    """solid-shapes on one kind: its figures, seconds and peak RSS (MiB)."""
    proc = subprocess.run(["/usr/bin/time", "-f", "peak-rss-kib %M", shapes, str(size), str(seed), "-o", outdir,
                           kind], capture_output=True, text=True)
    out, err = proc.stdout, proc.stderr
    rss = re.findall(r"^peak-rss-kib (\d+)$", err, re.M)
    rss_mib = int(rss[-1]) / 1024.0 if rss else None
    if proc.returncode != 0:
        sys.exit("solid-shapes %d %d %s failed (%d): %s" % (size, seed, kind, proc.returncode, err.strip()))
    figures, seconds = {}, None
    for line in out.splitlines():
        m = solid_seeds.FIGURE.match(line)
        if m:
            figures[m.group(2)] = dict(zip(("coherence", "completeness", "sharpness", "axis", "seam"),
                                           map(float, m.group(3, 4, 5, 6, 7))))
        m = solid_seeds.SYNTH.match(line)
        if m:
            seconds = float(m.group(2))
    if "truth" not in figures or "ours" not in figures or seconds is None:
        sys.exit("solid-shapes %d %d %s: no figures in its output" % (size, seed, kind))
    return figures, seconds, rss_mib


def measure_kind(build, size, seed, kind, scratch, keep):
    stem = "%s-%d" % (kind, seed)
    vol = os.path.join(scratch, stem + ".vol")
    subprocess.run([os.path.join(build, "benchmarks", "solid-truth"), kind, str(size), str(seed), vol],
                   check=True)
    exemplar, truth = truth_slices(vol, size, scratch, stem)
    os.remove(vol)
    figures, seconds, rss = run_shapes(os.path.join(build, "benchmarks", "solid-shapes"), size, seed,
                                       kind, scratch)
    strip = os.path.join(scratch, kind + "-slices.png")
    if keep:
        shutil.copyfile(strip, os.path.join(keep, "%s-%d-slices.png" % (kind, seed)))
    ours = our_slices(strip, size, scratch, stem)
    phases = 3 if kind in THREE_PHASES else 2
    out = subprocess.run([os.path.join(build, "tools", "texsynth-measure"), "--shapes", "--json",
                          "--phases=%d" % phases, exemplar] + truth + ours,
                         capture_output=True, text=True)
    if out.returncode != 0:
        sys.exit("texsynth-measure --shapes on %s seed %d failed: %s" % (kind, seed, out.stderr.strip()))
    images = json.loads(out.stdout)["images"]
    return {"size": size, "seed": seed, "kind": kind, "phases": phases,
            "truth": [i["phases"] for i in images[1:1 + len(truth)]],
            "ours": [i["phases"] for i in images[1 + len(truth):]],
            "figures": figures, "seconds": seconds, "rss_mib": rss}


def finite(values):
    return [v for v in values if v is not None]


def median(values):
    values = finite(values)
    return statistics.median(values) if values else float("nan")


def s2_distance(s2, reference):
    pairs = [(a, b) for a, b in zip(s2, reference) if a is not None and b is not None]
    return max(abs(a - b) for a, b in pairs) if pairs else float("nan")


def inside(value, spread):
    lo, hi, mean = min(spread), max(spread), statistics.mean(spread)
    return lo <= value <= hi or abs(value - mean) <= NEAR_MEAN * abs(mean)


def kind_rows(records):
    """Per phase: the shape figures and the aims missed; then the kind's
    other figures and their misses."""
    phases = records[0]["phases"]
    lines, misses = [], 0
    for p in range(phases):
        ours = {key: [] for key in ("solidity", "fraction", "chord_rows", "chord_columns", "s2")}
        truth = {key: [] for key in ours}
        truth_middle_solidity = []
        for r in records:
            reference = [statistics.mean(finite([t[p]["s2"][i] for t in r["truth"]]) or [0.0])
                         for i in range(len(r["truth"][0][p]["s2"]))]
            for k, t in enumerate(r["truth"]):
                for key in ("fraction", "chord_rows", "chord_columns"):
                    if t[p][key] is not None:
                        truth[key].append(t[p][key])
                truth["s2"].append(s2_distance(t[p]["s2"], reference))
                if k < TRUTH_MIDDLE:
                    truth_middle_solidity.append(t[p]["solidity"])
            for o in r["ours"]:
                for key in ("solidity", "fraction", "chord_rows", "chord_columns"):
                    ours[key].append(o[p][key])
                ours["s2"].append(s2_distance(o[p]["s2"], reference))
        solidity = median(ours["solidity"]) / median(truth_middle_solidity)
        marks = "S" if not solidity >= SOLIDITY_AIM else ""
        cells = ["solidity %.3f (%.3f/%.3f)" % (solidity, median(ours["solidity"]),
                                                median(truth_middle_solidity))]
        for key, label, mark in (("fraction", "fraction", "F"), ("chord_rows", "chord-rows", "R"),
                                 ("chord_columns", "chord-columns", "C")):
            value = median(ours[key])
            if truth[key]:
                cells.append("%s %.3f [%.3f-%.3f]" % (label, value, min(truth[key]), max(truth[key])))
                if not (value == value and inside(value, truth[key])):
                    marks += mark
            else:
                cells.append("%s %.3f [-]" % (label, value))
        s2_ours, s2_truth = median(ours["s2"]), max(truth["s2"])
        cells.append("s2 %.4f [<= %.4f]" % (s2_ours, s2_truth))
        if not s2_ours <= s2_truth:
            marks += "2"
        misses += len(marks)
        lines.append("  phase %d: %s %s" % (p, " ".join(cells), marks or "-"))
    values = {}
    for key in ("sharpness", "coherence", "completeness"):
        values[key] = median([r["figures"]["ours"][key] / r["figures"]["truth"][key] for r in records])
    for key in ("axis", "seam"):
        values[key] = median([r["figures"]["ours"][key] for r in records])
    values["seconds"] = median([r["seconds"] for r in records])
    marks = "".join(mark if (values[key] < limit if way == "min" else values[key] > limit) else ""
                    for key, limit, way, mark in LIMITS)
    misses += len(marks)
    rss = finite([r["rss_mib"] for r in records])
    lines.append("  sharpness %.3f coherence %.3f completeness %.3f axis-edges %.3f seam %.3f time %.1f s "
                 "(max %.1f) peak RSS %.0f MiB %s" % (
                     values["sharpness"], values["coherence"], values["completeness"], values["axis"],
                     values["seam"], values["seconds"], max(r["seconds"] for r in records),
                     max(rss) if rss else float("nan"), marks or "-"))
    return lines, misses


def summarise(records):
    tuning, checking = halves()
    by_kind = {}
    for r in records:
        by_kind.setdefault(r["kind"], []).append(r)
    sizes = sorted({r["size"] for r in records})
    print("%s^3; per kind, medians over our middle slices (x, y, z, diagonal) of seeds %s" % (
        ",".join(map(str, sizes)), " ".join(map(str, sorted({r["seed"] for r in records})))))
    print("marks, the aims missed: S solidity < %.2f x the truth's; F fraction, R chord-rows, "
          "C chord-columns outside the truth's slices' range and over %d %% from its mean; 2 s2 "
          "farther from the truth's mean than any truth slice; then H sharpness < 0.9, "
          "O coherence > 1.15, P completeness > 1.15 (x the truth's), A axis-edges > 1.08, "
          "M seam > 1.10, T seconds > 30" % (SOLIDITY_AIM, round(NEAR_MEAN * 100)))
    for name, kinds in (("tuning", tuning), ("checking", checking)):
        present = [k for k in kinds if k in by_kind]
        total = 0
        print("\n%s half (%s)" % (name, ", ".join(kinds)))
        for kind in present:
            lines, misses = kind_rows(sorted(by_kind[kind], key=lambda r: r["seed"]))
            total += misses
            print("%s (seeds %s): %d missed" % (kind, " ".join(str(r["seed"]) for r in by_kind[kind]),
                                                 misses))
            print("\n".join(lines))
        missing = [k for k in kinds if k not in by_kind]
        print("%s half: %d aims missed over %d kinds%s" % (
            name, total, len(present), "; not measured: " + ", ".join(missing) if missing else ""))


def main():
    parser = argparse.ArgumentParser(description="The shape figures (texsynth-measure --shapes) and the solid aims on every truth solid, per kind and per half.")
    parser.add_argument("seeds", nargs="*", type=int, default=[1, 2, 3])
    parser.add_argument("-b", "--build", default=os.path.join(HERE, "..", "build"))
    parser.add_argument("-s", "--size", type=int, default=128)
    parser.add_argument("-k", "--kinds", help="comma-separated kinds (default: both halves)")
    parser.add_argument("-r", "--records", help="append every record to this file (JSON lines)")
    parser.add_argument("-R", "--from-records", help="only print the tables from this file")
    parser.add_argument("-o", "--keep-strips", help="keep solid-shapes' strips in this folder")
    args = parser.parse_args()
    if args.from_records:
        with open(args.from_records) as f:
            summarise([json.loads(line) for line in f if line.strip()])
        return
    tuning, checking = halves()
    kinds = args.kinds.split(",") if args.kinds else tuning + checking
    for tool in (("benchmarks", "solid-truth"), ("benchmarks", "solid-shapes"), ("tools", "texsynth-measure")):
        if not os.access(os.path.join(args.build, *tool), os.X_OK):
            sys.exit("%s: not built (meson setup and ninja)" % os.path.join(args.build, *tool))
    records = []
    if args.keep_strips:
        os.makedirs(args.keep_strips, exist_ok=True)
    with tempfile.TemporaryDirectory(prefix="solid-kinds-") as scratch:
        for seed in args.seeds:
            for kind in kinds:
                record = measure_kind(args.build, args.size, seed, kind, scratch, args.keep_strips)
                records.append(record)
                print("seed %d %s: %.1f s" % (seed, kind, record["seconds"]), file=sys.stderr, flush=True)
                if args.records:
                    with open(args.records, "a") as f:
                        f.write(json.dumps(record) + "\n")
    summarise(records)


if __name__ == "__main__":
    main()
