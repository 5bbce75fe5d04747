# texsynth:volume-save and texsynth:volume-slice in one process (GObject
# introspection): every file format (headers, lengths, PNG counts and
# sizes), files read back with texsynth:volume-load equal to the slices of
# texsynth:volume-slice, slice and atlas sizes on every axis, one
# synthesis for all of it (the shared cache's debug lines), the exemplar
# pads and free orientation, and the messages for bad paths and exemplars
# with older files left intact.
# SPDX-License-Identifier: LGPL-3.0-or-later

import glob
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import volops  # noqa: E402
from volops import LOAD, SAVE, SLICE, node, tsops  # noqa: E402
from tsops import check, note  # noqa: E402

SIZE = 16
SETTINGS = {"size": SIZE, "seed": 7, "iterations": 2}

volops.require_ops(SLICE, SAVE, LOAD)
os.environ["TEXSYNTH_DEBUG_CACHE"] = "1"
Gegl = tsops.gegl()
tmp = tsops.workdir()
bark, brick = tsops.exemplar("bark.png"), tsops.exemplar("brick.png")


def save(path, source=bark, aux=None, **props):
    """Run texsynth:volume-save; return its warnings."""
    return volops.save_volume(path, source, SETTINGS, aux=aux, **props)


def slice_u8(**props):
    graph = Gegl.Node()
    n = node(graph, SLICE, **dict(SETTINGS, **props))
    volops.loader(graph, bark).connect_to("output", n, "input")
    return volops.render_u8(n)


def load_u8(path, **props):
    graph = Gegl.Node()
    return volops.render_u8(node(graph, LOAD, path=path, **props))


log = [""]
with volops.captured_stderr(log):
    note("-- every format from one volume")
    vol, dds = os.path.join(tmp, "wood.vol"), os.path.join(tmp, "wood.dds")
    atlas = os.path.join(tmp, "atlas.png")
    folder = os.path.join(tmp, "slices") + "/"
    os.mkdir(folder)
    for path, props in ((vol, {}), (dds, {}), (atlas, {"axis": "y"}), (folder, {}),
                        (os.path.join(tmp, "wood.png"), {"format": "png-slices",
                                                         "axis": "x"})):
        warnings = save(path, **props)
        check(not warnings, "save %s %s: %s" % (os.path.basename(path.rstrip("/")) + "/"
                                               * path.endswith("/"), props,
                                               warnings or "no warning"))

    h = volops.vol_header(vol)
    check((h["magic"], h["version"], h["name"], h["wrap"], h["size"], h["channels"],
           h["bytes_per_channel"]) == (b"VOLU", 4, b"wood", 1, SIZE, 3, 1)
          and h["length"] == 4096 + SIZE ** 3 * 3,
          ".vol header (opaque: 3 channels) and length: %s" % h)
    h = volops.dds_header(dds)
    check((h["magic"], h["header_size"], h["width"], h["height"], h["depth"], h["fourcc"],
           h["dxgi_format"], h["dimension"]) == (b"DDS ", 124, SIZE, SIZE, SIZE, b"DX10", 28, 4)
          and h["length"] == 148 + SIZE ** 3 * 4, ".dds header (RGBA8, 3D) and length: %s" % h)
    check(volops.png_size(atlas) == volops.atlas_extent(SIZE),
          "atlas.png is %s" % (volops.png_size(atlas),))
    names = sorted(os.listdir(folder))
    check(names == ["slice-%03d.png" % i for i in range(SIZE)]
          and all(volops.png_size(folder + n) == (SIZE, SIZE) for n in names),
          "%d PNG slices slice-000.png ... of %dx%d" % (len(names), SIZE, SIZE))
    prefixed = sorted(glob.glob(os.path.join(tmp, "wood-*.png")))
    check(len(prefixed) == SIZE and prefixed[0].endswith("wood-000.png"),
          "format=png-slices path=wood.png: wood-000.png ... (%d files)" % len(prefixed))
    check(not glob.glob(os.path.join(tmp, "*.tmp-*")) and not glob.glob(folder + "*.tmp-*"),
          "no temporary files left")

    note("-- slices and atlases on every axis, equal to the saved files")
    for axis in ("x", "y", "z"):
        w, h, px = slice_u8(axis=axis, index=5)
        ok = (w, h) == (SIZE, SIZE)
        for path in (vol, dds):
            lw, lh, lpx = load_u8(path, axis=axis, index=5)
            ok = ok and (lw, lh) == (w, h) and volops.max_byte_diff(px, lpx) <= 1
        aw, ah, apx = slice_u8(axis=axis, layout="atlas")
        lw, lh, lpx = load_u8(vol, axis=axis, layout="atlas")
        ok = ok and (aw, ah) == volops.atlas_extent(SIZE) == (lw, lh)
        ok = ok and volops.max_byte_diff(apx, lpx) <= 1
        check(ok, "axis %s: slice 5 %dx%d and atlas %dx%d equal .vol/.dds read back"
              % (axis, w, h, aw, ah))
    w, h, px = slice_u8(axis="z", index=SIZE // 2)
    check(slice_u8(axis="z")[2] == px, "index -1 (default) is the middle slice")
    check(volops.max_byte_diff(px, volops.load_u8(folder + "slice-%03d.png" % (SIZE // 2))[2])
          <= 1, "slice-008.png equals slice 8 across z")
    check(volops.max_byte_diff(slice_u8(axis="x", index=3)[2],
                               volops.load_u8(os.path.join(tmp, "wood-003.png"))[2]) <= 1,
          "wood-003.png equals slice 3 across x")
    check(volops.max_byte_diff(slice_u8(axis="y", layout="atlas")[2],
                               volops.load_u8(atlas)[2]) <= 1,
          "atlas.png equals the atlas across y")

    note("-- an XML graph with volume-save as its last node")
    xml_vol = os.path.join(tmp, "xml.vol")
    graph = Gegl.Node.new_from_xml(
        "<gegl><node operation='%s'><params><param name='path'>%s</param>%s</params></node>"
        "<node operation='gegl:load'><params><param name='path'>%s</param></params></node>"
        "</gegl>" % (SAVE, xml_vol, "".join("<param name='%s'>%s</param>" % kv
                                            for kv in SETTINGS.items()), bark), "/")
    sink = [n for n in graph.get_children() if n.get_operation() == SAVE]
    if sink:
        sink[0].process()
    check(sink and os.path.isfile(xml_vol) and open(xml_vol, "rb").read() == open(vol, "rb").read()
          .replace(b"wood", b"xml\0", 1), "the XML graph writes the same volume")

check(volops.cache_misses(log[0]) == 1,
      "one synthesis for 6 saves and %d slices and atlases: %d cache misses"
      % (13, volops.cache_misses(log[0])))

note("-- the gegl tool")
cli_vol = os.path.join(tmp, "cli.dds")
code, _, err = tsops.run_gegl(["-i", bark, "--", SAVE, "path=" + cli_vol]
                              + volops.prop_args(SETTINGS))
check(code == 0 and not volops.op_warnings(err, SAVE) and os.path.isfile(cli_vol)
      and open(cli_vol, "rb").read() == open(dds, "rb").read(),
      "gegl -i bark.png -- %s path=cli.dds ...: the same file as in-process" % SAVE)

note("-- a translucent exemplar gives a 4-channel .vol")
holes = os.path.join(tmp, "translucent.png")
tsops.convert(bark, holes, "R'G'B'A u8", alpha_fn=lambda x, y, w, h: 0.5)
alpha_vol = os.path.join(tmp, "alpha.vol")
warnings = save(alpha_vol, source=holes, size=8)
h = volops.vol_header(alpha_vol) if os.path.isfile(alpha_vol) else {}
check(not warnings and h.get("channels") == 4 and h.get("length") == 4096 + 8 ** 3 * 4,
      "channels %s, length %s" % (h.get("channels"), h.get("length")))

note("-- exemplar pads and a free orientation")
with volops.captured_stderr(log):
    two = os.path.join(tmp, "two.vol")
    warnings = save(two, aux=brick, free_axis="z")
    check(not warnings and volops.vol_header(two)["size"] == SIZE,
          "aux = brick for x, input for y, z free: %s" % (warnings or "no warning"))
    check(open(two, "rb").read()[4096:] != open(vol, "rb").read()[4096:],
          "another exemplar set gives another volume")
    save(two, aux=brick, free_axis="z")
check(volops.cache_misses(log[0]) == 1, "saved twice, synthesised once")

note("-- bad paths and exemplars: a message, no file, older files intact")
before = open(vol, "rb").read()
transparent = os.path.join(tmp, "transparent.png")
tsops.convert(bark, transparent, "R'G'B'A u8", alpha_fn=lambda x, y, w, h: 0.0)
cases = [
    ("transparent exemplar over an existing .vol", vol, {"source": transparent},
     "fully transparent"),
    ("missing folder", os.path.join(tmp, "missing", "x.vol"), {}, "does not exist"),
    ("unwritable /proc/x.vol", "/proc/x.vol", {}, "/proc/x.vol"),
    ("no extension", os.path.join(tmp, "noext"), {}, "cannot tell the format"),
    ("a folder as .vol", folder, {"format": "vol"}, "is a folder"),
    ("empty path", "", {}, "no file name"),
    ("memory limit", os.path.join(tmp, "big.vol"), {"memory_limit": 1, "seed": 8},
     "limit of 1.0 MiB"),
]
for label, path, props, word in cases:
    warnings = save(path, **props)
    check(warnings and word in warnings[0] and
          (path in (vol, folder) or not os.path.exists(path)),
          "%s: %s" % (label, warnings[0] if warnings else "no warning"))
check(open(vol, "rb").read() == before, "the older wood.vol is intact")
check(not glob.glob(os.path.join(tmp, "*.tmp-*")), "no temporary files left")

tsops.finish()
