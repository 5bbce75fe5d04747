# The heal procedures in GIMP 2.10, headless: plug-in-texsynth-heal-selection
# (pixels outside the selection bit-identical; a layer with offsets and a
# selection leaving it; 16-bit and 32-bit float), -heal-transparency and
# -uncrop, and the calling errors. (GIMP 3: not yet; see README.)
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
if gimp.version != 2:
    tsops.note("SKIP  the heal procedures are registered for GIMP 2.10 only so far")
    sys.exit(77)
stone = tsops.exemplar("stone33.png")   # 156x156, 8-bit RGB
healed = os.path.join(work, "healed.png")


def load():
    return ("(img (car (gimp-file-load RUN-NONINTERACTIVE %s %s))) "
            "(drw (car (gimp-image-get-active-drawable img)))" % (quote(stone), quote(stone)))


def pixel(x, y):
    return "(vector->list (cadr (gimp-drawable-get-pixel drw %d %d)))" % (x, y)


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


heal_sel = "(plug-in-texsynth-heal-selection RUN-NONINTERACTIVE img drw %d %d 2 1)"
batch = [
    # In place, then saved for a byte comparison.
    "(let* (%s) (gimp-image-select-rectangle img CHANNEL-OP-REPLACE 60 60 30 30) %s "
    "(gimp-selection-none img) (gimp-file-save RUN-NONINTERACTIVE img drw %s %s) %s)"
    % (load(), heal_sel % (0, 0), quote(healed), quote(healed), message("healsel", 1)),
    # A layer at offset (20, 20) and a selection that leaves it, 16 bits.
    changed_kept("healoffset16",
                 "(gimp-image-convert-precision img PRECISION-U16-GAMMA) "
                 "(gimp-layer-resize drw 100 100 -20 -20) "
                 "(gimp-image-select-rectangle img CHANNEL-OP-REPLACE 80 80 60 60)",
                 heal_sel % (40, 1), (75, 75), (5, 5),
                 ["(car (gimp-image-get-precision img))",
                  "(car (gimp-drawable-offsets drw))"]),
    changed_kept("healfloat",
                 "(gimp-image-convert-precision img PRECISION-FLOAT-LINEAR) "
                 "(gimp-image-select-ellipse img CHANNEL-OP-REPLACE 50 60 40 30)",
                 heal_sel % (0, 2), (70, 75), (5, 5),
                 ["(car (gimp-image-get-precision img))"]),
    changed_kept("healtrans",
                 "(gimp-layer-add-alpha drw) "
                 "(gimp-image-select-rectangle img CHANNEL-OP-REPLACE 50 50 30 30) "
                 "(gimp-edit-clear drw) (gimp-selection-none img)",
                 "(plug-in-texsynth-heal-transparency RUN-NONINTERACTIVE img drw 0 0 2 1)",
                 (60, 60), (5, 5), ["(list-ref %s 3)" % pixel(60, 60)]),
    "(let* (%s (k0 %s)) (plug-in-texsynth-uncrop RUN-NONINTERACTIVE img drw 10 2 1) %s)"
    % (load(), pixel(5, 5),
       message("uncrop", "(car (gimp-image-width img))", "(car (gimp-image-height img))",
               "(list-ref %s 3)" % pixel(0, 0), "(let ((p %s)) (if (and (= (car k0) (car p)) (= (cadr k0) (cadr p)) "
               "(= (caddr k0) (caddr p))) 1 0))" % pixel(20, 20),
               "(car (gimp-drawable-width drw))")),
]
errors = [
    '(begin (gimp-message "TSCALL nosel") (let* (%s) %s))' % (load(), heal_sel % (0, 0)),
    '(begin (gimp-message "TSCALL noalpha") (let* (%s) (plug-in-texsynth-heal-transparency '
    'RUN-NONINTERACTIVE img drw 0 0 2 1)))' % load(),
    '(begin (gimp-message "TSCALL badcontext") (let* (%s) '
    '(gimp-image-select-rectangle img CHANNEL-OP-REPLACE 60 60 30 30) %s))'
    % (load(), heal_sel % (-1, 0)),
    '(begin (gimp-message "TSCALL nothing") (let* (%s) (gimp-selection-all img) %s))'
    % (load(), heal_sel % (0, 0)),
]
code, out, _ = gimp.run(batch)
lines = out.splitlines()
tsops.check(code == 0, "GIMP exits normally (exit code %d)" % code)
lines += gimp.run(errors)[1].splitlines()
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
tsops.check(r is not None and r[:2] == [1, 1] and int(r[2]) in gimpbatch.ScriptFu2.u16_precisions
            and int(r[3]) == 20,
            "heal-selection: a 16-bit layer at offset 20 with a selection leaving it: the selected "
            "part filled, the rest kept (%s)" % (r,))
r = fields("healfloat")
tsops.check(r is not None and r[:2] == [1, 1] and int(r[2]) == 600,
            "heal-selection: 32-bit float, an ellipse filled, the rest kept (%s)" % (r,))
r = fields("healtrans")
tsops.check(r is not None and r[:2] == [1, 1] and r[2] == 255,
            "heal-transparency: the cleared square is filled and opaque, the rest kept (%s)" % (r,))
r = fields("uncrop")
tsops.check(r is not None and r[:2] == [156 + 2 * 15, 156 + 2 * 15] and r[2] == 255 and r[3] == 1
            and r[4] == 186,
            "uncrop 10 %%: a 186x186 canvas, the new corner filled and opaque, the picture kept "
            "in place (%s)" % (r,))
for tag, pattern in [("nosel", "no selection"), ("noalpha", "no alpha channel"),
                     ("badcontext", "context width"), ("nothing", "Nothing was healed")]:
    text = gimp.error_text(lines, tag)
    tsops.check(text is not None and pattern in text, "%s: GIMP reports %r (%s)"
                % (tag, pattern, text))
tsops.finish()
