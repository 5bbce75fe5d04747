# source-map in GIMP and in gegl: GIMP's generated dialogs of
# texsynth:synthesize and texsynth:tileable must not offer source-map
# (GIMP would show the coordinates as a strange two-channel picture), so
# the property carries the GUM key visible = 0, which GIMP's property GUI
# evaluates; the gegl tool, with docs/synthesis.md's XML graph and with a command
# line, must still use it: the layout applied to the exemplar gives the
# colour result.
# SPDX-License-Identifier: LGPL-3.0-or-later

import os

import tsops
from tsops import check

tsops.require_op()
Gegl = tsops.gegl()
brick = tsops.exemplar("brick.png")
work = tsops.workdir()
SIZE, SEED = 64, 7

for op in ("texsynth:synthesize", "texsynth:tileable"):
    check(Gegl.Operation.find_property(op, "source-map") is not None,
          "%s has source-map" % op)
    visible = Gegl.Operation.get_property_key(op, "source-map", "visible")
    check(visible == "0", "%s: source-map is hidden from GIMP's dialog (visible = %r)"
          % (op, visible))
    shown = Gegl.Operation.get_property_key(op, "seed", "visible")
    check(shown is None, "%s: seed is still shown (visible = %r)" % (op, shown))

colour = os.path.join(work, "colour.png")
code, _, err = tsops.synthesize_cli(brick, colour, width=SIZE, height=SIZE, seed=SEED)
check(code == 0 and os.path.isfile(colour), "gegl: the colour result (%s)" % err.strip())

# docs/synthesis.md's graph, with brick as both the driving and the laid-out map.
xml = os.path.join(work, "layout.xml")
with open(xml, "w") as f:
    f.write("""<?xml version='1.0' encoding='UTF-8'?>
<gegl>
  <node operation='gegl:crop'>
    <params><param name='width'>%d</param><param name='height'>%d</param></params>
  </node>
  <node operation='gegl:map-absolute'>
    <params><param name='sampler-type'>nearest</param></params>
    <node operation='texsynth:synthesize'>
      <params>
        <param name='width'>%d</param><param name='height'>%d</param>
        <param name='seed'>%d</param><param name='source-map'>true</param>
      </params>
    </node>
    <node operation='gegl:load'><params><param name='path'>%s</param></params></node>
  </node>
  <node operation='gegl:load'><params><param name='path'>%s</param></params></node>
</gegl>
""" % (SIZE, SIZE, SIZE, SIZE, SEED, brick, brick))
from_xml = os.path.join(work, "from-xml.png")
code, _, err = tsops.run_gegl([xml, "-o", from_xml])
check(code == 0 and os.path.isfile(from_xml), "gegl layout.xml -o: ran (%s)" % err.strip())

from_cli = os.path.join(work, "from-cli.png")
code, _, err = tsops.run_gegl(["-i", brick, "-o", from_cli, "--", "gegl:map-absolute",
                               "sampler-type=nearest", "aux=[", "gegl:load", "path=" + brick,
                               "texsynth:synthesize", "width=%d" % SIZE, "height=%d" % SIZE,
                               "seed=%d" % SEED, "source-map=true", "]",
                               "gegl:crop", "width=%d" % SIZE, "height=%d" % SIZE])
check(code == 0 and os.path.isfile(from_cli), "gegl -- map-absolute aux=[ ... source-map=true ]: "
      "ran (%s)" % err.strip())

if all(os.path.isfile(p) for p in (colour, from_xml, from_cli)):
    w, h, expected = tsops.load(colour)
    for name, path in (("XML graph", from_xml), ("command line", from_cli)):
        lw, lh, got = tsops.load(path)
        # 8-bit files: the op's Lab result and the copied exemplar pixel may
        # round to neighbouring levels (at most ΔE 0.0002 apart in float).
        diff = tsops.max_abs_diff(expected, got) if (lw, lh) == (w, h) else float("inf")
        check((lw, lh) == (SIZE, SIZE) and diff <= 1.0 / 255,
              "%s: the layout applied to the exemplar is the colour result (%dx%d, max "
              "difference %.4f)" % (name, lw, lh, diff))
        tsops.check(len(set(got[0::4])) > 20, "%s: a texture, not a flat colour" % name)
tsops.finish()
