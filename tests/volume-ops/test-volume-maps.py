# Aligned maps and sources of solid textures: texsynth:volume-save
# and texsynth:volume-slice with a map on "aux3" lay the map out with the
# cached volume's sources. The exemplar itself as the map gives the colour
# volume byte for byte; an inverted map gives the inverted colour volume;
# colours, map and sources cost one synthesis; content=source writes an
# R16G16B16A16_UINT .dds whose x, y, orientation applied to the exemplar
# give the colour .dds, identical at 1 and 2 threads; a map of another
# size, or beside per-axis exemplars, gets a warning and no file.
# SPDX-License-Identifier: LGPL-3.0-or-later

import os
import struct
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import volops  # noqa: E402
from volops import SAVE, SLICE, node, tsops  # noqa: E402
from tsops import check, note  # noqa: E402

SIZE = 16
SETTINGS = {"size": SIZE, "seed": 7, "iterations": 2}
DDS_DATA = 148

volops.require_ops(SLICE, SAVE)
os.environ["TEXSYNTH_DEBUG_CACHE"] = "1"
Gegl = tsops.gegl()
tmp = tsops.workdir()
bark = tsops.exemplar("bark.png")
width, height, bark_px = volops.load_u8(bark)


def write_u8(path, w, h, px):
    buf = Gegl.Buffer.new("R'G'B'A u8", 0, 0, w, h)
    buf.set(Gegl.Rectangle.new(0, 0, w, h), "R'G'B'A u8", bytes(px))
    tsops.save_buffer(buf, path)


def inverted(px):
    out = bytearray(px)
    for i in range(len(out)):
        if i % 4 != 3:
            out[i] = 255 - out[i]
    return bytes(out)


inverted_map = os.path.join(tmp, "inverted.png")
write_u8(inverted_map, width, height, inverted(bark_px))
small_map = os.path.join(tmp, "small.png")
crop = b"".join(bark_px[y * width * 4:(y * width + 32) * 4] for y in range(32))
write_u8(small_map, 32, 32, crop)


def save(path, map_path=None, aux=None, **props):
    """Run texsynth:volume-save on bark; return its warnings."""
    return volops.save_volume(path, bark, SETTINGS, aux=aux, aux3=map_path, **props)


def slice_u8(map_path=None, **props):
    graph = Gegl.Node()
    n = node(graph, SLICE, **dict(SETTINGS, **props))
    volops.loader(graph, bark).connect_to("output", n, "input")
    if map_path:
        volops.loader(graph, map_path).connect_to("output", n, "aux3")
    text = [""]
    with volops.captured_stderr(text):
        result = volops.render_u8(n)
    return result, volops.op_warnings(text[0], SLICE)


def read(path):
    with open(path, "rb") as f:
        return f.read()


def rgb_diff(a, b):
    """Largest difference of the R, G, B bytes (alpha left out)."""
    if len(a) != len(b):
        return 256
    return max((abs(a[i] - b[i]) for i in range(len(a)) if i % 4 != 3), default=0)


log = [""]
with volops.captured_stderr(log):
    note("-- round trip: the exemplar as its own map")
    colour_dds, colour_atlas = os.path.join(tmp, "colour.dds"), os.path.join(tmp, "colour.png")
    same_dds, same_atlas = os.path.join(tmp, "same.dds"), os.path.join(tmp, "same.png")
    for path, map_path in ((colour_dds, None), (colour_atlas, None), (same_dds, bark),
                           (same_atlas, bark)):
        warnings = save(path, map_path)
        check(not warnings and os.path.isfile(path), "%s written (%s)" % (path, warnings))
    colour_voxels = read(colour_dds)[DDS_DATA:]
    check(read(same_dds)[DDS_DATA:] == colour_voxels,
          "the exemplar laid out as a map is the colour volume byte for byte")
    same = volops.load_u8(same_atlas)[2]
    check(same == volops.load_u8(colour_atlas)[2], "and its atlas is the colour atlas")
    (w, h, shown), warnings = slice_u8(bark, axis=1, index=5)
    (_, _, colours), _ = slice_u8(axis=1, index=5)
    check(not warnings and (w, h) == (SIZE, SIZE) and shown == colours,
          "texsynth:volume-slice with the exemplar as map shows the colour slice")

    note("-- alignment: an inverted map gives the inverted volume")
    inv_dds = os.path.join(tmp, "inverted.dds")
    check(not save(inv_dds, inverted_map), "inverted map's volume written")
    error = rgb_diff(read(inv_dds)[DDS_DATA:], inverted(colour_voxels))
    note("inverted map against the inverted colour volume: max error %d of 255" % error)
    check(error <= 2, "inverted map within 1 %% of the inverted colours (max %d)" % error)
    check(error == 0, "and in fact exact")
    (_, _, shown), _ = slice_u8(inverted_map, layout=1, axis=0)
    (_, _, colours), _ = slice_u8(layout=1, axis=0)
    check(rgb_diff(shown, inverted(colours)) == 0, "texsynth:volume-slice's inverted atlas")

    note("-- the sources as a .dds")
    src = os.path.join(tmp, "sources.dds")
    check(not save(src, content=1), "sources written")
    head = volops.dds_header(src)
    check(head["dxgi_format"] == 12 and head["depth"] == SIZE
          and head["length"] == DDS_DATA + SIZE ** 3 * 8,
          "R16G16B16A16_UINT volume of %d^3 (format %d, %d bytes)"
          % (SIZE, head["dxgi_format"], head["length"]))
    values = struct.unpack("<%dH" % (SIZE ** 3 * 4), read(src)[DDS_DATA:])
    applied = bytearray()
    inside = True
    for v in range(SIZE ** 3):
        x, y, o, a = values[4 * v:4 * v + 4]
        inside = inside and x < width and y < height and o < 3 and a == 65535
        i = (y * width + x) * 4
        applied += bark_px[i:i + 4]
    check(inside, "every source lies inside the exemplar, orientation 0-2")
    check(bytes(applied) == colour_voxels,
          "the sources applied to the exemplar's bytes give the colour .dds")
    orientations = {values[4 * v + 2] for v in range(SIZE ** 3)}
    check(orientations == {0, 1, 2}, "all three orientations supply voxels %s" % orientations)

check(volops.cache_misses(log[0]) == 1,
      "colours, maps and sources of one volume: one synthesis (%d)"
      % volops.cache_misses(log[0]))

note("-- sources at 1 and 2 threads (separate processes, 32^3)")
paths = []
for threads in (1, 2):
    path = os.path.join(tmp, "threads-%d.dds" % threads)
    code, _, err = tsops.run_gegl(["-i", bark, "--", SAVE, "path=" + path, "content=source",
                                   "size=32", "seed=4", "iterations=2"],
                                  env={"OMP_NUM_THREADS": str(threads)})
    check(code == 0 and os.path.isfile(path), "%d thread(s): written (%s)" % (threads, err))
    paths.append(path)
check(all(os.path.isfile(p) for p in paths) and read(paths[0]) == read(paths[1]),
      "1 and 2 threads write the same source volume")

note("-- bad input")
keep = os.path.join(tmp, "keep.dds")
with open(keep, "wb") as f:
    f.write(b"older file")
warnings = save(keep, small_map)
check(len(warnings) == 1 and warnings[0].startswith("the map is 32x32 but the exemplar"),
      "a map of another size: %s" % warnings)
check(read(keep) == b"older file", "and the older file is left as it was")
warnings = save(keep, bark, aux=bark)
check(len(warnings) == 1 and "'aux'" in warnings[0], "a map beside 'aux': %s" % warnings)
warnings = save(keep, bark, content=1)
check(len(warnings) == 1 and "content=source" in warnings[0],
      "a map with content=source: %s" % warnings)
warnings = save(os.path.join(tmp, "sources.png"), content=1)
check(len(warnings) == 1 and ".dds" in warnings[0], "sources as a PNG: %s" % warnings)
check(read(keep) == b"older file" and not os.path.exists(os.path.join(tmp, "sources.png")),
      "no file written by a refused request")
(w, h, shown), warnings = slice_u8(small_map)
check(len(warnings) == 1 and warnings[0].startswith("the map is 32x32")
      and set(shown[3::4]) == {0}, "texsynth:volume-slice: %s, transparent" % warnings)

tsops.finish()
