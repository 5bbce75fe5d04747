# texsynth:tileable on the gegl tool's graphs and XML graphs: size, seam
# (texsynth-measure --tileable and the output tiled 2x2), determinism,
# layout kept (CIE76 dE over the central half), one-direction modes, alpha
# and other formats, and the messages for bad input. The runs whose process
# matters (one thread, an XML file, --info) use the gegl tool; the others
# run in this process on the graph the tool builds from the same arguments
# (tsops.run_gegl_here), sparing a GEGL start-up each. Small-size runs
# (TEXSYNTH_TEST_SMALL) run the op on every case but leave the measured
# seams to the native run.
# SPDX-License-Identifier: LGPL-3.0-or-later
#
# Run with the system Python (/usr/bin/python3): it has PyGObject and the
# Gegl typelib. Usage: test-tileable-op.py --measure PATH [--keep DIR]

import argparse
import atexit
import json
import math
import os
import shutil
import struct
import subprocess
import sys
import tempfile
from xml.sax.saxutils import escape, quoteattr

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "ops"))
import tsops  # noqa: E402
from tsops import check, die, exemplar, finish, load, note, save_buffer  # noqa: E402

OP = "texsynth:tileable"
PREFIX = OP + ": "
# The seam figure is about 1 where the edges are as alike as any two
# neighbouring windows inside, above it for a visible seam: the op's
# results measure 0.18-0.44 (brick crop, rock, granite1, leopard, seeds
# 1-4), with too narrow a band (seam-width=0.05) 1.37-1.85, the brick crop
# untouched 10 or more.
SEAM_MAX = 1.10
# The op changes only a band along the edges: its results' central half
# measures 0.000 against the input's, a fresh tileable synthesis of the
# brick crop (texsynth:synthesize, seed 3) 27.5.
DE_MAX = 5.0

parser = argparse.ArgumentParser()
parser.add_argument("--measure", required=True, help="path of texsynth-measure")
parser.add_argument("--keep", help="keep the images in this folder")
args = parser.parse_args()

Gegl = tsops.gegl()

tmp = args.keep or tempfile.mkdtemp(prefix="texsynth-tileable-")
os.makedirs(tmp, exist_ok=True)
if not args.keep:
    atexit.register(shutil.rmtree, tmp, True)
gegl_tool = os.environ.get("TEXSYNTH_GEGL") or shutil.which("gegl")
if not gegl_tool:
    die("the gegl command-line tool is not installed")


def path(name):
    return os.path.join(tmp, name)


def gegl(*argv):
    """Run gegl; (exit code, our warning lines, stderr). A crash fails."""
    proc = subprocess.run([gegl_tool] + list(argv), capture_output=True, text=True, errors="replace",
                          stdin=subprocess.DEVNULL, timeout=600)
    if proc.returncode < 0:
        die("gegl %s was killed by signal %d\n%s" % (" ".join(argv), -proc.returncode, proc.stderr))
    return proc.returncode, [l for l in proc.stderr.splitlines() if PREFIX in l], proc.stderr


def tileable(src, dst, *props):
    """gegl -i src -o dst -- texsynth:tileable props, in this process."""
    code, _, err = tsops.run_gegl_here(["-i", src, "-o", dst, "--", OP, *props])
    if code != 0 or not os.path.isfile(dst):
        die("gegl %s failed (exit %d):\n%s" % (OP, code, err))
    return [line for line in err.splitlines() if PREFIX in line]


def save(p, w, h, px, fmt="R'G'B'A float", bitdepth=8):
    buf = Gegl.Buffer.new(fmt, 0, 0, w, h)
    buf.set(Gegl.Rectangle.new(0, 0, w, h), fmt, struct.pack("%df" % len(px), *px))
    save_buffer(buf, p, bitdepth)


def measure(ex, results, tileable="--tileable"):
    """texsynth-measure of each of `results` against `ex`, in one run: a
    list of dicts."""
    proc = subprocess.run([args.measure, "--json", tileable, ex] + results,
                          capture_output=True, text=True)
    if proc.returncode != 0:
        die("texsynth-measure failed:\n" + proc.stderr)
    return [json.loads(line) for line in proc.stdout.splitlines()]


def delta_e(a_path, b_path, x0, y0, x1, y1):
    """Mean CIE76 dE between two images over [x0, x1) x [y0, y1)."""
    w, h, a = load(a_path, "CIE Lab float")
    w2, h2, b = load(b_path, "CIE Lab float")
    if (w, h) != (w2, h2):
        return float("inf")
    total = 0.0
    for y in range(y0, y1):
        for x in range(x0, x1):
            i = (y * w + x) * 3
            total += math.sqrt(sum((a[i + c] - b[i + c]) ** 2 for c in range(3)))
    return total / max(1, (x1 - x0) * (y1 - y0))


def delta_e_central(a_path, b_path):
    w, h, _ = load(a_path)
    return delta_e(a_path, b_path, w // 4, h // 4, w // 4 + w // 2, h // 4 + h // 2)


def tiled_2x2(src, dst):
    """Write `src` repeated twice across and twice down."""
    w, h, px = load(src)
    out = []
    for y in range(2 * h):
        row = px[(y % h) * w * 4:((y % h) + 1) * w * 4]
        out.extend(row)
        out.extend(row)
    save(dst, 2 * w, 2 * h, out, bitdepth=16)
    return dst


def max_abs_diff(a, b):
    return max(abs(x - y) for x, y in zip(a, b)) if len(a) == len(b) else float("inf")


if not Gegl.has_operation(OP):
    die("GEGL cannot find %s (GEGL_PATH=%s)" % (OP, os.environ.get("GEGL_PATH")))

# A crop of a pattern that does not end on its period: a visible seam.
brick = path("brick-crop.png")
tsops.run_gegl_here(["-i", exemplar("brick.png"), "-o", brick, "--", "gegl:crop", "x=7", "y=11",
                     "width=80", "height=70"])

note("-- the op's keys")
info = subprocess.run([gegl_tool, "--info", OP], capture_output=True, text=True, errors="replace").stdout
check("<Image>/Filters/Map" in info and "Make Seamless by Synthesis" in info,
      "GIMP menu path and label")
check("license" not in info.lower(), "no license key")

note("-- size, seam, layout")
out = path("brick-tileable.png")
warnings = tileable(brick, out, "seed=3")
w, h, px = load(out)
check((w, h) == (80, 70) and not warnings, "80x70 in, 80x70 out, no warnings (%dx%d %s)"
      % (w, h, warnings))
if not tsops.small():
    # The same figure on the output tiled 2x2: the windows where the copies
    # meet inside the tiling count with the others, those across its outer
    # edges as the seam; the input tiled that way is far from seamless.
    m_in, m_out, m_2x2, m_2x2_in = measure(brick, [brick, out, tiled_2x2(out, path("brick-2x2.png")),
                                                   tiled_2x2(brick, path("brick-in-2x2.png"))])
    check(m_out["seam"] <= SEAM_MAX, "seam %.3f <= %.2f (the input's own: %.1f)"
          % (m_out["seam"], SEAM_MAX, m_in["seam"]))
    check(m_out["sharpness"] >= 0.9, "sharpness %.3f >= 0.9 (no blending)" % m_out["sharpness"])
    check(m_2x2["seam"] <= SEAM_MAX and m_2x2_in["seam"] > 10 * SEAM_MAX,
          "tiled 2x2: seam %.3f <= %.2f (the input tiled 2x2: %.1f)"
          % (m_2x2["seam"], SEAM_MAX, m_2x2_in["seam"]))
de = delta_e_central(brick, out)
check(de <= DE_MAX, "layout kept: dE over the central half %.3f <= %.0f" % (de, DE_MAX))

note("-- determinism")
again = path("brick-again.png")
tileable(brick, again, "seed=3")
check(load(again)[2] == px, "same seed, same pixels")
other = path("brick-seed4.png")
tileable(brick, other, "seed=4")
check(load(other)[2] != px, "another seed, another result")
one_thread = path("brick-1thread.png")
code, _, err = subprocess.run([gegl_tool, "-i", brick, "-o", one_thread, "--", OP, "seed=3"],
                              capture_output=True, text=True, errors="replace",
                              env=dict(os.environ, OMP_NUM_THREADS="1")).returncode, None, None
check(load(one_thread)[2] == px, "same pixels with OMP_NUM_THREADS=1")

note("-- one direction only")
for direction, wrapped, kept in (("horizontal", "x", "y"), ("vertical", "y", "x")):
    res = path("brick-%s.png" % direction)
    warnings = tileable(brick, res, "direction=" + direction, "seed=3")
    check(not warnings, "%s: no warnings (%s)" % (direction, warnings))
    # The edges that do not wrap stay as they were away from the others.
    if kept == "y":
        de = delta_e(brick, res, w // 4, 0, w - w // 4, h)
    else:
        de = delta_e(brick, res, 0, h // 4, w, h - h // 4)
    check(de < 0.01, "%s: the %s edges are untouched (dE %.4f)"
          % (direction, "top/bottom" if kept == "y" else "left/right", de))
    if tsops.small():
        continue
    seam, seam_2x2 = (m["seam"] for m in measure(
        brick, [res, tiled_2x2(res, path("2x2-" + direction + ".png"))], "--tileable=" + wrapped))
    check(seam <= SEAM_MAX, "%s: seam along %s %.3f <= %.2f" % (direction, wrapped, seam, SEAM_MAX))
    check(seam_2x2 <= SEAM_MAX, "%s: tiled 2x2, seam along %s %.3f"
          % (direction, wrapped, seam_2x2))

note("-- every exemplar size, formats")
for name in ("rock.png", "granite1.png", "leopard.png"):   # non-square, grey, odd size
    res = path("t-" + name)
    warnings = tileable(exemplar(name), res, "seed=1")
    rw, rh, _ = load(res)
    ew, eh, _ = load(exemplar(name))
    check((rw, rh) == (ew, eh) and not warnings
          and delta_e_central(exemplar(name), res) <= DE_MAX,
          "%s %dx%d: size and layout kept" % (name, ew, eh))
    if not tsops.small():
        seam = measure(exemplar(name), [res])[0]["seam"]
        check(seam <= SEAM_MAX, "%s: seam %.3f <= %.2f" % (name, seam, SEAM_MAX))

# Alpha: a transparent hole in the middle and a soft alpha ramp.
ew, eh, epx = load(brick)
rgba = list(epx)
for y in range(eh):
    for x in range(ew):
        a = 0.0 if (30 <= x < 50 and 25 <= y < 45) else 0.4 + 0.6 * x / (ew - 1)
        rgba[(y * ew + x) * 4 + 3] = a
alpha_in = path("alpha.png")
save(alpha_in, ew, eh, rgba, bitdepth=16)
alpha_out = path("alpha-tileable.png")
warnings = tileable(alpha_in, alpha_out, "seed=2")
aw, ah, apx = load(alpha_out)
_, _, ain = load(alpha_in)
worst = max(abs(apx[(y * aw + x) * 4 + 3] - ain[(y * aw + x) * 4 + 3])
            for y in range(ah // 4, ah // 4 + ah // 2) for x in range(aw // 4, aw // 4 + aw // 2))
check(not warnings and (aw, ah) == (ew, eh) and worst < 1e-3,
      "with alpha: the hole and the ramp are kept in the central half (max change %.4f)" % worst)

note("-- XML graphs")


def node(op, **params):
    rows = "".join("      <param name=%s>%s</param>\n"
                   % (quoteattr(k.replace("_", "-")), escape(str(v))) for k, v in params.items())
    return "  <node operation=%s>\n    <params>\n%s    </params>\n  </node>\n" % (quoteattr(op), rows)


def run_graph(name, *nodes):
    xml, png = path(name + ".xml"), path(name + ".png")
    with open(xml, "w") as f:
        f.write("<?xml version='1.0' encoding='UTF-8'?>\n<gegl>\n%s</gegl>\n" % "".join(nodes))
    code, warnings, err = gegl(xml, "-o", png)
    if code != 0 or not os.path.isfile(png):
        die("gegl %s failed (exit %d):\n%s" % (xml, code, err))
    return png, warnings


load_node = node("gegl:load", path=exemplar("brick.png"))
png, warnings = run_graph("offset", node(OP, seed=3, seam_width=0.2, direction="both",
                                         quality=3, patch_size=9, fine_patch_size=5,
                                         iterations=4, histogram_matching="false"),
                          node("gegl:crop", x=7, y=11, width=80, height=70), load_node)
gw, gh, _ = load(png)
check((gw, gh) == (80, 70) and not warnings, "an input at (7, 11), every property: 80x70")
if not tsops.small():
    check(measure(brick, [png])[0]["seam"] <= SEAM_MAX, "... and seamless")

note("-- bad input")
tiny = path("tiny.png")
save(tiny, 6, 6, [0.5, 0.2, 0.1, 1.0] * 36)
res = path("tiny-out.png")
warnings = tileable(tiny, res)
check(len(warnings) == 1 and "too small" in warnings[0] and "left unchanged" in warnings[0],
      "6x6: a clear warning (%s)" % warnings)
check(max_abs_diff(load(res)[2], load(tiny)[2]) < 2e-3, "6x6: the image is left unchanged")
clear = path("clear.png")
save(clear, 32, 32, [0.3, 0.3, 0.3, 0.0] * 1024)
res = path("clear-out.png")
warnings = tileable(clear, res)
check(len(warnings) == 1 and "fully transparent" in warnings[0],
      "fully transparent: a clear warning (%s)" % warnings)
check(max(load(res)[2][3::4]) == 0.0, "fully transparent: stays transparent")
# One direction only needs the size along that direction.
strip = path("strip.png")
save(strip, 64, 5, [0.5, 0.2, 0.1, 1.0] * 320)
res = path("strip-out.png")
warnings = tileable(strip, res, "direction=horizontal")
check(not warnings and load(res)[:2] == (64, 5), "64x5 horizontally only: fine")

finish()
