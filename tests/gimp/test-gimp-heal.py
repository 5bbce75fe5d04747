# The heal procedures in GIMP 2.10, headless: plug-in-texsynth-heal-selection
# (pixels outside the selection bit-identical; a layer with offsets and a
# selection leaving it; 16-bit and 32-bit float), -heal-transparency and
# -uncrop, and the calling errors; in GIMP 2.10 and GIMP 3 (their
# Script-Fu dialects differ in loading, drawables, sizes and clearing).
# SPDX-License-Identifier: GPL-3.0-or-later
import argparse
import os
import re
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "ops"))
import tsops  # noqa: E402
import gimpbatch  # noqa: E402
from gimpbatch import quote  # noqa: E402

parser = argparse.ArgumentParser()
parser.add_argument("--gimp", required=True)
parser.add_argument("--plugin", required=True)
args = parser.parse_args()

work = tsops.workdir()
gimp = gimpbatch.Gimp(args.gimp, args.plugin, work)
V3 = gimp.version >= 3
stone = tsops.exemplar("stone33.png")   # 156x156, 8-bit RGB
healed = os.path.join(work, "healed.png")
uncropped = os.path.join(work, "uncropped.png")
uncropped_hole = os.path.join(work, "uncropped-hole.png")


def load():
    return gimp.sf.load(stone)


def pixel(x, y):
    return gimp.sf.pixel("drw", x, y)


DRW = gimp.sf.drawables()
IMAGE_WIDTH = "gimp-image-get-width" if V3 else "gimp-image-width"
IMAGE_HEIGHT = "gimp-image-get-height" if V3 else "gimp-image-height"
DRAWABLE_WIDTH = "gimp-drawable-get-width" if V3 else "gimp-drawable-width"
OFFSETS = "gimp-drawable-get-offsets" if V3 else "gimp-drawable-offsets"
CLEAR = "gimp-drawable-edit-clear" if V3 else "gimp-edit-clear"
U16 = "PRECISION-U16-NON-LINEAR" if V3 else "PRECISION-U16-GAMMA"


def message(tag, *values):
    return '(gimp-message (string-append "TSRESULT %s " %s))' % (
        tag, " \" \" ".join("(number->string %s)" % v for v in values))


def changed_kept(tag, setup, call, inside, outside, extra=()):
    """Runs `call` after `setup`; reports whether the pixel `inside`
    changed and the pixel `outside` was kept (1 = as expected)."""
    return ("(let* (%s) %s (let* ((in0 %s) (out0 %s)) %s %s))" % (
        load(), setup, pixel(*inside), pixel(*outside), call,
        message(tag, "(if (equal? in0 %s) 0 1)" % pixel(*inside),
                "(if (equal? out0 %s) 1 0)" % pixel(*outside), *extra)))


heal_sel = "(plug-in-texsynth-heal-selection RUN-NONINTERACTIVE img " + DRW + " %d %d 2 1)"
save_healed = gimp.sf.save("img", "drw", healed)
batch = [
    # In place, then saved for a byte comparison.
    "(let* (%s) (gimp-image-select-rectangle img CHANNEL-OP-REPLACE 60 60 30 30) %s "
    "(gimp-selection-none img) %s %s)"
    % (load(), heal_sel % (0, 0), save_healed, message("healsel", 1)),
    # A layer at offset (20, 20) and a selection that leaves it, 16 bits.
    changed_kept("healoffset16",
                 "(gimp-image-convert-precision img %s) " % U16 +
                 "(gimp-layer-resize drw 100 100 -20 -20) "
                 "(gimp-image-select-rectangle img CHANNEL-OP-REPLACE 80 80 60 60)",
                 heal_sel % (40, 1), (75, 75), (5, 5),
                 ["(car (gimp-image-get-precision img))",
                  "(car (%s drw))" % OFFSETS]),
    changed_kept("healfloat",
                 "(gimp-image-convert-precision img PRECISION-FLOAT-LINEAR) "
                 "(gimp-image-select-ellipse img CHANNEL-OP-REPLACE 50 60 40 30)",
                 heal_sel % (0, 2), (70, 75), (5, 5),
                 ["(car (gimp-image-get-precision img))"]),
    changed_kept("healtrans",
                 "(gimp-layer-add-alpha drw) "
                 "(gimp-image-select-rectangle img CHANNEL-OP-REPLACE 50 50 30 30) "
                 "(%s drw) (gimp-selection-none img)" % CLEAR,
                 "(plug-in-texsynth-heal-transparency RUN-NONINTERACTIVE img %s 0 0 2 1)" % DRW,
                 (60, 60), (5, 5)),
    "(let* (%s) (plug-in-texsynth-uncrop RUN-NONINTERACTIVE img %s 10 2 1) %s %s)"
    % (load(), DRW, gimp.sf.save("img", "drw", uncropped),
       message("uncrop", "(car (%s img))" % IMAGE_WIDTH, "(car (%s img))" % IMAGE_HEIGHT,
               "(car (%s drw))" % DRAWABLE_WIDTH)),
    # A layer that already has a transparent square: uncrop fills the new
    # border only.
    "(let* (%s) (gimp-layer-add-alpha drw) "
    "(gimp-image-select-rectangle img CHANNEL-OP-REPLACE 60 60 20 20) (%s drw) "
    "(gimp-selection-none img) (plug-in-texsynth-uncrop RUN-NONINTERACTIVE img %s 10 2 1) %s %s)"
    % (load(), CLEAR, DRW, gimp.sf.save("img", "drw", uncropped_hole), message("uncrophole", 1)),
]
errors = [
    '(begin (gimp-message "TSCALL nosel") (let* (%s) %s))' % (load(), heal_sel % (0, 0)),
    '(begin (gimp-message "TSCALL noalpha") (let* (%s) (plug-in-texsynth-heal-transparency '
    'RUN-NONINTERACTIVE img %s 0 0 2 1)))' % (load(), DRW),
    '(begin (gimp-message "TSCALL badcontext") (let* (%s) '
    '(gimp-image-select-rectangle img CHANNEL-OP-REPLACE 60 60 30 30) %s))'
    % (load(), heal_sel % (-1, 0)),
    '(begin (gimp-message "TSCALL nothing") (let* (%s) (gimp-selection-all img) %s))'
    % (load(), heal_sel % (0, 0)),
]
code, out, _ = gimp.run(batch)
lines = out.splitlines()
tsops.check(code == 0, "GIMP exits normally (exit code %d)" % code)
# GIMP 3 stops a batch at its first error: one session each there.
for session in ([[e] for e in errors] if V3 else [errors]):
    lines += gimp.run(session)[1].splitlines()
tsops.check(not any("crashed" in line for line in lines), "the plug-in never crashes")


def fields(tag):
    for line in lines:
        found = re.search(r"TSRESULT %s ((?:-?[0-9.]+ ?)*)" % re.escape(tag), line)
        if found:
            return [float(v) for v in found.group(1).split()]
    return None


if tsops.check(fields("healsel") is not None and os.path.isfile(healed),
               "heal-selection: ran and saved"):
    w, h, before = tsops.load_bytes(stone, "R'G'B' u8")
    _, _, after = tsops.load_bytes(healed, "R'G'B' u8")
    inside = lambda p: 60 <= p % w < 90 and 60 <= p // w < 90  # noqa: E731
    outside_changed = sum(1 for p in range(w * h) if not inside(p)
                          and before[3 * p:3 * p + 3] != after[3 * p:3 * p + 3])
    inside_changed = sum(1 for p in range(w * h) if inside(p)
                         and before[3 * p:3 * p + 3] != after[3 * p:3 * p + 3])
    tsops.check(outside_changed == 0, "heal-selection: every unselected pixel is bit-identical")
    tsops.check(inside_changed > 450, "heal-selection: the selection is filled (%d of 900 "
                "pixels changed)" % inside_changed)

r = fields("healoffset16")
tsops.check(r is not None and r[:2] == [1, 1] and int(r[2]) in gimp.sf.u16_precisions
            and int(r[3]) == 20,
            "heal-selection: a 16-bit layer at offset 20 with a selection leaving it: the selected "
            "part filled, the rest kept (%s)" % (r,))
r = fields("healfloat")
tsops.check(r is not None and r[:2] == [1, 1] and int(r[2]) == 600,
            "heal-selection: 32-bit float, an ellipse filled, the rest kept (%s)" % (r,))
r = fields("healtrans")
tsops.check(r is not None and r[:2] == [1, 1],
            "heal-transparency: the cleared square is filled, the rest kept (%s)" % (r,))
r = fields("uncrop")
tsops.check(r is not None and r == [186, 186, 186],
            "uncrop 10 %%: a 186x186 canvas and layer (%s)" % (r,))
if tsops.check(os.path.isfile(uncropped), "uncrop: saved"):
    w, h, before = tsops.load_bytes(stone, "R'G'B'A u8")
    uw, uh, after = tsops.load_bytes(uncropped, "R'G'B'A u8")
    moved = sum(1 for y in range(h) for x in range(w)
                if before[4 * (y * w + x):4 * (y * w + x) + 4]
                != after[4 * ((y + 15) * uw + x + 15):4 * ((y + 15) * uw + x + 15) + 4])
    tsops.check(moved == 0, "uncrop: the picture is kept bit for bit, 15 pixels in")
    tsops.check(min(after[3::4]) == 255, "uncrop: the new border is filled and opaque")
if tsops.check(fields("uncrophole") is not None and os.path.isfile(uncropped_hole),
               "uncrop of a layer with a transparent square: ran and saved"):
    w, h, before = tsops.load_bytes(stone, "R'G'B'A u8")
    uw, uh, after = tsops.load_bytes(uncropped_hole, "R'G'B'A u8")
    square = lambda x, y: 60 <= x < 80 and 60 <= y < 80  # noqa: E731
    alpha = lambda x, y: after[4 * (y * uw + x) + 3]  # noqa: E731
    kept_clear = sum(1 for y in range(60, 80) for x in range(60, 80) if alpha(x + 15, y + 15) == 0)
    moved = sum(1 for y in range(h) for x in range(w) if not square(x, y)
                and before[4 * (y * w + x):4 * (y * w + x) + 4]
                != after[4 * ((y + 15) * uw + x + 15):4 * ((y + 15) * uw + x + 15) + 4])
    border_open = sum(1 for y in range(uh) for x in range(uw)
                      if not (15 <= x < 15 + w and 15 <= y < 15 + h) and alpha(x, y) != 255)
    tsops.check(kept_clear == 400, "uncrop leaves the layer's own transparent square "
                "transparent (%d of 400 pixels)" % kept_clear)
    tsops.check(moved == 0, "uncrop keeps the rest of the picture bit for bit (%d moved)" % moved)
    tsops.check(border_open == 0, "uncrop fills the new border opaque, copying no transparent "
                "pixel (%d are not)" % border_open)
# GIMP 3's Script-Fu checks the registered range itself.
for tag, pattern in [("nosel", "no selection"), ("noalpha", "no alpha channel"),
                     ("badcontext", "out of range" if V3 else "context width"),
                     ("nothing", "Nothing was healed")]:
    text = gimp.error_text(lines, tag)
    tsops.check(text is not None and pattern in text, "%s: GIMP reports %r (%s)"
                % (tag, pattern, text))
tsops.finish()
