# texsynth:synthesize from Python through GObject introspection: metadata,
# property specs, buffers of many formats, bounds, progress, caching.
# SPDX-License-Identifier: LGPL-3.0-or-later

import struct

import tsops
from tsops import check, note

tsops.require_op()
Gegl = tsops.gegl()
OP = tsops.OP

note("-- metadata and properties")
check(Gegl.has_operation(OP), "Gegl.has_operation('%s')" % OP)
for key in ("title", "description", "categories"):
    value = Gegl.Operation.get_key(OP, key)
    check(bool(value), "key %s = %r" % (key, value))
check(not Gegl.Operation.get_key(OP, "license"), "no license key")

specs = {p.name: p for p in Gegl.Operation.list_properties(OP)}
expected = {"width", "height", "tileable", "quality", "seed", "patch-size",
            "fine-patch-size", "iterations", "histogram-matching"}
check(expected <= set(specs), "properties %s" % sorted(specs))
for name in ("width", "height"):
    p = specs.get(name)
    check(p and (p.minimum, p.maximum, p.default_value) == (1, 16384, 512),
          "%s: 1..16384, default 512" % name)
p = specs.get("quality")
check(p and p.minimum == 1 and p.maximum == 10 and 1 <= p.default_value <= 10,
      "quality: 1..10, default %s" % (p and p.default_value))
for name in ("patch-size", "fine-patch-size", "iterations"):
    p = specs.get(name)
    check(p and p.minimum == 0 and p.default_value == 0, "%s: 0 = automatic by default" % name)
check(specs.get("tileable") and specs["tileable"].default_value is False, "tileable: off by default")
for name in sorted(expected & set(specs)):
    check(bool(specs[name].nick) and bool(specs[name].blurb),
          "%s has a label and a description" % name)

# The exemplar, as float RGBA, to be offered in other formats.
ex_w, ex_h, ex_px = tsops.load(tsops.exemplar("brick.png"))
ex_rect = Gegl.Rectangle.new(0, 0, ex_w, ex_h)
ex_rgba = Gegl.Buffer.new("R'G'B'A float", 0, 0, ex_w, ex_h)
ex_rgba.set(ex_rect, "R'G'B'A float", struct.pack("%df" % len(ex_px), *ex_px))


def exemplar_buffer(fmt, x=0, y=0):
    buf = Gegl.Buffer.new(fmt, x, y, ex_w, ex_h)
    ex_rgba.copy(ex_rect, Gegl.AbyssPolicy.NONE, buf, Gegl.Rectangle.new(x, y, ex_w, ex_h))
    return buf


def synth_node(buf, **props):
    return tsops.op_on_buffer(buf, OP, **props)


note("-- buffers of many formats")
for fmt in ("R'G'B'A u8", "R'G'B' u8", "R'G'B'A u16", "Y' u8", "Y'A float",
            "RGBA float", "RGB half", "CIE Lab float", "CIE Lab alpha float"):
    graph, _, op = synth_node(exemplar_buffer(fmt), width=48, height=40, seed=1)
    w, h, px = tsops.render(op)
    check((w, h) == (48, 40) and min(tsops.alphas(px)) > 0.99, "%s exemplar -> 48x40, opaque" % fmt)

note("-- bounds: the output is at the origin whatever the input")
graph, _, op = synth_node(exemplar_buffer("R'G'B'A u8", 30, 40), width=70, height=50, seed=1)
box = op.get_bounding_box()
check((box.x, box.y, box.width, box.height) == (0, 0, 70, 50),
      "bounding box (%d, %d, %d, %d)" % (box.x, box.y, box.width, box.height))
w, h, offset_px = tsops.render(op)
_, _, op0 = synth_node(exemplar_buffer("R'G'B'A u8"), width=70, height=50, seed=1)
_, _, origin_px = tsops.render(op0)
check(offset_px == origin_px, "an exemplar at (30, 40) gives the same texture as at (0, 0)")

note("-- progress")
graph, _, op = synth_node(exemplar_buffer("R'G'B'A u8"), width=96, height=96, seed=2)
reports = []
op.connect("progress", lambda node, fraction, *rest: reports.append(fraction))
tsops.render(op)
fractions = reports
check(len(reports) >= 2, "%d progress reports" % len(reports))
check(fractions == sorted(fractions) and fractions and fractions[-1] == 1.0,
      "progress never goes back and ends at 1.0")

note("-- caching and invalidation")
graph, source, op = synth_node(exemplar_buffer("R'G'B'A u8"), width=64, height=64, seed=3)
_, _, first = tsops.render(op)
_, _, again = tsops.render(op)
check(first == again, "rendering twice gives the same pixels")
op.set_property("seed", 4)
_, _, other = tsops.render(op)
check(tsops.max_abs_diff(first, other) > 0.1, "changing the seed re-synthesises")
op.set_property("seed", 3)
_, _, back = tsops.render(op)
check(back == first, "the original seed gives the original texture back")

note("-- a bad exemplar, then a good one on the same node")
clear = Gegl.Buffer.new("R'G'B'A u8", 0, 0, 32, 32)
source.set_property("buffer", clear)
_, _, bad = tsops.render(op)
check(max(tsops.alphas(bad)) == 0.0, "a fully transparent exemplar gives a transparent result")
source.set_property("buffer", exemplar_buffer("R'G'B'A u8"))
_, _, good = tsops.render(op)
check(good == first, "with the exemplar back, the same texture as before")

tsops.finish()
