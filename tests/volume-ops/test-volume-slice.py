# texsynth:volume-slice through the gegl tool and an XML graph: output
# sizes of a slice and of an atlas, determinism of the seed, XML equal to
# the command line, and the messages for bad input. A slice that another
# must equal is made by the gegl tool, in a process of its own, so the
# volume cache (operations/volume-cache.c) cannot hand the first one's
# volume back; the others run on the tool's graph in this process
# (tsops.run_gegl_here), sparing a GEGL start-up each.
# SPDX-License-Identifier: LGPL-3.0-or-later

import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import volops  # noqa: E402
from volops import SLICE, tsops  # noqa: E402
from tsops import check, note  # noqa: E402

volops.require_ops(SLICE)
tmp = tsops.workdir()
bark = tsops.exemplar("bark.png")


def slice_cli(dst, source=None, tool=False, **props):
    """gegl -i SOURCE -o DST -- texsynth:volume-slice ..., in this process
    or with `tool` through the gegl tool; returns (exit code, warnings of
    the op, stderr)."""
    if os.path.exists(dst):
        os.unlink(dst)
    head = ["-i", source or bark] if source != "" else []
    args = head + ["-o", dst, "--", SLICE] + volops.prop_args(props)
    code, _, err = tsops.run_gegl(args) if tool else tsops.run_gegl_here(args)
    return code, volops.op_warnings(err, SLICE), err


def pixels(path):
    return volops.load_u8(path)


note("-- sizes of a slice and of an atlas")
base = {"size": 16, "seed": 1, "iterations": 2}
s1 = os.path.join(tmp, "s1.png")
code, warnings, _ = slice_cli(s1, **base)
w, h, px1 = pixels(s1) if code == 0 and os.path.isfile(s1) else (0, 0, b"")
check(code == 0 and not warnings and (w, h) == (16, 16),
      "size=16 slice: exit %d, %dx%d, %s" % (code, w, h, warnings or "no warning"))
check(min(px1[3::4], default=0) == 255, "a slice of an opaque exemplar's volume is opaque")

atlas = os.path.join(tmp, "atlas.png")
code, warnings, _ = slice_cli(atlas, size=20, axis="x", layout="atlas", seed=1, iterations=2)
w, h, pxa = pixels(atlas) if code == 0 and os.path.isfile(atlas) else (0, 0, b"")
check(code == 0 and not warnings and (w, h) == volops.atlas_extent(20) == (100, 80),
      "size=20 atlas across x: %dx%d (5 x 4 cells of 20)" % (w, h))
# 20 slices in a 5 x 4 grid fill every cell: all opaque.
check(min(pxa[3::4], default=0) == 255, "every atlas cell holds a slice")

note("-- determinism: the same seed gives the same bytes, another seed others")
s1b, s2 = os.path.join(tmp, "s1b.png"), os.path.join(tmp, "s2.png")
slice_cli(s1b, tool=True, **base)
slice_cli(s2, **dict(base, seed=2))
px1b, px2 = pixels(s1b)[2], pixels(s2)[2]
check(px1b == px1 and len(px1) == 16 * 16 * 4, "seed 1 twice: identical slices")
check(px2 != px1 and len(px2) == len(px1), "seed 2: another slice (%d of %d bytes differ)"
      % (sum(a != b for a, b in zip(px1, px2)), len(px1)))

note("-- the cell structure: another volume, opaque and reproducible")
sc, scb = os.path.join(tmp, "sc.png"), os.path.join(tmp, "scb.png")
code, warnings, _ = slice_cli(sc, cell_structure="on", **base)
slice_cli(scb, tool=True, cell_structure="on", **base)
w, h, pxc = pixels(sc) if code == 0 and os.path.isfile(sc) else (0, 0, b"")
check(code == 0 and not warnings and (w, h) == (16, 16) and min(pxc[3::4], default=0) == 255,
      "cell-structure=on: exit %d, %dx%d, %s, opaque" % (code, w, h, warnings or "no warning"))
check(pxc != px1 and pxc == pixels(scb)[2], "cell-structure=on: another slice than without, "
      "the same twice")
# The default is automatic: off for bark, on for stones in mortar.
soff = os.path.join(tmp, "soff.png")
slice_cli(soff, tool=True, cell_structure="off", **base)
check(pixels(soff)[2] == px1, "bark: the default (automatic) slice is the one with cell-structure=off")
stones = tsops.exemplar("stone33.png")
sauto, son = os.path.join(tmp, "sauto.png"), os.path.join(tmp, "son.png")
code, warnings, _ = slice_cli(sauto, stones, cell_structure="auto", **base)
slice_cli(son, stones, tool=True, cell_structure="on", **base)
pxauto = pixels(sauto)[2] if code == 0 and os.path.isfile(sauto) else b""
check(code == 0 and not warnings and len(pxauto) == 16 * 16 * 4 and pxauto == pixels(son)[2],
      "stone33: cell-structure=auto gives the slice of cell-structure=on (exit %d, %s)"
      % (code, warnings or "no warning"))

note("-- an XML graph gives the same slice as the command line")
xml = os.path.join(tmp, "slice.xml")
with open(xml, "w") as f:
    f.write("<?xml version='1.0' encoding='UTF-8'?>\n<gegl>\n"
            "  <node operation='%s'>\n    <params>\n%s    </params>\n  </node>\n"
            "  <node operation='gegl:load'>\n    <params><param name='path'>%s</param>"
            "</params>\n  </node>\n</gegl>\n"
            % (SLICE, "".join("      <param name='%s'>%s</param>\n" % (k, v)
                              for k, v in base.items()), bark))
sx = os.path.join(tmp, "sx.png")
code, _, err = tsops.run_gegl([xml, "-o", sx])
check(code == 0 and os.path.isfile(sx) and pixels(sx)[2] == px1,
      "gegl slice.xml -o sx.png equals the command-line slice")

note("-- bad input: a warning that says what is wrong, a transparent result")
bad = os.path.join(tmp, "bad.png")
crop = lambda w, h: ["gegl:crop", "width=%d" % w, "height=%d" % h]  # noqa: E731


def bad_case(label, word, expect, source=None, extra_ops=(), glib_word=None, **props):
    if os.path.exists(bad):
        os.unlink(bad)
    head = ["-i", source or bark] if source != "" else []
    code, _, err = tsops.run_gegl_here(head + ["-o", bad, "--"] + list(extra_ops) + [SLICE]
                                       + volops.prop_args(props))
    warnings = volops.op_warnings(err, SLICE)
    w, h, px = pixels(bad) if code == 0 and os.path.isfile(bad) else (0, 0, b"")
    ok = (code == 0 and bool(warnings) and word in warnings[0] and (w, h) == expect
          and max(px[3::4], default=0) == 0)
    if glib_word:
        ok = ok and glib_word in err
    check(ok, "%s: exit %d, %dx%d, %s" % (label, code, w, h,
                                         warnings[0] if warnings else "no warning"))


bad_case("index 16 of a size-16 volume", "index must be 0 to 15", (16, 16), size=16, index=16)
bad_case("index 1000", "slice 1000 does not exist", (16, 16), size=16, index=1000)
bad_case("transparent exemplar", "fully transparent", (16, 16), "",
         ["gegl:color", "value=transparent"] + crop(32, 32), size=16)
bad_case("2x2 exemplar", "2x2", (16, 16), None, crop(2, 2), size=16)
bad_case("translucent exemplar with the cell structure", "needs opaque exemplars", (16, 16),
         None, ["gegl:opacity", "value=0.5"], size=16, cell_structure="on")
bad_case("memory limit 1 MiB", "limit of 1.0 MiB", (32, 32), size=32, memory_limit=1)
# GObject refuses an out-of-range size with its own message and keeps the
# default (128); the memory limit then refuses that without synthesising.
bad_case("size 0", "limit of 1.0 MiB", (128, 128), glib_word="size", size=0, memory_limit=1)
bad_case("unbounded exemplar", "unbounded", (16, 16), "", ["gegl:color", "value=red"],
         size=16)

tsops.finish()
