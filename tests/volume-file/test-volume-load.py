# texsynth:volume-load on the gegl tool's graphs, in this process
# (tsops.run_gegl_here: one GEGL start-up for all; once through the gegl
# tool itself), and once on one GObject introspection node: slice and
# atlas sizes and pixels for every axis, grey and RGB volumes, DX10 and
# legacy DDS, and the messages for a bad index and for missing, truncated
# and foreign files.
# SPDX-License-Identifier: LGPL-3.0-or-later
#
# Run with the system Python (/usr/bin/python3): images are read back
# through PyGObject's Gegl.

import os
import struct
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "ops"))
import tsops  # noqa: E402
from tsops import check  # noqa: E402

OP = "texsynth:volume-load"


def value(x, y, z, c):
    """Voxel channel c at (x, y, z): distinct for every voxel of the small
    test volumes, so a pixel from a wrong place shows."""
    return (x + 6 * y + 36 * z + 53 * c) % 256


def volume_bytes(size, channels):
    return bytes(value(x, y, z, c)
                 for z in range(size) for y in range(size) for x in range(size)
                 for c in range(channels))


def write_vol(path, size, channels, wrap=True):
    header = bytearray(4096)
    header[0:4] = b"VOLU"
    struct.pack_into("<i", header, 4, 4)
    header[8:8 + 4] = b"test"
    header[264] = 1 if wrap else 0
    struct.pack_into("<iii", header, 268, size, channels, 1)
    with open(path, "wb") as f:
        f.write(bytes(header) + volume_bytes(size, channels))


def dds_header(size, legacy):
    h = bytearray(128)
    h[0:4] = b"DDS "
    struct.pack_into("<7I", h, 4, 124, 0x80100F, size, size, size * 4, size, 1)
    if legacy:  # 32-bit BGRA by masks
        struct.pack_into("<8I", h, 76, 32, 0x41, 0, 32, 0xFF0000, 0xFF00, 0xFF, 0xFF000000)
    else:
        struct.pack_into("<2I", h, 76, 32, 0x4)
        h[84:88] = b"DX10"
    struct.pack_into("<2I", h, 108, 0x1008, 0x200000)
    if not legacy:
        h += struct.pack("<5I", 28, 4, 0, 1, 0)
    return bytes(h)


def write_dds(path, size, legacy=False):
    data = bytearray(volume_bytes(size, 4))
    if legacy:
        for i in range(0, len(data), 4):
            data[i], data[i + 2] = data[i + 2], data[i]
    with open(path, "wb") as f:
        f.write(dds_header(size, legacy) + bytes(data))


def expected_pixel(size, channels, axis, index, u, v):
    """RGBA u8 of slice `index` across `axis` at (u, v):
    X shows (y, z), Y shows (x, z), Z shows (x, y)."""
    x, y, z = {"x": (index, u, v), "y": (u, index, v), "z": (u, v, index)}[axis]
    c = [value(x, y, z, k) for k in range(channels)]
    if channels == 1:
        return (c[0], c[0], c[0], 255)
    if channels == 2:
        return (c[0], c[0], c[0], c[1])
    if channels == 3:
        return (c[0], c[1], c[2], 255)
    return tuple(c)


def load_cli(out, tool=False, **props):
    """gegl -o out -- texsynth:volume-load k=v ..., in this process or with
    `tool` through the gegl tool: (warnings, image or None)."""
    if os.path.exists(out):
        os.unlink(out)
    args = ["-o", out, "--", OP] + ["%s=%s" % (k, v) for k, v in props.items()]
    code, _, err = tsops.run_gegl(args, timeout=120) if tool else tsops.run_gegl_here(args)
    check(code == 0, "gegl%s exits 0 for %s" % (" (the tool)" if tool else "", " ".join(args[3:])))
    warnings = [line for line in err.splitlines() if OP + ": " in line]
    if not os.path.exists(out):
        return warnings, None
    w, h, px = tsops.load(out, "R'G'B'A float")
    return warnings, (w, h, [int(round(p * 255)) for p in px])


def pixels_match(image, expect_fn):
    w, h, px = image
    for v in range(h):
        for u in range(w):
            got = tuple(px[(v * w + u) * 4:(v * w + u) * 4 + 4])
            if got != expect_fn(u, v):
                return "(%d, %d) is %s, expected %s" % (u, v, got, expect_fn(u, v))
    return None


def check_slice(path, size, channels, axis, index, out, what, tool=False):
    warnings, image = load_cli(out, tool=tool, path=path, axis=axis, index=index)
    check(not warnings, "%s: no warning (%s)" % (what, warnings))
    if not check(image is not None and image[:2] == (size, size),
                 "%s: slice is %dx%d" % (what, size, size)):
        return
    wrong = pixels_match(image, lambda u, v: expected_pixel(size, channels, axis, index, u, v))
    check(wrong is None, "%s: every pixel is its voxel%s" % (what, "" if not wrong else ": " + wrong))


def check_atlas(path, size, channels, axis, out, what):
    columns = next(c for c in range(1, size + 1) if c * c >= size)
    rows = -(-size // columns)
    warnings, image = load_cli(out, path=path, axis=axis, layout="atlas")
    check(not warnings, "%s: no warning (%s)" % (what, warnings))
    if not check(image is not None and image[:2] == (columns * size, rows * size),
                 "%s: atlas is %dx%d" % (what, columns * size, rows * size)):
        return

    def expect(px, py):
        i = (py // size) * columns + px // size
        if i >= size:
            return (0, 0, 0, 0)
        return expected_pixel(size, channels, axis, i, px % size, py % size)

    wrong = pixels_match(image, expect)
    check(wrong is None, "%s: every cell is its slice, unused cells transparent%s"
          % (what, "" if not wrong else ": " + wrong))


def check_failure(out, fragment, what, size=None, **props):
    warnings, image = load_cli(out, **props)
    check(len(warnings) >= 1 and fragment in warnings[0],
          "%s: warns '%s' (got %s)" % (what, fragment, warnings))
    if size is None:
        check(image is None or image[:2] == (0, 0), "%s: empty result" % what)
    else:
        check(image is not None and image[:2] == (size, size)
              and all(p == 0 for p in image[2][3::4]),
              "%s: transparent %dx%d result" % (what, size, size))


def check_reload(path, work):
    """Through GI: one node, two slices, then the file changes on disk."""
    Gegl = tsops.gegl()
    graph = Gegl.Node()
    node = graph.create_child(OP)
    node.set_property("path", path)
    results = []
    for index in (0, 2):
        node.set_property("index", index)
        w, h, px = tsops.render(node, "R'G'B'A float")
        results.append([int(round(p * 255)) for p in px[:4]])
    check(results[0] == list(expected_pixel(6, 4, "z", 0, 0, 0))
          and results[1] == list(expected_pixel(6, 4, "z", 2, 0, 0)),
          "GI: two slices from one node")
    write_vol(path, 4, 1)
    os.utime(path, ns=(0, 1234567890123456789))
    node.set_property("index", 1)
    w, h, px = tsops.render(node, "R'G'B'A float")
    check((w, h) == (4, 4) and [int(round(p * 255)) for p in px[:4]]
          == list(expected_pixel(4, 1, "z", 1, 0, 0)),
          "GI: a changed file is read again (%dx%d)" % (w, h))


def main():
    if not tsops.gegl().has_operation(OP):
        tsops.die("GEGL cannot find %s (GEGL_PATH=%s)" % (OP, os.environ.get("GEGL_PATH", "<unset>")))

    work = tsops.workdir()
    out = os.path.join(work, "out.png")
    rgba_vol = os.path.join(work, "rgba.vol")
    write_vol(rgba_vol, 6, 4)
    for axis in ("x", "y", "z"):
        for index in (0, 4):
            check_slice(rgba_vol, 6, 4, axis, index, out, "RGBA .vol axis %s slice %d" % (axis, index),
                        tool=(axis, index) == ("x", 4))
    grey_vol = os.path.join(work, "grey.vol")
    write_vol(grey_vol, 5, 1, wrap=False)
    check_slice(grey_vol, 5, 1, "y", 3, out, "grey .vol axis y slice 3")
    rgb_vol = os.path.join(work, "rgb.vol")
    write_vol(rgb_vol, 5, 3)
    check_slice(rgb_vol, 5, 3, "x", 1, out, "RGB .vol axis x slice 1")
    ga_vol = os.path.join(work, "ga.vol")
    write_vol(ga_vol, 4, 2)
    check_slice(ga_vol, 4, 2, "z", 2, out, "grey+alpha .vol axis z slice 2")

    dds = os.path.join(work, "volume.dds")
    write_dds(dds, 5)
    check_slice(dds, 5, 4, "z", 2, out, "DX10 .dds axis z slice 2")
    legacy = os.path.join(work, "legacy.dds")
    write_dds(legacy, 5, legacy=True)
    check_slice(legacy, 5, 4, "y", 4, out, "legacy BGRA .dds axis y slice 4")

    for axis in ("x", "y", "z"):
        check_atlas(dds, 5, 4, axis, out, "atlas of 5 across %s" % axis)
    check_atlas(grey_vol, 5, 1, "z", out, "grey atlas of 5")
    check_atlas(ga_vol, 4, 2, "x", out, "atlas of 4 (full grid)")

    check_failure(out, "slice 6 does not exist", "index 6 of 6", size=6,
                  path=rgba_vol, index=6)
    missing = os.path.join(work, "missing.vol")
    check_failure(out, "cannot read '%s': No such file or directory" % missing,
                  "missing file", path=missing)
    truncated = os.path.join(work, "truncated.vol")
    with open(rgba_vol, "rb") as f:
        data = f.read()
    with open(truncated, "wb") as f:
        f.write(data[:4500])
    check_failure(out, "is truncated", "truncated .vol", path=truncated)
    with open(truncated, "wb") as f:
        f.write(data[:100])
    check_failure(out, "is truncated", "truncated .vol header", path=truncated)
    foreign = os.path.join(work, "foreign.vol")
    with open(foreign, "wb") as f:
        f.write(b"\x89PNG\r\n\x1a\n" + bytes(range(256)) * 4)
    check_failure(out, "is not a volume file", "a PNG named .vol", path=foreign)
    bc1 = os.path.join(work, "bc1.dds")
    header = bytearray(dds_header(4, False))
    struct.pack_into("<I", header, 128, 71)
    with open(bc1, "wb") as f:
        f.write(bytes(header) + bytes(4 * 4 * 4 * 4))
    check_failure(out, "DXGI format 71", "BC1 .dds", path=bc1)
    check_failure(out, "Is a directory", "a folder", path=work)

    check_reload(rgba_vol, work)
    tsops.finish()


if __name__ == "__main__":
    main()
