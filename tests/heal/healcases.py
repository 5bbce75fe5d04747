# The heal cases: masks (a centred square, a smooth blob, the photos'
# object outlines) written as 8-bit grey PNGs with the standard library.
# SPDX-License-Identifier: LGPL-3.0-or-later
import math
import os
import struct
import zlib


def write_grey_png(path, width, height, values):
    """values: a function (x, y) -> 0..255."""
    raw = bytearray()
    for y in range(height):
        raw.append(0)
        raw.extend(values(x, y) for x in range(width))

    def chunk(kind, data):
        body = kind + data
        return struct.pack(">I", len(data)) + body + struct.pack(">I", zlib.crc32(body) & 0xffffffff)

    with open(path, "wb") as f:
        f.write(b"\x89PNG\r\n\x1a\n")
        f.write(chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 0, 0, 0, 0)))
        f.write(chunk(b"IDAT", zlib.compress(bytes(raw), 9)))
        f.write(chunk(b"IEND", b""))


def square(width, height, side, cx=None, cy=None):
    """(x, y) -> 255 inside a side x side square centred at (cx, cy)."""
    cx = width // 2 if cx is None else cx
    cy = height // 2 if cy is None else cy
    x0, y0 = cx - side // 2, cy - side // 2
    return lambda x, y: 255 if x0 <= x < x0 + side and y0 <= y < y0 + side else 0


def blob(width, height, area=1600, cx=None, cy=None):
    """(x, y) -> 255 inside a smooth closed curve of about `area` pixels:
    a circle whose radius wobbles with two harmonics."""
    cx = width / 2.0 if cx is None else cx
    cy = height / 2.0 if cy is None else cy
    # Mean of r^2 over the angle: r0^2 (1 + (0.25^2 + 0.15^2) / 2).
    r0 = math.sqrt(area / math.pi / (1 + (0.25 ** 2 + 0.15 ** 2) / 2))

    def inside(x, y):
        dx, dy = x + 0.5 - cx, y + 0.5 - cy
        t = math.atan2(dy, dx)
        r = r0 * (1 + 0.25 * math.sin(2 * t + 0.7) + 0.15 * math.cos(3 * t))
        return 255 if dx * dx + dy * dy <= r * r else 0
    return inside


def count(width, height, values):
    return sum(1 for y in range(height) for x in range(width) if values(x, y))


# The bundled texture cases: central 128x128 crops of the exemplars at
# least that large (not tiled: a repeat would let a heal copy the hole's
# own pixels back), each with a centred 40x40 square and a ~1600 px blob.
TEXTURES = ["3dweave", "bluemetal", "canyons2", "cracked", "land1", "stone33"]
HOLES = {"square": lambda: square(128, 128, 40), "blob": lambda: blob(128, 128)}
SIDE = 128


def png_size(p):
    with open(p, "rb") as f:
        return struct.unpack(">II", f.read(24)[16:24])


def make_texture(gegl_tool, exemplar_path, out_path, side=SIDE, tile=False, run_gegl=None):
    """The central side x side crop of the exemplar, or with `tile` of the
    exemplar repeated (GIMP patterns tile), through the gegl tool, or
    through `run_gegl` (the tool's arguments -> exit status, stdout,
    stderr; a test's in-process twin of the tool) if given."""
    import subprocess
    w, h = png_size(exemplar_path)
    x, y = (0, 0) if tile else ((w - side) // 2, (h - side) // 2)
    if not tile and (x < 0 or y < 0):
        raise RuntimeError("%s is %dx%d, smaller than %d" % (exemplar_path, w, h, side))
    args = (["-i", exemplar_path, "-o", out_path, "--"] + (["gegl:tile"] if tile else [])
            + ["gegl:crop", "x=%d" % x, "y=%d" % y, "width=%d" % side, "height=%d" % side])
    if run_gegl is None:
        proc = subprocess.run([gegl_tool] + args, capture_output=True, text=True,
                              stdin=subprocess.DEVNULL)
        code, err = proc.returncode, proc.stderr
    else:
        code, _, err = run_gegl(args)
    if code != 0 or not os.path.isfile(out_path):
        raise RuntimeError("gegl could not crop %s:\n%s" % (exemplar_path, err))


def median(values):
    v = sorted(values)
    n = len(v)
    return v[n // 2] if n % 2 else 0.5 * (v[n // 2 - 1] + v[n // 2])


def ellipse(cx, cy, rx, ry):
    return lambda x, y: 255 if ((x + 0.5 - cx) / rx) ** 2 + ((y + 0.5 - cy) / ry) ** 2 <= 1 else 0


def rectangle(x0, y0, x1, y1):
    return lambda x, y: 255 if x0 <= x < x1 and y0 <= y < y1 else 0


# Object removals in GIMP 2.10's splash (Debian gimp-data,
# /usr/share/gimp/2.0/images/gimp-splash.png, 1920x1080): a 512x512 crop
# (x, y) and the hole in the crop's coordinates.
SPLASH = "/usr/share/gimp/2.0/images/gimp-splash.png"
PHOTOS = {
    # the pebble on the moss, right: an ellipse around it
    "pebble": ((1376, 420), ellipse(257, 242, 72, 46)),
    # the "2.10" of the title over the blurred forest: its bounding box
    "title": ((1350, 0), rectangle(152, 102, 468, 338)),
    # the single mushroom in front of the cluster: an ellipse
    "mushroom": ((300, 330), ellipse(260, 250, 45, 80)),
}
# The speed case: a 1024x1024 crop with a 200x200 hole in its middle.
BIG = ((448, 28), rectangle(412, 412, 612, 612))
