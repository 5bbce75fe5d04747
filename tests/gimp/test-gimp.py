# The texsynth plug-in in real, headless GIMP (2.10 or 3): Script-Fu calls
# the three procedures on real exemplars and prints what it finds; this
# script checks it. Run by meson (tests/gimp/meson.build) with the system
# Python, GEGL_PATH set to the freshly built ops.
# SPDX-License-Identifier: GPL-3.0-or-later
#
# Usage: test-gimp.py --gimp GIMP-CONSOLE --plugin PLUG-IN --measure TEXSYNTH-MEASURE

import argparse
import filecmp
import json
import os
import re
import struct
import subprocess
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "ops"))
import tsops  # noqa: E402
import gimpbatch  # noqa: E402

parser = argparse.ArgumentParser()
parser.add_argument("--gimp", required=True, help="gimp-console-2.10 or gimp-console-3.0")
parser.add_argument("--plugin", required=True, help="the built plug-in executable")
parser.add_argument("--measure", required=True, help="texsynth-measure")
args = parser.parse_args()

# scripts/sanitize.sh builds with sanitizers and preloads ASan into every
# test: GIMP itself is not built for it (its own leaks would fail the run),
# so there is nothing to learn about the plug-in here. (Not ASAN_OPTIONS:
# newer meson sets it for every test.)
def sanitized(path):
    with open(path, "rb") as f:
        data = f.read()
    return any(mark in data for mark in (b"__asan_init", b"__tsan_init", b"__ubsan_handle"))


if "san" in os.path.basename(os.environ.get("LD_PRELOAD", "")) or sanitized(args.plugin):
    tsops.note("SKIP  GIMP under a sanitizer run")
    sys.exit(77)

work = tsops.workdir()
gimp = gimpbatch.Gimp(args.gimp, args.plugin, work)
sf = gimp.sf  # the version's Script-Fu dialect
tsops.note("GIMP %s (%s), profile %s" % (gimp.version, args.gimp, gimp.profile))

# --- exemplars: 8-bit RGB, 16-bit RGB, 8-bit RGBA with transparent corners, grey
source_root = os.environ.get("TEXSYNTH_SOURCE_ROOT", ".")
bark = os.path.join(source_root, "examples", "bark.png")
brick = os.path.join(os.path.dirname(bark), "brick.png")
# Light stones in dark joints: what the solid's cell structure is for.
stones = os.path.join(source_root, "tests", "exemplars", "stone33.png")
bark16 = os.path.join(work, "bark16.png")
tsops.convert(bark, bark16, "R'G'B' u16", bitdepth=16)
brick_rgba = os.path.join(work, "brick-rgba.png")
tsops.convert(brick, brick_rgba, "R'G'B'A u8",
              alpha_fn=lambda x, y, w, h: 0.0 if (x < 8 and y < 8) else 1.0)

# Bark in the top-left and bottom-right quadrants, pure blue in the others:
# a selection of the two bark quadrants has the whole image as its bounds.
quadrants = os.path.join(work, "quadrants.png")
tsops.convert(bark, quadrants, "R'G'B' u8",
              colour_fn=lambda x, y, w, h: None if (x < w // 2) == (y < h // 2) else (0.0, 0.0, 1.0))


def fields(lines, tag):
    """The values printed after "TSRESULT <tag>" on the first such line."""
    for line in lines:
        found = re.search(r"%s ((?:-?[0-9.]+ ?)*)" % re.escape(tag), line)
        if found:
            return found.group(1).split()
    return None


# --- one GIMP session with every non-interactive call ------------------------
render16 = os.path.join(work, "render16.png")
render_rgba = os.path.join(work, "render-rgba.png")
render_a = os.path.join(work, "render-a.png")
render_b = os.path.join(work, "render-b.png")
render_shape = os.path.join(work, "render-shape.png")
tileable = os.path.join(work, "tileable.png")
volume = os.path.join(work, "volume.vol")
# The same solid with the cell structure off, on and automatic (which must
# choose it for these stones): its volume and the exported slice across x.
CELLS_OFF, CELLS_ON, CELLS_AUTO = 0, 1, 2
CELLS_SIZE = 32
plain_volume = os.path.join(work, "plain.vol")
cells_volume = os.path.join(work, "cells.vol")
# A .vol file's header holds its name: automatic's volume gets the same
# name as on's, in a folder of its own, so the two files may be compared.
os.makedirs(os.path.join(work, "auto"))
auto_volume = os.path.join(work, "auto", "cells.vol")
plain_slice = os.path.join(work, "plain-x.png")
cells_slice = os.path.join(work, "cells-x.png")
auto_slice = os.path.join(work, "auto-x.png")
CELL_RUNS = (("solidplain", plain_volume, plain_slice),
             ("solidcells", cells_volume, cells_slice),
             ("solidauto", auto_volume, auto_slice))
# GIMP 2.10 keeps last values as the bytes of TsSolidArgs: size, path[4096],
# quality, seed, then cell_structure (once a boolean, now 0/1/2), which
# older plug-ins' structs lack: those get the default, automatic. Each
# entry: tag, stored cell_structure, export, the slice it must equal.
LAST_VALUES = [("lastold", None, os.path.join(work, "last-old-x.png"), cells_slice),
               ("lastplain", CELLS_OFF, os.path.join(work, "last-plain-x.png"), plain_slice),
               ("lastcells", CELLS_ON, os.path.join(work, "last-cells-x.png"), cells_slice)]


def last_values(cell_structure):
    """The solidplain/solidcells settings as stored bytes; None: the older
    struct without cell_structure."""
    path = os.path.join(work, "last.vol").encode()
    data = struct.pack("<i4096sii", CELLS_SIZE, path, 1, 4)
    return data if cell_structure is None else data + struct.pack("<i", cell_structure)


# The Solid Texture procedure runs both ops: without them its checks
# below fail too, this one says why.
for solid_op in ("texsynth:volume-save", "texsynth:volume-slice"):
    tsops.check(gimpbatch.gegl_has(solid_op), "gegl finds %s (GEGL_PATH=%s)"
                % (solid_op, os.environ.get("GEGL_PATH", "<unset>")))

batch = [
    # Precision and size: a 16-bit exemplar gives a 16-bit image.
    sf.render_report("render16", bark16, 100, 80, "FALSE", 2, 7, save=render16),
    # Alpha is kept, and an 8-bit exemplar gives 8 bits.
    sf.render_report("renderrgba", brick_rgba, 64, 48, "FALSE", 2, 3, save=render_rgba),
    # The same seed and settings give the same texture.
    sf.render_report("rendera", bark, 64, 64, "TRUE", 2, 11, save=render_a),
    sf.render_report("renderb", bark, 64, 64, "TRUE", 2, 11, save=render_b),
    # A selection: its bounds are the exemplar.
    sf.render_report("renderselection", bark, 40, 30, "FALSE", 1, 5, select=(10, 10, 40, 40)),
    # Two rectangles: the exemplar is their shape, not their bounds.
    sf.render_report("rendershape", quadrants, 64, 64, "FALSE", 1, 5, save=render_shape,
                     select=[(0, 0, 40, 45), (41, 45, 41, 45)]),
    # In place and undoable: one undo step restores the layer.
    sf.tileable_report("tileable", brick, 2, 5, save=tileable),
]
# Bad arguments: a clear calling error, never a crash. GIMP 3 stops a
# batch at its first error, so there each gets a session of its own.
errors = [
    sf.call_render("badwidth", bark, 0, 80, "FALSE", 2, 7),
    sf.call_render("badquality", bark, 80, 80, "FALSE", 11, 7),
    sf.call_solid("badpath", bark, 16, "/nonexistent-folder/v.vol", 1, 1),
    sf.call_solid("badformat", bark, 16, os.path.join(work, "v.txt"), 1, 1),
]
batch.append(sf.solid_report("solid", bark, 16, volume, 1, 2))
for (tag, path, save), cells in zip(CELL_RUNS, (CELLS_OFF, CELLS_ON, CELLS_AUTO)):
    batch.append(sf.solid_report(tag, stones, CELLS_SIZE, path, 1, 4, cells, save=save))
# Automatic on transparent corners: not refused as "on" is (the engine
# leaves the cell structure off).
batch.append(sf.solid_report("autoalpha", brick_rgba, 16, os.path.join(work, "auto-a.vol"),
                             1, 1, CELLS_AUTO))
if gimp.version == 2:
    batch += [sf.solid_last_values_report(tag, stones, last_values(cells), save)
              for tag, cells, save, _ in LAST_VALUES]
# Transparent corners with the cell structure on: refused with a reason
# before anything runs.
errors.append(sf.call_solid("cellsalpha", brick_rgba, 16, os.path.join(work, "a.vol"), 1, 1,
                            CELLS_ON))
# No fourth choice.
errors.append(sf.call_solid("badcells", stones, 16, os.path.join(work, "b.vol"), 1, 1, 3))
if gimp.version >= 3:
    batch.append(sf.filter_report("filter", brick))

code, out, _ = gimp.run(batch)
lines = out.splitlines()
tsops.check(code == 0, "GIMP exits normally (exit code %d)" % code)
for session in ([[e] for e in errors] if gimp.version >= 3 else [errors]):
    lines += gimp.run(session)[1].splitlines()
tsops.check(not any("crashed" in line for line in lines), "the plug-in never crashes")

# --- results ------------------------------------------------------------------
r = fields(lines, "TSRESULT render16")
if tsops.check(r is not None, "render (16-bit exemplar) returns an image"):
    w, h, prec_in, prec_out = map(int, r[:4])
    tsops.check((w, h) == (100, 80), "render: the new image is 100x80 (got %dx%d)" % (w, h))
    tsops.check(prec_out == prec_in and prec_in in sf.u16_precisions,
                "render: 16-bit exemplar, 16-bit image (precision %d -> %d)" % (prec_in, prec_out))

r = fields(lines, "TSRESULT renderrgba")
if tsops.check(r is not None, "render (RGBA exemplar) returns an image"):
    w, h, prec_in, prec_out, alpha = map(int, r[:5])
    tsops.check((w, h) == (64, 48), "render: the new image is 64x48 (got %dx%d)" % (w, h))
    tsops.check(prec_out == prec_in, "render: 8-bit exemplar, same precision (%d -> %d)"
                % (prec_in, prec_out))
    tsops.check(alpha == 1, "render: RGBA exemplar, the new layer has alpha")
    _, _, px = tsops.load(render_rgba)
    tsops.check(min(tsops.alphas(px)) > 0.99,
                "render: transparent exemplar pixels are not copied (min alpha %.2f)"
                % min(tsops.alphas(px)))

if tsops.check(os.path.isfile(render_a) and os.path.isfile(render_b),
               "render: two runs with the same seed exported"):
    _, _, a = tsops.load(render_a)
    _, _, b = tsops.load(render_b)
    # Each run is a plug-in process of its own; the ops convert the
    # exemplar with fixed arithmetic, so only the last conversion to the
    # 8-bit layer (babl's, whose paths may differ between processes) may
    # round a value the other way. A different texture differs by ~0.9.
    diff = tsops.max_abs_diff(a, b)
    tsops.check(diff <= 1.5 / 255, "render: same seed, same texture (max difference %g)" % diff)

r = fields(lines, "TSRESULT renderselection")
tsops.check(r is not None and list(map(int, r[:2])) == [40, 30],
            "render with a selection: 40x30 image (got %s)" % (r,))

if tsops.check(os.path.isfile(render_shape), "render with a two-rectangle selection exported"):
    _, _, px = tsops.load(render_shape)
    blue = sum(1 for i in range(0, len(px), 4) if px[i + 2] > 0.9 and px[i] < 0.1 and px[i + 1] < 0.1)
    tsops.check(blue == 0, "render with a two-rectangle selection: nothing from the unselected "
                "quadrants (%d pure blue pixels of %d)" % (blue, len(px) // 4))

r = fields(lines, "TSRESULT tileable")
if tsops.check(r is not None and os.path.isfile(tileable), "tileable: ran and exported"):
    changed, kept = int(r[0]), int(r[1])
    tsops.check(changed == 1, "tileable: the layer's edges were changed in place")
    tsops.check(kept == 1, "tileable: the layer's middle is kept as it was")

    def seam(path):
        proc = subprocess.run([args.measure, "--json", "--tileable", brick, path],
                              capture_output=True, text=True, timeout=300)
        return json.loads(proc.stdout)["seam"] if proc.returncode == 0 else float("inf")

    # About 1 is seamless; docs/benchmarks.md's figure for texsynth:tileable is 0.36
    # (median over the shared exemplars).
    after = seam(tileable)
    tsops.check(after < 1.0, "tileable: the result tiles (seam figure %.2f < 1.0)" % after)


def volume_slice_x(path, size, png):
    """The volume's middle slice across x, read back by texsynth:volume-load:
    what the plug-in's top layer must show."""
    code, _, _ = tsops.run_gegl(["-o", png, "--", "texsynth:volume-load", "path=" + path,
                                 "axis=x", "index=%d" % (size // 2)])
    return tsops.load(png)[2] if code == 0 and os.path.isfile(png) else None


def check_cell_structure():
    for tag, path, slice_png in CELL_RUNS:
        r = fields(lines, "TSRESULT " + tag)
        if tsops.check(r is not None, "%s: returns an image" % tag):
            w, h, layers = map(int, r[:3])
            tsops.check((w, h, layers) == (CELLS_SIZE, CELLS_SIZE, 3),
                        "%s: three %dx%d slices (got %dx%d, %d)"
                        % (tag, CELLS_SIZE, CELLS_SIZE, w, h, layers))
        size = os.path.getsize(path) if os.path.isfile(path) else 0
        # At least a byte per channel of every RGB voxel.
        tsops.check(size >= CELLS_SIZE ** 3 * 3, "%s: the volume file was written (%d bytes)"
                    % (tag, size))
        if not tsops.check(os.path.isfile(slice_png), "%s: the slice across x exported" % tag):
            continue
        # The slices must come from the volume in the file: the slice op
        # gets the cell structure too. 8-bit exports round alike to 1/255.
        _, _, shown = tsops.load(slice_png)
        in_file = volume_slice_x(path, CELLS_SIZE, os.path.join(work, tag + "-file-x.png"))
        diff = tsops.max_abs_diff(shown, in_file) if in_file else float("inf")
        tsops.check(diff <= 1.5 / 255, "%s: the slice shown is the file's (max difference %g)"
                    % (tag, diff))
    if os.path.isfile(plain_slice) and os.path.isfile(cells_slice):
        diff = tsops.max_abs_diff(tsops.load(plain_slice)[2], tsops.load(cells_slice)[2])
        tsops.check(diff > 0.2, "solid: the cell structure changes the slices with the same "
                    "seed (max difference %.3f)" % diff)
    # Automatic chooses the cell structure for light stones in dark joints:
    # the very volume of "on".
    tsops.check(os.path.isfile(auto_volume) and os.path.isfile(cells_volume) and
                filecmp.cmp(auto_volume, cells_volume, shallow=False),
                "solid: automatic gives the stones the cell structure (the volume of on)")
    r = fields(lines, "TSRESULT autoalpha")
    tsops.check(r is not None and list(map(int, r[:3])) == [16, 16, 3],
                "solid: automatic on a layer with transparent pixels is not refused "
                "(got %s)" % (r,))
    # Last values: the older struct is read without cell_structure (the
    # default, automatic), the current one with it.
    for tag, cells, save, same_as in LAST_VALUES:
        if gimp.version != 2 or not os.path.isfile(same_as):
            continue
        r = fields(lines, "TSRESULT " + tag)
        ok = tsops.check(r is not None and os.path.isfile(save) and
                         list(map(int, r[:2])) == [CELLS_SIZE, CELLS_SIZE],
                         "%s: stored last values of %d bytes read (got %s)"
                         % (tag, len(last_values(cells)), r))
        diff = tsops.max_abs_diff(tsops.load(save)[2], tsops.load(same_as)[2]) if ok else 1.0
        tsops.check(diff == 0, "%s: the slice is %s's (max difference %g)"
                    % (tag, os.path.basename(same_as), diff))
    tsops.check(os.path.isfile(plain_volume) and os.path.isfile(cells_volume) and
                not filecmp.cmp(plain_volume, cells_volume, shallow=False),
                "solid: the cell structure changes the volume file")


def calling_error(tag, pattern):
    text = gimp.error_text(lines, tag)
    tsops.check(text is not None and sf.is_calling_error(text) and re.search(pattern, text),
                "%s: calling error with a clear message (%r)" % (tag, text))


# GIMP 3's Script-Fu names the argument by its position (width is the 4th,
# quality the 7th, after run mode, image and drawables).
calling_error("badwidth", r"width must be between 1 and 16384|argument 4 .*value 0 out of range: 1 to 16384")
calling_error("badquality", r"[Qq]uality must be between 1 and 10|argument 7 .*value 11 out of range: 1 to 10")
calling_error("badpath", r"folder \"/nonexistent-folder\" does not exist")
calling_error("badformat", r"must end in \.vol, \.dds or \.png")
text = gimp.error_text(lines, "cellsalpha")
tsops.check(text is not None and "needs an opaque exemplar" in text,
            "cell structure on a layer with transparent pixels: an error saying why (%r)" % text)
# GIMP 3's Script-Fu checks the range itself (cell-structure is the 8th).
calling_error("badcells", r"[Cc]ell structure must be 0 \(off\), 1 \(on\) or 2 "
              r"\(automatic\) \(got 3\)|argument 8 .*value 3 out of range: 0 to 2")

r = fields(lines, "TSRESULT solid")
if tsops.check(r is not None, "solid: returns an image"):
    w, h, layers = map(int, r[:3])
    tsops.check((w, h, layers) == (16, 16, 3), "solid: three 16x16 slices (got %dx%d, %d)"
                % (w, h, layers))
size = os.path.getsize(volume) if os.path.isfile(volume) else 0
tsops.check(size >= 16 ** 3 * 4, "solid: the volume file was written (%d bytes)" % size)
check_cell_structure()

if gimp.version >= 3:
    r = fields(lines, "TSRESULT filter")
    tsops.check(r is not None and r[0] == "1",
                "GIMP 3 runs texsynth:tileable as a layer filter (non-destructive effect)")

tsops.finish()
