# The ops give the same result whichever conversion paths babl picks.
# babl picks its paths by timing them (and caches the choice per user), so
# two processes can convert the same exemplar to CIE Lab slightly
# differently; texture synthesis turns such a 1e-4 difference into a
# completely different texture. Each child process below runs the ops on
# exemplars of known bytes with a different babl tolerance (BABL_TOLERANCE,
# which changes the paths babl may use) and a fresh babl cache; the
# results must be the same bytes.
# SPDX-License-Identifier: LGPL-3.0-or-later

import hashlib
import os
import struct
import subprocess
import sys

import tsops

# Exemplar formats whose pixels arrive exactly as given (integer codes,
# or floats) and the bytes of one pixel value v in 0..255 (grey: the mean).
FORMATS = {
    "R'G'B' u8": lambda r, g, b: struct.pack("3B", r, g, b),
    "R'G'B'A u16": lambda r, g, b: struct.pack("4H", r * 257, g * 257, b * 257, 65535),
    "Y' u8": lambda r, g, b: struct.pack("B", (r + g + b) // 3),
    "RGBA float": lambda r, g, b: struct.pack("4f", (r / 255.0) ** 2.2, (g / 255.0) ** 2.2,
                                              (b / 255.0) ** 2.2, 1.0),
}


def child(fmt, out):
    Gegl = tsops.gegl()
    w, h, rgb = exemplar_bytes()
    data = b"".join(FORMATS[fmt](*rgb[i:i + 3]) for i in range(0, len(rgb), 3))
    exemplar = Gegl.Buffer.new(fmt, 0, 0, w, h)
    exemplar.set(Gegl.Rectangle.new(0, 0, w, h), fmt, data)
    digest = hashlib.sha256()
    for op, props in (("texsynth:synthesize", dict(width=64, height=64, seed=11, quality=1)),
                      ("texsynth:tileable", dict(seed=5, quality=1))):
        graph, _, node = tsops.op_on_buffer(exemplar, op, **props)
        # The ops' own format (RGBA with the exemplar's curve and depth, in
        # its space): read without any conversion.
        own = "RGBA float" if fmt == "RGBA float" else "R'G'B'A " + fmt.split()[-1]
        digest.update(tsops.render_bytes(node, own)[2])
    with open(out, "w") as f:
        f.write(digest.hexdigest())


def exemplar_bytes():
    """bark.png's R'G'B' u8 codes, as stored (no conversion)."""
    path = os.path.join(os.environ.get("TEXSYNTH_SOURCE_ROOT", "."), "examples", "bark.png")
    load = tsops.gegl().Node().create_child("gegl:load")
    load.set_property("path", path)
    return tsops.render_bytes(load, "R'G'B' u8")


if len(sys.argv) == 4 and sys.argv[1] == "--child":
    child(sys.argv[2], sys.argv[3])
    sys.exit(0)

tsops.require_op()
work = tsops.workdir()
for fmt in FORMATS:
    digests = []
    for i, tolerance in enumerate(("", "0", "0.01")):
        env = dict(os.environ)
        env["XDG_CACHE_HOME"] = os.path.join(work, "cache-%d" % len(digests))
        env.pop("BABL_TOLERANCE", None)
        if tolerance:
            env["BABL_TOLERANCE"] = tolerance
        out = os.path.join(work, "digest-%d" % len(digests))
        proc = subprocess.run([sys.executable, os.path.abspath(__file__), "--child", fmt, out],
                              env=env, capture_output=True, text=True, timeout=300)
        if not tsops.check(proc.returncode == 0, "%s, BABL_TOLERANCE=%r: ran" % (fmt, tolerance)):
            tsops.note(proc.stderr)
            continue
        with open(out) as f:
            digests.append(f.read())
    tsops.check(len(set(digests)) == 1,
                "%s exemplar: the same results whichever babl paths (%d distinct)"
                % (fmt, len(set(digests))))
tsops.finish()
