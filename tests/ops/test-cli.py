# texsynth:synthesize through the real `gegl` command-line tool: output
# size, determinism, seeds, tiling, input formats and bad inputs.
# SPDX-License-Identifier: LGPL-3.0-or-later

import os

import tsops
from tsops import check, note

tsops.require_op()
tmp = tsops.workdir()
brick = tsops.exemplar("brick.png")        # 96x96
out = lambda name: os.path.join(tmp, name)


def synth(src, name, env=None, extra_ops=(), **props):
    code, _, err = tsops.synthesize_cli(src, out(name), env=env, extra_ops=extra_ops, **props)
    warnings = tsops.op_warnings(err)
    if code != 0 or not os.path.isfile(out(name)):
        tsops.die("gegl failed (exit %d) for %s:\n%s" % (code, name, err))
    return tsops.load(out(name)), warnings


note("-- size")
(w, h, a), warnings = synth(brick, "a.png", width=200, height=150, seed=7)
check((w, h) == (200, 150), "a 96x96 exemplar gives the requested 200x150 (got %dx%d)" % (w, h))
check(not warnings, "no warning on a good exemplar %s" % warnings)
check(min(tsops.alphas(a)) > 0.99, "an opaque exemplar gives an opaque result")
(w1, h1, _), _ = synth(brick, "tall.png", width=37, height=301, seed=7)
check((w1, h1) == (37, 301), "odd, non-square size 37x301 (got %dx%d)" % (w1, h1))

note("-- determinism and seeds")
(_, _, b), _ = synth(brick, "b.png", width=200, height=150, seed=7)
check(a == b, "the same seed gives identical pixels")
(_, _, t1), _ = synth(brick, "t1.png", env={"OMP_NUM_THREADS": "1"}, width=200, height=150, seed=7)
(_, _, t2), _ = synth(brick, "t2.png", env={"OMP_NUM_THREADS": "2"}, width=200, height=150, seed=7)
check(t1 == t2 == a, "identical with 1 and 2 threads")
(_, _, c), _ = synth(brick, "c.png", width=200, height=150, seed=8)
check(tsops.max_abs_diff(a, c) > 0.1, "another seed gives another texture")

note("-- tileable")
(wt, ht, t), warnings = synth(brick, "tile.png", width=160, height=128, seed=7, tileable=True)
check((wt, ht) == (160, 128) and not warnings, "tileable=true gives 160x128 without warnings")
# One image's wrap-around edge may fall on a natural edge (mortar), so
# compare averages over a few exemplars; the quality test measures seams
# properly.
# A small-size run makes one pair and leaves the comparison to the native run.
seams = {True: [], False: []}
for name in ("brick",) if tsops.small() else ("brick", "wood1", "granite1", "java"):
    for tileable in (True, False):
        (sw, sh, s), _ = synth(tsops.exemplar(name + ".png"), "seam.png", width=128, height=96,
                               seed=7, tileable=tileable)
        seams[tileable].append(max(tsops.wrap_seam_excess(sw, sh, s)))
mean_t, mean_p = (sum(seams[k]) / len(seams[k]) for k in (True, False))
note("      wrap-around edges: tileable step %.2f, plain %.2f" % (mean_t, mean_p))
if not tsops.small():
    check(mean_t <= 1.2 and mean_t + 0.2 <= mean_p,
          "wrap-around edges: tileable step %.2f (<= 1.2) vs plain %.2f, in multiples of the "
          "90th percentile of inner boundaries" % (mean_t, mean_p))

note("-- input formats")
formats = [
    ("grey.png", "Y' u8", 8, None),
    ("rgb.png", "R'G'B' u8", 8, None),
    ("rgba16.png", "R'G'B'A u16", 16, None),
    ("alpha.png", "R'G'B'A u8", 8, lambda x, y, w, h: 0.0 if x < w // 3 else 1.0),
]
for name, fmt, depth, alpha_fn in formats:
    src = out("in-" + name)
    tsops.convert(brick, src, fmt, depth, alpha_fn)
    (fw, fh, f), warnings = synth(src, "out-" + name, width=64, height=48, seed=3)
    ok = (fw, fh) == (64, 48) and not warnings and max(tsops.alphas(f)) > 0.99
    check(ok, "%s exemplar (%s, %d-bit) synthesises 64x48 %s" % (name, fmt, depth, warnings))
    if fmt.startswith("Y"):
        spread = max(max(f[i:i + 3]) - min(f[i:i + 3]) for i in range(0, len(f), 4))
        check(spread < 0.02, "a grey exemplar gives a grey result (max R-G-B spread %.4f)" % spread)

note("-- bad inputs: a warning from the op, a transparent image, no crash")
tsops.convert(brick, out("transparent.png"), "R'G'B'A u8", 8, lambda x, y, w, h: 0.0)
code, _, err = tsops.run_gegl(["-i", brick, "-o", out("tiny.png"), "--", "gegl:crop",
                               "width=2", "height=2"])
cases = [
    ("fully transparent", out("transparent.png"), {}, (), "transparent"),
    ("2x2", out("tiny.png"), {}, (), "2x2"),
    # Far beyond the memory limit; the crop keeps gegl from writing a
    # 16384x16384 file of the (transparent) result.
    ("16384x16384", brick, {"width": 16384, "height": 16384},
     ("gegl:crop", "width=16", "height=16"), "MiB"),
]
for label, src, props, extra, word in cases:
    props = dict({"width": 40, "height": 30}, **props)
    (bw, bh, bad), warnings = synth(src, "bad.png", extra_ops=extra, **props)
    check(len(warnings) >= 1 and word in warnings[0],
          "%s exemplar: warning '%s...' mentions '%s'" % (label, tsops.PREFIX, word))
    if warnings:
        note("      " + warnings[0].strip())
    check(max(tsops.alphas(bad)) == 0.0, "%s exemplar: the result is fully transparent" % label)
generated = [
    ("no input at all", [], "no pixels"),
    # An infinite plane: GEGL must not be asked to render all of it.
    ("an unbounded input", ["gegl:color", "value=red"], "unbounded"),
    ("a 16385x20 input", ["gegl:color", "value=red", "gegl:crop", "width=16385", "height=20"],
     "16385x20"),
]
for label, source_ops, word in generated:
    code, _, err = tsops.run_gegl(["-o", out("gen.png"), "--"] + source_ops +
                                  [tsops.OP, "width=10", "height=10"], timeout=120)
    warnings = tsops.op_warnings(err)
    check(code == 0 and warnings and word in warnings[0],
          "%s: a warning mentioning '%s', no crash or hang %s" % (label, word, warnings))

tsops.finish()
