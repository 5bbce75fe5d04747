# Results stay in the exemplar's colour space: from an sRGB PNG, a PNG
# with a gAMA chunk and a PNG with an ICC profile (Adobe RGB's primaries,
# gamma 1.8), all holding the same bytes, texsynth:synthesize, texsynth:tileable,
# texsynth:heal, texsynth:volume-slice and texsynth:volume-save give
# results in that space: saved as 8-bit PNG, every pixel copied from the
# exemplar (the source map, or the volume's sources, says which) has the
# exemplar's very bytes, and the file carries the space.
# SPDX-License-Identifier: LGPL-3.0-or-later

import ctypes
import ctypes.util
import math
import os
import struct
import zlib

import tsops
from tsops import check

tsops.require_op()
Gegl = tsops.gegl()
for op in ("texsynth:tileable", "texsynth:heal", "texsynth:volume-slice",
           "texsynth:volume-save", "texsynth:volume-load", "gegl:png-save",
           "gegl:map-absolute"):
    check(Gegl.has_operation(op), "%s exists" % op)
work = tsops.workdir()
LAB = "CIE Lab alpha float"


# --- PNG files written and read here, byte for byte ---------------------------

def chunk(kind, data):
    body = kind + data
    return struct.pack(">I", len(data)) + body + struct.pack(">I", zlib.crc32(body))


def write_png(path, width, height, rgba, extra_chunks):
    """An 8-bit RGBA PNG of `rgba` with `extra_chunks` before the pixels."""
    rows = b"".join(b"\0" + rgba[y * width * 4:(y + 1) * width * 4] for y in range(height))
    with open(path, "wb") as f:
        f.write(b"\x89PNG\r\n\x1a\n")
        f.write(chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 6, 0, 0, 0)))
        for kind, data in extra_chunks:
            f.write(chunk(kind, data))
        f.write(chunk(b"IDAT", zlib.compress(rows)))
        f.write(chunk(b"IEND", b""))


def paeth(a, b, c):
    p = a + b - c
    pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
    return a if pa <= pb and pa <= pc else (b if pb <= pc else c)


def read_png(path):
    """(width, height, RGBA bytes, chunk names) of an 8-bit RGB(A) PNG."""
    with open(path, "rb") as f:
        data = f.read()
    pos, kinds, idat = 8, [], b""
    while pos < len(data):
        (length,) = struct.unpack(">I", data[pos:pos + 4])
        kind, body = data[pos + 4:pos + 8], data[pos + 8:pos + 8 + length]
        kinds.append(kind.decode())
        if kind == b"IHDR":
            width, height, depth, colour = struct.unpack(">IIBB", body[:10])
        elif kind == b"IDAT":
            idat += body
        pos += 12 + length
    if "IHDR" not in kinds:
        tsops.die("%s is not a PNG file (GEGL could not save it?)" % path)
    if depth != 8 or colour not in (2, 6):
        tsops.die("%s: %d-bit colour type %d, not 8-bit RGB(A)" % (path, depth, colour))
    bpp = 4 if colour == 6 else 3
    raw, stride, out, prev = zlib.decompress(idat), width * bpp, bytearray(), bytearray(width * bpp)
    for y in range(height):
        kind, line = raw[y * (stride + 1)], bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for i in range(stride):
            a = line[i - bpp] if i >= bpp else 0
            b, c = prev[i], prev[i - bpp] if i >= bpp else 0
            line[i] = (line[i] + (0, a, b, (a + b) // 2, paeth(a, b, c))[kind]) & 255
        out += line if bpp == 4 else b"".join(bytes(line[i:i + 3]) + b"\xff"
                                               for i in range(0, stride, 3))
        prev = line
    return width, height, bytes(out), kinds


def icc_profile():
    """A matrix/TRC ICC profile (Adobe RGB's wide primaries, gamma 1.8)
    made by babl itself: the kind of profile an application embeds.
    (Display P3's red, adapted to D50, lies outside what libpng accepts
    as chromaticities, so GEGL could not save a PNG in that space.)"""
    name = ctypes.util.find_library("babl-0.1") or "libbabl-0.1.so.0"
    babl = ctypes.CDLL(name)
    babl.babl_init()
    babl.babl_trc_gamma.restype = ctypes.c_void_p
    babl.babl_trc_gamma.argtypes = [ctypes.c_double]
    babl.babl_space_from_chromaticities.restype = ctypes.c_void_p
    babl.babl_space_from_chromaticities.argtypes = ([ctypes.c_char_p] + [ctypes.c_double] * 8
                                                    + [ctypes.c_void_p] * 3 + [ctypes.c_int])
    babl.babl_space_get_icc.restype = ctypes.c_void_p
    babl.babl_space_get_icc.argtypes = [ctypes.c_void_p, ctypes.POINTER(ctypes.c_int)]
    trc = babl.babl_trc_gamma(1.8)
    space = babl.babl_space_from_chromaticities(b"texsynth-test-adobe-g18", 0.3127, 0.3290,
                                                0.640, 0.330, 0.210, 0.710, 0.150, 0.060,
                                                trc, trc, trc, 1)
    length = ctypes.c_int(0)
    data = babl.babl_space_get_icc(space, ctypes.byref(length))
    if not data or length.value < 132:
        tsops.die("babl made no ICC profile")
    return d50_white(ctypes.string_at(data, length.value))


def d50_white(profile):
    """`profile` with its media white point (wtpt) set to D50, as ICC v4
    asks and Display P3 profiles have: babl writes the space's own white
    there, and GEGL 0.4.42's png-save then fails on the chromaticities it
    reports for the space."""
    profile = bytearray(profile)
    (count,) = struct.unpack(">I", profile[128:132])
    for i in range(count):
        sig, offset, size = struct.unpack(">4sII", profile[132 + 12 * i:144 + 12 * i])
        if sig == b"wtpt":
            profile[offset + 8:offset + 20] = struct.pack(
                ">iii", *(round(v * 65536) for v in (0.9642, 1.0, 0.8249)))
            return bytes(profile)
    tsops.die("babl's ICC profile has no wtpt tag")


# --- GEGL graphs ---------------------------------------------------------------

def node_chain(graph, source, op=None, **props):
    load = graph.create_child("gegl:load")
    load.set_property("path", source)
    if op is None:
        return load
    node = graph.create_child(op)
    for key, value in props.items():
        node.set_property(key.replace("_", "-"), value)
    load.connect_to("output", node, "input")
    return node


def save_png(node, path):
    graph = node.get_parent()
    save = graph.create_child("gegl:png-save")
    save.set_property("path", path)
    save.set_property("bitdepth", 8)
    node.connect_to("output", save, "input")
    save.process()


def source_map(node):
    _, _, data = tsops.render_bytes(node, "float[2] ")  # babl_format_n (float, 2)
    coords = struct.unpack("%df" % (len(data) // 4), data)
    return [(int(x), int(y)) for x, y in zip(coords[0::2], coords[1::2])]


def pixel(data, width, x, y):
    return data[4 * (y * width + x):4 * (y * width + x) + 4]


def max_delta_e(a, b):
    return max(math.sqrt(sum((a[i + c] - b[i + c]) ** 2 for c in range(3)))
               for i in range(0, len(a), 4))


def tagged(kinds, case):
    """The saved file says what space it is in: sRGB, or a profile."""
    return ("sRGB" in kinds) if case == "srgb" else ("iCCP" in kinds)


# --- the exemplars ---------------------------------------------------------------

w, h, exemplar_bytes = tsops.load_bytes(tsops.exemplar("brick.png"), "R'G'B'A u8")
cases = {
    "srgb": [(b"sRGB", b"\0")],
    "gAMA": [(b"gAMA", struct.pack(">I", 55556))],   # 1 / 1.8
    "ICC": [(b"iCCP", b"wide gamma 1.8\0\0" + zlib.compress(icc_profile()))],
}
paths = {}
for case, chunks in cases.items():
    paths[case] = os.path.join(work, "brick-%s.png" % case)
    write_png(paths[case], w, h, exemplar_bytes, chunks)

# The premise: GEGL reads the three as different colours (else the test
# could not tell a space kept from one lost).
as_srgb = {case: tsops.load_bytes(path, "R'G'B'A u8")[2] for case, path in paths.items()}
check(as_srgb["srgb"] == exemplar_bytes, "the sRGB PNG reads as its bytes in sRGB")
for case in ("gAMA", "ICC"):
    differ = sum(a != b for a, b in zip(as_srgb[case], exemplar_bytes))
    check(differ > len(exemplar_bytes) // 4,
          "the %s PNG reads as other colours: %d of %d sRGB bytes differ"
          % (case, differ, len(exemplar_bytes)))


def check_copies(case, label, out_path, sources, out_size, origin=(0, 0)):
    """Every pixel of the saved result at `out_path` whose source is known
    has the bytes of the exemplar pixel it was copied from."""
    ow, oh, out, kinds = read_png(out_path)
    check((ow, oh) == out_size, "%s %s: %dx%d result" % (case, label, ow, oh))
    wrong = sum(pixel(out, ow, i % ow, i // ow) != pixel(exemplar_bytes, w, sx - origin[0],
                                                            sy - origin[1])
                for i, (sx, sy) in enumerate(sources))
    check(wrong == 0, "%s %s: all %d copied pixels have the exemplar's 8-bit values "
          "(%d differ)" % (case, label, len(sources), wrong))
    check(tagged(kinds, case), "%s %s: the file carries the exemplar's space (chunks %s)"
          % (case, label, ", ".join(k for k in kinds if k not in ("IDAT",))))
    return out


# --- synthesize and tileable, with the source map's round trip --------------------

plans = [("texsynth:synthesize", {"width": 80, "height": 64, "seed": 3}),
         ("texsynth:tileable", {"seed": 2})]
for case, path in paths.items():
    for op, props in plans:
        label = op.split(":")[1]
        graph = Gegl.Node()
        colour = node_chain(graph, path, op, **props)
        layout = node_chain(graph, path, op, source_map=True, **props)
        out_path = os.path.join(work, "%s-%s.png" % (label, case))
        save_png(colour, out_path)
        sources = source_map(layout)
        box = layout.get_bounding_box()
        check_copies(case, label, out_path, sources, (box.width, box.height))

        # The round trip holds: the map applied to the exemplar is the
        # result, in any format (here the engine's Lab).
        _, _, lab_colour = tsops.render(colour, LAB)
        exemplar = node_chain(graph, path)
        _, _, lab_laid = tsops.render(tsops.apply_layout(graph, exemplar, layout), LAB)
        delta = max_delta_e(lab_colour, lab_laid)
        check(delta < 0.01, "%s %s: map-absolute of the exemplar = the result, max ΔE76 %.2g "
              "< 0.01" % (case, label, delta))
        # And the saved file, read back through its own tags, shows those
        # colours: its bytes are not mislabelled. png-save writes the space
        # as a new profile, with the gamma in 8.8 fixed point (1.7969 for
        # the gAMA chunk's 1.8000): ΔE76 0.11 from that alone.
        _, _, lab_file = tsops.load(out_path, LAB)
        delta = max_delta_e(lab_file, lab_laid)
        check(delta < 0.25, "%s %s: the saved file read back = the exemplar's colours laid out, "
              "max ΔE76 %.2g < 0.25" % (case, label, delta))

# --- heal: kept pixels keep their bytes, the fill is in the same space -----------

hole = (36, 40, 24, 16)   # x, y, width, height


def in_hole(x, y):
    return hole[0] <= x < hole[0] + hole[2] and hole[1] <= y < hole[1] + hole[3]


holed = bytearray(exemplar_bytes)
for y in range(h):
    for x in range(w):
        if in_hole(x, y):
            holed[4 * (y * w + x) + 3] = 0
for case, chunks in cases.items():
    path = os.path.join(work, "holed-%s.png" % case)
    write_png(path, w, h, bytes(holed), chunks)
    graph = Gegl.Node()
    out_path = os.path.join(work, "heal-%s.png" % case)
    save_png(node_chain(graph, path, "texsynth:heal", seed=1), out_path)
    kept = [(x, y) if not in_hole(x, y) else None for y in range(h) for x in range(w)]
    ow, oh, out, kinds = read_png(out_path)
    wrong = sum(1 for i, s in enumerate(kept)
                if s and pixel(out, ow, i % w, i // w) != pixel(exemplar_bytes, w, *s))
    check((ow, oh) == (w, h) and wrong == 0,
          "%s heal: every pixel outside the hole keeps its 8-bit values (%d differ)"
          % (case, wrong))
    check(tagged(kinds, case), "%s heal: the file carries the exemplar's space" % case)
    fill = [pixel(out, ow, x, y) for y in range(h) for x in range(w) if in_hole(x, y)]
    check(all(p[3] == 255 for p in fill), "%s heal: the hole is filled, opaque" % case)

# --- solid textures: slices, PNG files and .vol files ---------------------------

SIZE = 24
for case, path in paths.items():
    props = {"size": SIZE, "seed": 1}
    graph = Gegl.Node()
    sources_path = os.path.join(work, "sources-%s.dds" % case)
    vol_path = os.path.join(work, "volume-%s.vol" % case)
    slices_dir = os.path.join(work, "slices-%s" % case) + "/"
    os.mkdir(slices_dir)
    for target, extra in ((sources_path, {"content": 1}), (vol_path, {}), (slices_dir, {})):
        node_chain(graph, path, "texsynth:volume-save", path=target, **props, **extra).process()
    with open(sources_path, "rb") as f:
        raw = f.read()[148:]
    src = struct.unpack("<%dH" % (len(raw) // 2), raw)
    voxel_sources = [(src[4 * i], src[4 * i + 1]) for i in range(SIZE ** 3)]
    with open(vol_path, "rb") as f:
        vol = f.read()
    channels = struct.unpack("<i", vol[272:276])[0]
    voxels = vol[4096:]
    wrong = sum(voxels[i * channels:i * channels + 3] != pixel(exemplar_bytes, w, *s)[:3]
                for i, s in enumerate(voxel_sources))
    check(wrong == 0, "%s .vol: all %d voxels have their source pixel's 8-bit values "
          "(%d differ)" % (case, SIZE ** 3, wrong))

    index = SIZE // 2
    plane = SIZE * SIZE
    slice_sources = voxel_sources[index * plane:(index + 1) * plane]   # across z
    check_copies(case, "volume-save slice", os.path.join(slices_dir, "slice-%03d.png" % index),
                 slice_sources, (SIZE, SIZE))
    shown_path = os.path.join(work, "volume-slice-%s.png" % case)
    save_png(node_chain(graph, path, "texsynth:volume-slice", index=index, **props), shown_path)
    check_copies(case, "volume-slice", shown_path, slice_sources, (SIZE, SIZE))

    # volume-load gives a file's bytes as they are (read as sRGB: a .vol
    # or .dds file names no space).
    loaded = graph.create_child("texsynth:volume-load")
    loaded.set_property("path", vol_path)
    loaded.set_property("index", index)
    _, _, loaded_bytes = tsops.render_bytes(loaded, "R'G'B'A u8")
    expected = b"".join(voxels[(index * plane + i) * channels:(index * plane + i) * channels + 3]
                        + b"\xff" for i in range(plane))
    check(loaded_bytes == expected, "%s volume-load: the .vol slice's bytes as they are" % case)

tsops.finish()
