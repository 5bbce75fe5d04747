# The layout as an image: texsynth:synthesize and
# texsynth:tileable with source-map=true give, per pixel, the absolute
# pixel-centre coordinates of the input pixel it comes from, as
# gegl:map-absolute reads them. Applied with sampler-type=nearest to the
# exemplar itself, the map reproduces the colour result exactly; applied to
# another map aligned with the exemplar, it gives that map the same layout.
# SPDX-License-Identifier: LGPL-3.0-or-later

import math
import struct

import tsops
from tsops import check, note

tsops.require_op()
Gegl = tsops.gegl()
for op in ("texsynth:tileable", "gegl:map-absolute", "gegl:gray"):
    check(Gegl.has_operation(op), "%s exists" % op)
LAB = "CIE Lab alpha float"


def exemplar_node(graph, path, translate=(0, 0), height_map=False):
    """gegl:load of `path` in `graph`, moved by `translate`, optionally
    turned into a grey "height map" (a pixel-wise function of it)."""
    node = graph.create_child("gegl:load")
    node.set_property("path", path)
    if translate != (0, 0):
        moved = graph.create_child("gegl:translate")
        moved.set_property("x", float(translate[0]))
        moved.set_property("y", float(translate[1]))
        node.connect_to("output", moved, "input")
        node = moved
    if height_map:
        grey = graph.create_child("gegl:gray")
        node.connect_to("output", grey, "input")
        node = grey
    return node


def op_node(graph, source, op, props):
    node = graph.create_child(op)
    for key, value in props.items():
        node.set_property(key, value)
    source.connect_to("output", node, "input")
    return node


def floats(node, fmt):
    w, h, data = tsops.render_bytes(node, fmt)
    return w, h, struct.unpack("%df" % (len(data) // 4), data)


def max_delta_e(a, b):
    return max(math.sqrt(sum((a[i + c] - b[i + c]) ** 2 for c in range(3)))
               for i in range(0, len(a), 4))


cases = [
    ("brick.png", "texsynth:synthesize", {"width": 128, "height": 96, "seed": 3}, (0, 0)),
    ("bark.png", "texsynth:synthesize",
     {"width": 100, "height": 70, "seed": 5, "tileable": True}, (13, -7)),
    ("wood1.png", "texsynth:tileable", {"seed": 2}, (0, 0)),
    ("rock.png", "texsynth:tileable", {"seed": 4}, (-5, 9)),
]
for name, op, props, translate in cases:
    label = "%s on %s%s" % (op, name, " moved by %s" % (translate,) if translate != (0, 0) else "")
    note("-- " + label)
    path = tsops.exemplar(name)
    graph = Gegl.Node()
    source = exemplar_node(graph, path, translate)
    colour = op_node(graph, source, op, props)
    layout = op_node(graph, source, op, dict(props, **{"source-map": True}))

    # The coordinates: half-integers inside the exemplar's box.
    ex_box = source.get_bounding_box()
    w, h, coords = floats(layout, "float[2] ")  # babl_format_n (float, 2)
    inside = all(ex_box.x < x < ex_box.x + ex_box.width and ex_box.y < y < ex_box.y + ex_box.height
                 and x % 1 == 0.5 and y % 1 == 0.5 for x, y in zip(coords[0::2], coords[1::2]))
    check(inside, "%dx%d map: every coordinate a pixel centre inside the %dx%d%+d%+d exemplar"
          % (w, h, ex_box.width, ex_box.height, ex_box.x, ex_box.y))

    # Round trip: the map applied to the exemplar is the colour result.
    cw, ch, expected = tsops.render_bytes(colour, "R'G'B'A u16")
    rw, rh, got = tsops.render_bytes(tsops.apply_layout(graph, source, layout), "R'G'B'A u16")
    check((cw, ch) == (rw, rh) and expected == got,
          "map-absolute of the exemplar = the colour result, bit for bit in 16-bit R'G'B'A")
    _, _, lab_expected = floats(colour, LAB)
    _, _, lab_got = floats(tsops.apply_layout(graph, source, layout), LAB)
    delta = max_delta_e(lab_expected, lab_got)
    note("      max ΔE76 in float Lab: %.2g (the op reads the exemplar into Lab with its own "
         "fixed arithmetic, map-absolute through babl)" % delta)
    check(delta < 0.01, "max ΔE76 %.2g < 0.01" % delta)

    # Alignment: a height map (a pixel-wise function of the colours) laid
    # out by the map is that function of the colour result.
    height = exemplar_node(graph, path, translate, height_map=True)
    _, _, synthesised_height = floats(tsops.apply_layout(graph, height, layout), "Y float")
    grey = graph.create_child("gegl:gray")
    colour.connect_to("output", grey, "input")
    _, _, height_of_result = floats(grey, "Y float")
    error = tsops.max_abs_diff(synthesised_height, height_of_result)
    check(error <= 0.01, "height map laid out = height of the colour result: max error %.3g "
          "of the range 0..1 (<= 1 %%)" % error)

tsops.finish()
