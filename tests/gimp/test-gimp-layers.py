# plug-in-texsynth-render-layers in headless GIMP (2.10 or 3): a material
# set of three layers of one size ("height", the inverse of "albedo";
# "albedo"; "moved", a copy of albedo with alpha at offset (30, 20)) is
# synthesised with one layout in 8-bit, 16-bit (driven by "height"),
# 32-bit float, and 8-bit tileable (driven by "moved"). The new image must have the same layers, names, order and
# precision, and the layers must share one layout: "height" stays the
# inverse of "albedo" and "moved" equals "albedo". Bad input: layers of
# different sizes give a calling error and leave the image as it was.
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
sf = gimp.sf
V3 = gimp.version >= 3
brick = tsops.exemplar("brick.png")   # 96x96, 8-bit RGB
WIDTH, HEIGHT = 80, 72
NAMES = ["height", "albedo", "moved"]  # top to bottom
U16 = "PRECISION-U16-NON-LINEAR" if V3 else "PRECISION-U16-GAMMA"
# The tolerance of the alignment measure: 1 % of the range.
TOLERANCE = 0.01


def layers(image):
    """The image's layers as a Scheme vector, top first."""
    return "(car (gimp-image-get-layers %s))" % image if V3 else \
        "(cadr (gimp-image-get-layers %s))" % image


N_IMAGES = "(vector-length (car (gimp-get-images)))" if V3 else "(car (gimp-image-list))"


def material_set(precision):
    """Bindings and setup that make the three-layer set from brick."""
    bindings = ("%s (h (car (gimp-layer-new-from-drawable drw img)))"
                " (m (car (gimp-layer-new-from-drawable drw img)))" % sf.load(brick))
    setup = ""
    if precision:
        bindings = bindings.replace("(h (car", "(conv (gimp-image-convert-precision img %s))"
                                    " (h (car" % precision, 1)
    setup += ("(gimp-image-insert-layer img h 0 0) (gimp-image-insert-layer img m 0 2) "
              "(gimp-item-set-name h \"height\") (gimp-item-set-name drw \"albedo\") "
              "(gimp-item-set-name m \"moved\") (gimp-drawable-invert h FALSE) "
              "(gimp-layer-add-alpha m) (gimp-layer-set-offsets m 30 20) ")
    return bindings, setup


def save_layer(image, index, path):
    """Saves layer `index` of `image` alone (a duplicate with the others
    removed), in the image's precision."""
    removals = " ".join("(gimp-image-remove-layer dup (vector-ref ls %d))" % i
                        for i in range(len(NAMES)) if i != index)
    return ("(let* ((dup (car (gimp-image-duplicate %s))) (ls %s)) %s %s)"
            % (image, layers("dup"), removals, sf.save("dup", "(vector-ref ls %d)" % index, path)))


def run_set(tag, precision, driver, tileable="FALSE"):
    """Synthesises the set driven by the layer bound to `driver`; reports
    the new image's size, layer count, precision and each layer's alpha,
    prints its layer names, saves its layers."""
    bindings, setup = material_set(precision)
    drivers = "(vector %s)" % driver if V3 else driver
    call = ("(car (plug-in-texsynth-render-layers RUN-NONINTERACTIVE img %s %d %d %s 2 5))"
            % (drivers, WIDTH, HEIGHT, tileable))
    saves = " ".join(save_layer("out", i, os.path.join(work, "%s-%d.png" % (tag, i)))
                     for i in range(len(NAMES)))
    names = " \"|\" ".join("(car (gimp-item-get-name (vector-ref %s %d)))" % (layers("out"), i)
                           for i in range(len(NAMES)))
    alphas = ["(car (gimp-drawable-has-alpha (vector-ref %s %d)))" % (layers("out"), i)
              for i in range(len(NAMES))]
    return ("(let* (%s) %s (let* ((out %s)) %s "
            "(gimp-message (string-append \"TSNAMES %s \" %s)) %s))"
            % (bindings, setup, call, saves, tag, names,
               sf.message(tag, sf.width("out"), sf.height("out"), sf.n_layers("out"),
                          "(car (gimp-image-get-precision img))",
                          "(car (gimp-image-get-precision out))", *alphas)))


# Layers of different sizes: an error, and nothing new or changed. GIMP 3
# stops a batch at an uncaught error; `catch` goes on to the report.
bad_size = ("(let* (%s (b (car (gimp-layer-new-from-drawable drw img)))) "
            "(gimp-image-insert-layer img b 0 0) (gimp-layer-resize b 50 40 0 0) "
            "(gimp-item-set-name b \"small\") (gimp-item-set-name drw \"albedo\") "
            "(let* ((images %s) (before %s)) (gimp-message \"TSCALL badsize\") "
            "(catch #f (plug-in-texsynth-render-layers RUN-NONINTERACTIVE img %s 40 40 FALSE 1 1)) "
            "%s))" % (sf.load(brick), N_IMAGES, sf.pixel("drw", 10, 10),
                      "(vector drw)" if V3 else "drw",
                      sf.message("badsize", "(- %s images)" % N_IMAGES, sf.n_layers("img"),
                                 "(if (equal? before %s) 1 0)" % sf.pixel("drw", 10, 10))))

batch = [run_set("set8", None, "drw"),
         run_set("set16", U16, "h"),
         run_set("setfloat", "PRECISION-FLOAT-LINEAR", "drw"),
         run_set("settile", None, "m", tileable="TRUE"),
         bad_size]
code, out, _ = gimp.run(batch)
lines = out.splitlines()
tsops.check(code == 0, "GIMP exits normally (exit code %d)" % code)
tsops.check(not any("crashed" in line for line in lines), "the plug-in never crashes")


def fields(tag):
    for line in lines:
        found = re.search(r"TSRESULT %s ((?:-?[0-9.]+ ?)*)" % re.escape(tag), line)
        if found:
            return [int(float(v)) for v in found.group(1).split()]
    return None


def names(tag):
    for line in lines:
        found = re.search(r"TSNAMES %s (\S+)" % re.escape(tag), line)
        if found:
            return found.group(1).split("|")
    return None


def max_error(a, b, fn):
    """Max over colour channels of |b - fn(a)|, alpha ignored."""
    return max(abs(b[i] - fn(a[i])) for i in range(len(a)) if i % 4 != 3)


worst = 0.0
for tag, precision in (("set8", "8-bit"), ("set16", "16-bit, driven by height"),
                       ("setfloat", "32-bit float"),
                       ("settile", "8-bit, tileable, driven by the moved layer")):
    r = fields(tag)
    if not tsops.check(r is not None, "%s (%s): returns a new image" % (tag, precision)):
        continue
    w, h, n, prec_in, prec_out, *alpha = r
    tsops.check((w, h, n) == (WIDTH, HEIGHT, 3), "%s: %dx%d with 3 layers (got %dx%d, %d)"
                % (tag, WIDTH, HEIGHT, w, h, n))
    tsops.check(prec_out == prec_in, "%s: same precision (%d -> %d)" % (tag, prec_in, prec_out))
    tsops.check(names(tag) == NAMES, "%s: the layers keep their names and order (%s)"
                % (tag, names(tag)))
    tsops.check(alpha == [0, 0, 1], "%s: only \"moved\" has alpha, as before (%s)" % (tag, alpha))
    paths = [os.path.join(work, "%s-%d.png" % (tag, i)) for i in range(3)]
    if not tsops.check(all(os.path.isfile(p) for p in paths), "%s: its layers were saved" % tag):
        continue
    height, albedo, moved = (tsops.load(p)[2] for p in paths)
    inverse = max_error(albedo, height, lambda v: 1.0 - v)
    same = max_error(albedo, moved, lambda v: v)
    worst = max(worst, inverse, same)
    tsops.check(inverse <= TOLERANCE, "%s: \"height\" is still the inverse of \"albedo\" "
                "(max error %.5f of the range)" % (tag, inverse))
    tsops.check(same <= TOLERANCE, "%s: \"moved\" (at offset 30, 20) has albedo's layout "
                "(max error %.5f)" % (tag, same))
    # Synthesised, not a crop of the set (which would also stay aligned).
    bw, _, exemplar = tsops.load(brick)
    cropped = sum(1 for y in range(HEIGHT) for x in range(WIDTH)
                  if max(abs(albedo[4 * (y * WIDTH + x) + c] - exemplar[4 * (y * bw + x) + c])
                         for c in range(3)) < 0.02)
    tsops.check(cropped < WIDTH * HEIGHT // 2 and max(albedo) - min(albedo) > 0.3,
                "%s: the layers are synthesised texture, not a crop or a flat colour "
                "(%d of %d pixels as in the exemplar's corner)" % (tag, cropped, WIDTH * HEIGHT))
    if tag == "settile":
        # Every layer tiles, not only the driving one: the layout does.
        seam = max(max(tsops.wrap_seam_excess(WIDTH, HEIGHT, px)) for px in (height, albedo, moved))
        tsops.check(seam <= 1.2, "%s: every layer tiles (wrap-around seam figure %.2f <= 1.2)"
                    % (tag, seam))
tsops.note("layout agreement: max error %.5f of the range over all precisions" % worst)

r = fields("badsize")
text = gimp.error_text(lines, "badsize")
tsops.check(text is not None and "same size" in text and "\"small\" is 50\u00d740" in text,
            "layers of different sizes: a calling error naming the layer (%s)" % text)
tsops.check(r == [0, 2, 1], "layers of different sizes: no new image, the image's 2 layers "
            "and pixels as they were (%s)" % (r,))
tsops.finish()
