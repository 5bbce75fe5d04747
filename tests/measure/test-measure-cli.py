#!/usr/bin/env python3
# Property tests of the texsynth-measure command-line tool on real
# exemplars. Usage: test-measure-cli.py TEXSYNTH_MEASURE MEASURE_FIXTURE
# Needs $TEXSYNTH_EXEMPLARS (folder of PNG exemplars). Standard library only.
# SPDX-License-Identifier: LGPL-3.0-or-later
import json
import os
import subprocess
import sys
import tempfile
import time

MEASURE, FIXTURE = sys.argv[1], sys.argv[2]
EXEMPLARS = os.environ.get("TEXSYNTH_EXEMPLARS", "")
failures = []


def check(cond, message):
    if not cond:
        failures.append(message)
        print("FAIL: " + message, file=sys.stderr)
    return cond


def run(*args):
    p = subprocess.run([MEASURE, *args], capture_output=True, text=True, timeout=600)
    return p.returncode, p.stdout, p.stderr


def rows_of(out, results, what):
    rows = [json.loads(line) for line in out.splitlines()]
    if [r["result"] for r in rows] != list(results):
        raise RuntimeError("texsynth-measure %s: results %r, asked for %r"
                           % (what, [r["result"] for r in rows], list(results)))
    return rows


def measure_lists(lists):
    """The measures of several argument lists (exemplar, results, options),
    joined by '+' into one run (one GEGL start-up): per list, a list of
    dicts from --json output, one per line."""
    args = []
    for exemplar, results, options in lists:
        args += (["+"] if args else []) + ["--json", *options, exemplar, *results]
    code, out, err = run(*args)
    if code != 0:
        raise RuntimeError("texsynth-measure %s failed (%d): %s" % (" ".join(args), code, err))
    rows = rows_of(out, [r for _, results, _ in lists for r in results], " ".join(args))
    answers = []
    for _, results, _ in lists:
        answers.append(rows[:len(results)])
        rows = rows[len(results):]
    return answers


def measure_many(exemplar, results, *options):
    """The measures of each result against `exemplar`, in one run."""
    return measure_lists([(exemplar, results, options)])[0]


def measure(exemplar, result, *options):
    """The measures as a dict, from --json output."""
    return measure_many(exemplar, [result], *options)[0]


def fixtures(commands):
    """Makes the test images: every measure-fixture command (a list of its
    arguments) in one run, in order."""
    args = []
    for command in commands:
        args += (["+"] if args else []) + command
    subprocess.run([FIXTURE, *args], check=True, timeout=600)


def size_of(path):
    # PNG IHDR: width and height, big-endian, at bytes 16..24.
    with open(path, "rb") as f:
        head = f.read(24)
    return int.from_bytes(head[16:20], "big"), int.from_bytes(head[20:24], "big")


def main():
    if not os.path.isdir(EXEMPLARS):
        print("FAIL  TEXSYNTH_EXEMPLARS is not a folder: %s" % EXEMPLARS, file=sys.stderr)
        return 1
    names = sorted(n for n in os.listdir(EXEMPLARS) if n.endswith(".png"))
    check(len(names) > 0, "no exemplars in " + EXEMPLARS)
    ex = {n: os.path.join(EXEMPLARS, n) for n in names}

    def present(n):
        """Whether the exemplar a check needs is there: a failure if not."""
        return check(n in ex, "%s is among the exemplars in %s" % (n, EXEMPLARS))
    tmp = tempfile.mkdtemp(prefix="texsynth-measure-test-")
    t = lambda name: os.path.join(tmp, name)

    # --- the test images, all made first ------------------------------------
    # Seams: a crop that is not tileable (odd offsets cut the pattern's
    # period), tiled 2x2, rolled, and tiled 2x1. The seam measure runs the
    # same code on every image; these three cover the kinds of texture it
    # must tell a seam in: busy and irregular (bark), cells with mortar
    # (stone33), and strongly oriented grain (wood1).
    seam_names = [n for n in ("bark.png", "stone33.png", "wood1.png") if present(n)]
    collage_names = [n for n in ("bluemetal.png", "land1.png") if present(n)]
    blur_names = [n for n in ("bark.png", "brick.png", "java.png", "3dweave.png") if present(n)]
    noise_names = [n for n in ("java.png", "leopard.png", "parque1.png") if present(n)]
    copy_names = [n for n in ("brick.png", "wood1.png", "granite1.png") if present(n)]
    make = []
    for n in seam_names:
        w, h = size_of(ex[n])
        cw, ch = w - 17, h - 13
        make += [["crop", ex[n], t("crop-" + n), "5", "7", str(cw), str(ch)],
                 ["tile", t("crop-" + n), t("tiled-" + n), "2", "2"],
                 ["roll", t("crop-" + n), t("rolled-" + n), str(cw // 3), str(ch // 2)],
                 ["tile", t("crop-" + n), t("wide-" + n), "2", "1"]]
    for n in collage_names:
        make += [["blocks", ex[n], t("collage-wrapped-" + n), "256", "256", "32", "4", "16"],
                 ["blocks", ex[n], t("collage-cut-" + n), "256", "256", "32", "4", "0"]]
    make += [["blur", ex[n], t("blur-" + n), "4"] for n in blur_names]
    make.append(["noise", t("noise.png"), "64", "64", "3"])
    for n in copy_names:
        w, h = size_of(ex[n])
        make += [["tile", ex[n], t("tile22-" + n), "2", "2"],
                 ["roll", ex[n], t("roll-" + n), str(w // 2 + 3), str(h // 2 - 5)]]
    if present("canyons2.png"):
        make += [["crop", ex["canyons2.png"], t("c128.png"), "0", "0", "128", "128"],
                 ["blocks", t("c128.png"), t("c128-collage-1024.png"), "1024", "1024", "32", "9"]]
    make.append(["crop", ex[names[0]], t("tiny.png"), "0", "0", "6", "40"])
    fixtures(make)

    # Every result measured against an exemplar without options: the
    # exemplar itself first, then the checks' results.
    plain = {n: [ex[n]] for n in names}
    for n in blur_names:
        plain[n].append(t("blur-" + n))
    for n in noise_names:
        plain[n].append(t("noise.png"))
    for n in copy_names:
        plain[n] += [t("tile22-" + n), t("roll-" + n)]
    # The other checks' measures: name -> (exemplar, results, options).
    asked = {}
    for n in seam_names:
        crop, tiled, rolled, wide = (t(k + "-" + n) for k in ("crop", "tiled", "rolled", "wide"))
        for option in ("--tileable", "--tileable=x", "--tileable=y"):
            asked["tiled crop %s %s" % (n, option)] = (crop, [tiled], [option])
            asked["wide %s %s" % (n, option)] = (wide, [crop], [option])
        asked["crop vs tiling " + n] = (tiled, [crop, rolled], ["--tileable"])
    for n in collage_names:
        asked["collage " + n] = (ex[n], [t("collage-wrapped-" + n), t("collage-cut-" + n)],
                                 ["--tileable"])
    for n in copy_names:
        asked["rolled tileable " + n] = (ex[n], [t("roll-" + n)], ["--tileable"])
    if present("canyons2.png"):
        asked["bigger"] = (t("c128.png"), [t("c128-collage-1024.png")], [])
    # All in one run: one GEGL start-up.
    lists = [(ex[n], plain[n], []) for n in names] + list(asked.values())
    start = time.monotonic()
    answers = measure_lists(lists)
    print("%d argument lists, %d results, in one run: %.2f s"
          % (len(lists), sum(len(r) for _, r, _ in lists), time.monotonic() - start))
    got = {n: dict(zip(plain[n], rows)) for n, rows in zip(names, answers)}
    answer = dict(zip(asked, answers[len(names):]))

    # --- every exemplar against itself: perfect scores --------------------
    for n in names:
        m = got[n][ex[n]]
        print("%-14s self: coherence %.4f completeness %.4f copy %.4f sharpness %.4f"
              % (n, m["coherence"], m["completeness"], m["copy"], m["sharpness"]))
        check(m["coherence"] < 0.01, "%s self coherence %r" % (n, m["coherence"]))
        check(m["completeness"] < 0.01, "%s self completeness %r" % (n, m["completeness"]))
        check(m["copy"] > 0.99, "%s self copy %r" % (n, m["copy"]))
        check(abs(m["sharpness"] - 1) < 0.01, "%s self sharpness %r" % (n, m["sharpness"]))
        check(m["seam"] is None and m["tileable"] == "none", "%s: seam without --tileable" % n)
        check(0.0 <= m["anisotropy_exemplar"] <= 1.0,
              "%s anisotropy %r outside [0, 1]" % (n, m["anisotropy_exemplar"]))

    # --- several results and argument lists in one run ----------------------
    # Each result gets the figures it gets alone, whatever else the run
    # measures, and each list has its own options.
    if blur_names and seam_names:
        n, s = blur_names[0], seam_names[0]
        alone, together = measure(ex[n], t("blur-" + n)), got[n][t("blur-" + n)]
        check(alone == together, "%s blurred, alone %r, with others %r" % (n, alone, together))
        alone = measure(t("wide-" + s), t("crop-" + s), "--tileable=x")
        together = answer["wide %s --tileable=x" % s][0]
        check(alone == together, "%s wide --tileable=x, alone %r, in a list among others %r"
              % (s, alone, together))
    first = ex[names[0]]
    code, out, err = run(first, first, "+", "--bogus")
    check(code == 2 and "unknown option '--bogus'" in err,
          "a bad argument list after a good one: exit 2 %d %r" % (code, err))
    code, out, err = run(first, first, "+")
    check(code == 2 and "missing EXEMPLAR and RESULT" in err,
          "an empty argument list: exit 2 %d %r" % (code, err))

    # --- text output format ---------------------------------------------
    code, out, err = run(first, first)
    keys = [line.split(":")[0] for line in out.splitlines()]
    check(code == 0 and keys == ["coherence", "completeness", "copy", "sharpness", "axis-edges"],
          "text output: %r" % out)
    # Several results, in one or two argument lists: each one's figures
    # after a line naming it.
    code, out, err = run("--tileable", first, first, "+", "--tileable", first, first, t("tiny.png"))
    check(code == 2 and len(out.split("result: ")) == 2 and "tiny.png" in err,
          "a result too small in a later list: the first list's figures, none of that list's: "
          "%d %r %r" % (code, out, err))
    code, out, err = run("--tileable", first, first, t("noise.png"), "+", "--tileable", first, first)
    blocks = out.split("result: ")
    check(code == 0 and blocks[0] == "" and len(blocks) == 4,
          "three results, each after 'result: ': %r" % out)
    for block, path in zip(blocks[1:], (first, t("noise.png"), first)):
        lines = block.splitlines()
        keys = [line.split(":")[0] for line in lines[1:]]
        check(lines[0] == path and "seam" in keys, "--tileable prints seam for %s: %r" % (path, out))
        for line in lines[1:]:
            name, _, value = line.partition(": ")
            try:
                float(value)
            except ValueError:
                check(False, "not 'name: value': %r" % line)

    # --- seams -------------------------------------------------------------
    for n in seam_names:
        # Tiled 2x2: the crop's wrap-around edges are seams, its inside is
        # verbatim.
        for option in ("--tileable", "--tileable=x", "--tileable=y"):
            m = answer["tiled crop %s %s" % (n, option)][0]
            print("%-14s 2x2 tiling of a crop %s: seam %.3f" % (n, option, m["seam"]))
            check(m["seam"] > 1.1, "%s tiled crop %s: seam %r, want > 1.1" % (n, option, m["seam"]))
        # Against an exemplar holding every wrapped window (the crop tiled),
        # the crop itself is seamless: its wrapped windows are all there.
        for m in answer["crop vs tiling " + n]:
            check(0.9 < m["seam"] < 1.1 and m["coherence"] < 0.01,
                  "%s crop vs its tiling: seam %r coherence %r" % (n, m["seam"], m["coherence"]))
        # One direction only: tiled horizontally, the crop wraps seamlessly
        # in x but not in y.
        mx, my, mxy = (answer["wide %s %s" % (n, option)][0]
                       for option in ("--tileable=x", "--tileable=y", "--tileable"))
        check(0.9 < mx["seam"] < 1.1 and mx["tileable"] == "x", "%s x: seam %r" % (n, mx["seam"]))
        check(my["seam"] > 1.1 and my["tileable"] == "y", "%s y: seam %r" % (n, my["seam"]))
        check(mxy["seam"] > 1.1, "%s xy: seam %r" % (n, mxy["seam"]))

    # A collage of exemplar blocks whose blocks straddle the edges intact
    # tiles as well as its inside; the same collage cut at block edges not.
    for n in collage_names:
        mw, mc = answer["collage " + n]
        check(mw["seam"] < 1.1, "%s tileable collage: seam %r" % (n, mw["seam"]))
        check(mc["seam"] > 1.1, "%s collage cut at the edge: seam %r" % (n, mc["seam"]))
        check(abs(mw["coherence"] - mc["coherence"]) < 1e-3,
              "%s: same windows on the torus, same coherence" % n)
        check(0.5 < mw["coherence"] < 20 and mw["copy"] < 0.1,
              "%s collage: coherence %r copy %r" % (n, mw["coherence"], mw["copy"]))

    # --- blur: sharpness well below 1 ---------------------------------------
    for n in blur_names:
        m = got[n][t("blur-" + n)]
        check(m["sharpness"] < 0.7, "%s blurred: sharpness %r" % (n, m["sharpness"]))
        check(m["coherence"] > 1 and m["copy"] < 0.2,
              "%s blurred: coherence %r copy %r" % (n, m["coherence"], m["copy"]))

    # --- noise: nothing like the exemplar -----------------------------------
    for n in noise_names:
        m, self_m = got[n][t("noise.png")], got[n][ex[n]]
        check(m["coherence"] > 15 and m["completeness"] > 10 and m["copy"] < 0.01,
              "%s vs noise: %r" % (n, m))
        check(m["coherence"] > self_m["coherence"] + 15, "%s noise vs self" % n)

    # --- copy ---------------------------------------------------------------
    for n in copy_names:
        m = got[n][t("tile22-" + n)]
        check(m["copy"] > 0.99, "%s 2x2 tiling: copy %r" % (n, m["copy"]))
        m = got[n][t("roll-" + n)]
        check(0.1 < m["copy"] < 0.5, "%s rolled: copy %r, want a quadrant" % (n, m["copy"]))
        m = answer["rolled tileable " + n][0]
        check(m["copy"] > 0.99, "%s rolled, tileable: copy %r, want 1" % (n, m["copy"]))

    # --- bigger results -----------------------------------------------------
    if present("canyons2.png"):
        m = answer["bigger"][0]
        check(m["completeness"] < 1.5 and m["copy"] < 0.2, "1024 collage: %r" % m)

    # --- errors -------------------------------------------------------------
    code, out, err = run(t("missing.png"), first)
    check(code == 2 and "cannot read" in err and "missing.png" in err,
          "missing file: %d %r" % (code, err))
    code, out, err = run(first, t("missing.png"))
    check(code == 2 and "missing.png" in err, "missing result: %d %r" % (code, err))
    with open(t("not-an-image.png"), "w") as f:
        f.write("hello\n")
    code, out, err = run(first, t("not-an-image.png"))
    check(code == 2 and "not-an-image.png" in err, "not an image: %d %r" % (code, err))
    code, out, err = run(first, t("tiny.png"))
    check(code == 2 and "7x7" in err, "too small: %d %r" % (code, err))
    code, out, err = run("--bogus", first, first)
    check(code == 2 and "unknown option '--bogus'" in err, "bad option: %d %r" % (code, err))
    code, out, err = run("--tileable=z", first, first)
    check(code == 2 and "--tileable=z" in err, "bad --tileable: %d %r" % (code, err))
    code, out, err = run(first)
    check(code == 2 and "missing RESULT" in err, "one argument: %d %r" % (code, err))
    code, out, err = run()
    check(code == 2 and err, "no arguments: %d %r" % (code, err))
    code, out, err = run("--help")
    check(code == 0 and "Usage: texsynth-measure" in out and "--tileable=x" in out,
          "--help: %d" % code)

    if failures:
        print("%d check(s) failed" % len(failures), file=sys.stderr)
        return 1
    print("all checks passed")
    return 0


if __name__ == "__main__":
    sys.exit(main())
