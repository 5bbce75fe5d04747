# texsynth:synthesize in a GEGL XML graph file run by `gegl graph.xml`.
# SPDX-License-Identifier: LGPL-3.0-or-later

import os
from xml.sax.saxutils import escape, quoteattr

import tsops
from tsops import check, note

tsops.require_op()
tmp = tsops.workdir()
brick = tsops.exemplar("brick.png")        # 96x96


def node(op, **params):
    rows = "".join("      <param name=%s>%s</param>\n"
                   % (quoteattr(k.replace("_", "-")), escape(str(v)))
                   for k, v in params.items())
    return "  <node operation=%s>\n    <params>\n%s    </params>\n  </node>\n" % (quoteattr(op), rows)


def run_graph(name, *nodes):
    """Nodes from output to source, as GEGL's XML lists them."""
    xml = os.path.join(tmp, name + ".xml")
    png = os.path.join(tmp, name + ".png")
    with open(xml, "w") as f:
        f.write("<?xml version='1.0' encoding='UTF-8'?>\n<gegl>\n%s</gegl>\n" % "".join(nodes))
    code, _, err = tsops.run_gegl([xml, "-o", png])
    if code != 0 or not os.path.isfile(png):
        tsops.die("gegl %s failed (exit %d):\n%s" % (xml, code, err))
    return tsops.load(png), tsops.op_warnings(err)


load = node("gegl:load", path=brick)

note("-- a graph with the op")
(w, h, a), warnings = run_graph("plain", node(tsops.OP, width=200, height=150, seed=7), load)
check((w, h) == (200, 150) and not warnings, "XML graph gives 200x150 without warnings")

code, _, err = tsops.synthesize_cli(brick, os.path.join(tmp, "cli.png"), width=200, height=150, seed=7)
_, _, cli = tsops.load(os.path.join(tmp, "cli.png"))
check(a == cli, "same pixels as the same op on the gegl command line")

note("-- every property from XML")
(w, h, b), warnings = run_graph("props", node(
    tsops.OP, width=120, height=90, seed=7, tileable="true", quality=2, patch_size=9,
    fine_patch_size=5, iterations=3, histogram_matching="true"), load)
check((w, h) == (120, 90) and not warnings, "all properties accepted (%dx%d, %s)" % (w, h, warnings))
(_, _, b2), _ = run_graph("props2", node(tsops.OP, width=120, height=90, seed=7), load)
check(tsops.max_abs_diff(b, b2) > 0.1, "the properties change the result")

note("-- an exemplar that does not start at the origin, then more ops")
(w, h, c), warnings = run_graph(
    "offset",
    node("gegl:crop", x=0, y=0, width=50, height=40),
    node(tsops.OP, width=100, height=80, seed=7),
    node("gegl:crop", x=20, y=30, width=60, height=50),
    load)
check((w, h) == (50, 40) and not warnings and min(tsops.alphas(c)) > 0.99,
      "a 60x50 exemplar at (20, 30), result cropped to 50x40, opaque")

tsops.finish()
