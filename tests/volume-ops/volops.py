# Helpers for the tests of texsynth:volume-slice and texsynth:volume-save,
# on top of tests/ops/tsops.py.
# SPDX-License-Identifier: LGPL-3.0-or-later

import contextlib
import os
import struct
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "ops"))
import tsops  # noqa: E402,F401

SLICE, SAVE, LOAD = "texsynth:volume-slice", "texsynth:volume-save", "texsynth:volume-load"


def require_ops(*ops):
    """GEGL finds the ops (asked in this process: a gegl --exists run would
    start GEGL anew for each)."""
    for op in ops:
        if not tsops.gegl().has_operation(op):
            tsops.die("GEGL cannot find %s (GEGL_PATH=%s)" % (op, os.environ.get("GEGL_PATH")))


def prop_args(props):
    return ["%s=%s" % (k.replace("_", "-"), tsops._prop_text(v)) for k, v in props.items()]


def op_warnings(text, op):
    return [line.split(op + ": ", 1)[1] for line in text.splitlines() if op + ": " in line]


def atlas_extent(size):
    """common/volume/layout.h: columns = ceil(sqrt(size)), rows = ceil(size / columns)."""
    columns = 1
    while columns * columns < size:
        columns += 1
    rows = (size + columns - 1) // columns
    return columns * size, rows * size


# --- in-process graphs (GObject introspection) --------------------------------

def node(graph, op, **props):
    n = graph.create_child(op)
    for key, value in props.items():
        n.set_property(key.replace("_", "-"), value)
    return n


def loader(graph, path):
    return node(graph, "gegl:load", path=path)


def render_u8(n):
    """Render a node's bounding box as R'G'B'A u8: (width, height, bytes)."""
    Gegl = tsops.gegl()
    box = n.get_bounding_box()
    fmt = "R'G'B'A u8"
    buf = Gegl.Buffer.new(fmt, box.x, box.y, box.width, box.height)
    sink = n.get_parent().create_child("gegl:write-buffer")
    sink.set_property("buffer", buf)
    n.connect_to("output", sink, "input")
    sink.process()
    return box.width, box.height, bytes(buf.get(box, 1.0, fmt, Gegl.AbyssPolicy.NONE))


def load_u8(path):
    graph = tsops.gegl().Node()  # kept alive while rendering
    return render_u8(loader(graph, path))


def max_byte_diff(a, b):
    if len(a) != len(b):
        return 256
    return max((abs(x - y) for x, y in zip(a, b)), default=0)


@contextlib.contextmanager
def captured_stderr(store):
    """Collect what this process (GLib warnings, the cache's debug lines)
    writes to file descriptor 2 into store[0]."""
    sys.stderr.flush()
    saved = os.dup(2)
    with tempfile.TemporaryFile(mode="w+b") as f:
        os.dup2(f.fileno(), 2)
        try:
            yield
        finally:
            sys.stderr.flush()
            os.dup2(saved, 2)
            os.close(saved)
            f.seek(0)
            store[0] = f.read().decode("utf-8", "replace")
            sys.stderr.write(store[0])


def save_volume(path, source, settings, aux=None, aux3=None, **props):
    """Run texsynth:volume-save on `source`, with exemplars on the aux
    pads given; return its warnings."""
    graph = tsops.gegl().Node()
    sink = node(graph, SAVE, path=path, **dict(settings, **props))
    loader(graph, source).connect_to("output", sink, "input")
    for pad, pad_source in (("aux", aux), ("aux3", aux3)):
        if pad_source:
            loader(graph, pad_source).connect_to("output", sink, pad)
    text = [""]
    with captured_stderr(text):
        sink.process()
    return op_warnings(text[0], SAVE)


def cache_misses(text):
    return sum(1 for line in text.splitlines() if "texsynth: volume cache miss" in line)


# --- file headers -------------------------------------------------------------

def vol_header(path):
    with open(path, "rb") as f:
        head = f.read(4096)
    return {"magic": head[0:4], "version": struct.unpack_from("<i", head, 4)[0],
            "name": head[8:264].split(b"\0")[0], "wrap": head[264],
            "size": struct.unpack_from("<i", head, 268)[0],
            "channels": struct.unpack_from("<i", head, 272)[0],
            "bytes_per_channel": struct.unpack_from("<i", head, 276)[0],
            "length": os.path.getsize(path)}


def dds_header(path):
    with open(path, "rb") as f:
        head = f.read(148)
    u32 = lambda offset: struct.unpack_from("<I", head, offset)[0]  # noqa: E731
    return {"magic": head[0:4], "header_size": u32(4), "height": u32(12), "width": u32(16),
            "depth": u32(24), "fourcc": head[84:88], "dxgi_format": u32(128),
            "dimension": u32(132), "length": os.path.getsize(path)}


def png_size(path):
    with open(path, "rb") as f:
        head = f.read(24)
    if head[:8] != b"\x89PNG\r\n\x1a\n":
        return None
    return struct.unpack(">II", head[16:24])
