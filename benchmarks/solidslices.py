# Slices of .vol volumes and their quality figures, for quality-solid.py.
# SPDX-License-Identifier: LGPL-3.0-or-later

import math
import os
import statistics
import struct
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "tests", "ops"))
import tsops  # noqa: E402


def read_vol(path):
    """(size, channels, voxel bytes) of a .vol file."""
    with open(path, "rb") as f:
        data = f.read()
    if data[:4] != b"VOLU":
        tsops.die("%s is not a .vol file" % path)
    size, channels = struct.unpack_from("<ii", data, 268)
    return size, channels, data[4096:]


def save_rgb(path, width, height, pixels):
    """pixels: bytes, 3 per pixel (R'G'B' u8)."""
    Gegl = tsops.gegl()
    buf = Gegl.Buffer.new("R'G'B' u8", 0, 0, width, height)
    buf.set(Gegl.Rectangle.new(0, 0, width, height), "R'G'B' u8", pixels)
    tsops.save_buffer(buf, path)


def axis_slice(vol, axis, index, shift=0):
    """The slice across `axis` at `index`, its pixels rolled by `shift` in
    both directions (so that an inner line lands on the wrap-around edge)."""
    size, channels, data = vol
    out = bytearray(size * size * 3)
    for v in range(size):
        for u in range(size):
            a, b = (u + shift) % size, (v + shift) % size
            x, y, z = ((index, a, b), (a, index, b), (a, b, index))[axis]
            p = ((z * size + y) * size + x) * channels
            out[(v * size + u) * 3:(v * size + u) * 3 + 3] = data[p:p + 3]
    return bytes(out)


def diagonal_slice(vol):
    """The plane x = z through the volume: u runs along (1, 0, 1) / sqrt(2)
    at unit spacing (bilinear in x and z), v along y."""
    size, channels, data = vol
    out = bytearray(size * size * 3)
    for v in range(size):
        for u in range(size):
            s = u / math.sqrt(2.0)
            f = int(math.floor(s))
            t = s - f
            acc = [0.0, 0.0, 0.0]
            for dx, dz, w in ((0, 0, (1 - t) * (1 - t)), (1, 0, t * (1 - t)),
                              (0, 1, (1 - t) * t), (1, 1, t * t)):
                x, z = (f + dx) % size, (f + dz) % size
                p = ((z * size + v) * size + x) * channels
                for c in range(3):
                    acc[c] += w * data[p + c]
            out[(v * size + u) * 3:(v * size + u) * 3 + 3] = bytes(min(255, int(a + 0.5)) for a in acc)
    return bytes(out)


# Slices per axis the seam figures are averaged over: one slice's figure
# swings by +-0.3 with where large features happen to fall.
SEAM_SLICES = 4


def measure_volume(measure, exemplar, vol_path, outdir, name):
    """Figures of the middle slices across x, y and z and the diagonal
    slice against `exemplar`: medians of coherence, completeness,
    sharpness and axis-edges, and the largest copy. `seam` is the mean seam figure across
    the wrap-around edges of SEAM_SLICES slices per axis; `inner_seam` the
    same figure across their middle lines (the slices rolled by half their
    size), which shows what the figure gives where no boundary is."""
    vol = read_vol(vol_path)
    size = vol[0]
    figures, seams, inner = {}, [], []
    for axis, label in enumerate("xyz"):
        path = os.path.join(outdir, "%s-%s.png" % (name, label))
        save_rgb(path, size, size, axis_slice(vol, axis, size // 2))
        figures[label] = tsops.run_measure(measure, exemplar, path, True)
        for k in range(SEAM_SLICES):
            index = (2 * k + 1) * size // (2 * SEAM_SLICES)
            for shift, table in ((0, seams), (size // 2, inner)):
                path = os.path.join(outdir, "%s-%s-seam.png" % (name, label))
                save_rgb(path, size, size, axis_slice(vol, axis, index, shift))
                table.append(tsops.run_measure(measure, exemplar, path, True)["seam"])
    path = os.path.join(outdir, name + "-diagonal.png")
    save_rgb(path, size, size, diagonal_slice(vol))
    figures["diagonal"] = tsops.run_measure(measure, exemplar, path, False)
    slices = [figures[k] for k in ("x", "y", "z", "diagonal")]
    return {
        "coherence": statistics.median(s["coherence"] for s in slices),
        "completeness": statistics.median(s["completeness"] for s in slices),
        "copy": max(s["copy"] for s in slices),
        "sharpness": statistics.median(s["sharpness"] for s in slices),
        "axis_edges": statistics.median(s["axis_edges"] for s in slices),
        "seam": statistics.mean(seams),
        "inner_seam": statistics.mean(inner),
    }
