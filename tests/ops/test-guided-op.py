#!/usr/bin/env python3
# texsynth:guided in GEGL (Python, in-process): texture by numbers with a
# two-texture exemplar (cracked | wood1) and its label map, grown into
# discs; its source map puts each pixel's source in the label's half;
# the output takes the input's size and place; style transfer follows
# the input's lightness; the same seed gives the same result; bad input
# (a missing exemplar, a guide of the wrong size, a one-pixel target, a
# NaN guide) gives one warning and a transparent result.
# SPDX-License-Identifier: LGPL-3.0-or-later
import math
import struct
import sys

sys.path.insert(0, __import__("os").path.dirname(__file__))
import tsops  # noqa: E402

OP = "texsynth:guided"
tsops.OP = OP
tsops.PREFIX = OP + ": "
RGBA = "R'G'B'A float"
EX_W, EX_H, OUT = 128, 96, 160


def buffer_of(width, height, floats, fmt=RGBA, x=0, y=0):
    Gegl = tsops.gegl()
    buf = Gegl.Buffer.new(fmt, x, y, width, height)
    rect = Gegl.Rectangle.new(x, y, width, height)
    buf.set(rect, fmt, struct.pack("%df" % len(floats), *floats))
    return buf


def crop(path, width, height):
    w, h, px = tsops.load(tsops.exemplar(path))
    return [px[(y * w + x) * 4 + c] for y in range(height) for x in range(width) for c in range(4)]


def two_textures():
    left, right = crop("cracked.png", EX_W // 2, EX_H), crop("wood1.png", EX_W // 2, EX_H)
    half = EX_W // 2
    pixels, labels = [], []
    for y in range(EX_H):
        for x in range(EX_W):
            src, sx = (right, x - half) if x >= half else (left, x)
            pixels += src[(y * half + sx) * 4:(y * half + sx) * 4 + 4]
            v = 1.0 if x >= half else 0.0
            labels += [v, v, v, 1.0]
    return buffer_of(EX_W, EX_H, pixels), buffer_of(EX_W, EX_H, labels)


def disc_label(x, y):
    dx, dy = x % 80 - 40, y % 80 - 40
    return 1.0 if dx * dx + dy * dy < 26 * 26 else 0.0


def target_buffer(size=OUT, x=0, y=0, value=None):
    floats = []
    for j in range(size):
        for i in range(size):
            v = disc_label(i, j) if value is None else value
            floats += [v, v, v, 1.0]
    return buffer_of(size, size, floats, x=x, y=y)


def guided(target, exemplar, exemplar_guide=None, fmt=RGBA, **props):
    """Renders texsynth:guided: (width, height, floats, box, warnings)."""
    Gegl = tsops.gegl()
    graph, _, node = tsops.op_on_buffer(target, OP, **props)
    for pad, buf in (("aux", exemplar), ("aux2", exemplar_guide)):
        if buf is not None:
            src = graph.create_child("gegl:buffer-source")
            src.set_property("buffer", buf)
            src.connect_to("output", node, pad)
    with tsops.captured_stderr() as err:
        box = node.get_bounding_box()
        w, h, data = tsops.render_bytes(node, fmt)
    floats = struct.unpack("%df" % (len(data) // 4), data)
    del Gegl
    return w, h, floats, (box.x, box.y), tsops.op_warnings("".join(err))


def near_edge(x, y, margin=3):
    v = disc_label(x, y)
    return any(disc_label(min(max(x + dx, 0), OUT - 1), min(max(y + dy, 0), OUT - 1)) != v
               for dy in range(-margin, margin + 1) for dx in range(-margin, margin + 1))


def test_texture_by_numbers():
    exemplar, labels = two_textures()
    w, h, coords, box, warnings = guided(target_buffer(x=10, y=20), exemplar, labels,
                                         fmt="float[2] ", seed=3, source_map=True)
    tsops.check((w, h, box) == (OUT, OUT, (10, 20)),
                "the output takes the input's size and place (%dx%d at %s)" % (w, h, box))
    tsops.check(not warnings, "texture by numbers runs without warnings %s" % warnings)
    judged = right = 0
    for y in range(OUT):
        for x in range(OUT):
            if near_edge(x, y):
                continue
            sx = coords[2 * (y * OUT + x)]
            judged += 1
            right += (1.0 if sx >= EX_W / 2 else 0.0) == disc_label(x, y)
    fidelity = right / max(judged, 1)
    tsops.note("label fidelity by source map: %.3f" % fidelity)
    tsops.check(tsops.small() or fidelity >= 0.95, "label fidelity %.3f >= 0.95" % fidelity)
    _, _, a, _, _ = guided(target_buffer(), exemplar, labels, seed=5)
    _, _, b, _, _ = guided(target_buffer(), exemplar, labels, seed=5)
    tsops.check(a == b, "the same seed gives the same result")
    tsops.check(min(a[3::4]) == 1.0, "the result is opaque")


def test_style_transfer():
    w, h, px = tsops.load(tsops.exemplar("bark.png"))
    exemplar = buffer_of(w, h, px)
    floats = []
    for j in range(96):
        for i in range(128):
            v = 0.25 + 0.5 * i / 128 + (0.2 if (i - 64) ** 2 + (j - 48) ** 2 < 30 ** 2 else 0.0)
            floats += [v, v, v, 1.0]
    target = buffer_of(128, 96, floats)
    ow, oh, out, _, warnings = guided(target, exemplar, fmt="Y' float", seed=2)
    tsops.check((ow, oh) == (128, 96) and not warnings, "style transfer runs (%dx%d)" % (ow, oh))
    # Correlation of 8x8 block means of the lightness.
    def blocks(values):
        return [sum(values[(by * 8 + y) * 128 + bx * 8 + x] for y in range(8) for x in range(8))
                for by in range(12) for bx in range(16)]
    a, b = blocks(floats[0::4]), blocks(out)
    ma, mb = sum(a) / len(a), sum(b) / len(b)
    cov = sum((p - ma) * (q - mb) for p, q in zip(a, b))
    r = cov / math.sqrt(sum((p - ma) ** 2 for p in a) * sum((q - mb) ** 2 for q in b))
    tsops.note("style transfer: blurred lightness correlation %.3f" % r)
    tsops.check(tsops.small() or r >= 0.9, "blurred lightness correlation %.3f >= 0.9" % r)


def expect_refused(what, target, exemplar, exemplar_guide=None):
    w, h, px, _, warnings = guided(target, exemplar, exemplar_guide, seed=1)
    tsops.check(len(warnings) == 1 and all(v == 0.0 for v in px[3::4]),
                "%s: one warning, a transparent result (%s)" % (what, "; ".join(warnings)))


def test_bad_input():
    exemplar, labels = two_textures()
    expect_refused("no exemplar", target_buffer(), None)
    expect_refused("a guide of another size than the exemplar", target_buffer(), exemplar,
                   target_buffer(size=40))
    expect_refused("a one-pixel target", target_buffer(size=1), exemplar, labels)
    expect_refused("a NaN in the target guide", target_buffer(value=float("nan")), exemplar,
                   labels)


tsops.gegl()
if not tsops.gegl().has_operation(OP):
    tsops.die("GEGL cannot find %s (GEGL_PATH)" % OP)
test_texture_by_numbers()
test_style_transfer()
test_bad_input()
tsops.finish()
