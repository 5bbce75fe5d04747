# The guided procedures in headless GIMP (2.10 or 3):
# plug-in-texsynth-texture-by-numbers paints a two-texture exemplar (brick
# on the left, 3dweave on the right, its guide black and white) along a
# target guide of a white disc on black, as a new layer above the target,
# with label edges cut and blended; away from the disc's edge, the blocks
# inside it must look like the weave (their nearest window of the two
# textures is the weave's) and those outside like the brick, and the two
# layers must differ. plug-in-texsynth-style-transfer repaints a
# dark-to-light gradient with brick's texture in place: its
# blurred lightness must follow the gradient's. Bad input: an exemplar's
# guide of another size is a calling error that adds no layer.
# SPDX-License-Identifier: GPL-3.0-or-later
import argparse
import math
import os
import struct
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "ops"))
import tsops  # noqa: E402
import gimpbatch  # noqa: E402

parser = argparse.ArgumentParser()
parser.add_argument("--gimp", required=True)
parser.add_argument("--plugin", required=True)
args = parser.parse_args()

work = tsops.workdir()
gimp = gimpbatch.Gimp(args.gimp, args.plugin, work)
sf = gimp.sf
V3 = gimp.version >= 3
Gegl = tsops.gegl()

HALF = 96                      # each texture of the exemplar: 96x96
TARGET_W, TARGET_H = 128, 96   # the target guide
CENTRE, RADIUS = (64, 48), 30  # its white disc
BLOCK = 8                      # the blocks whose mean colour is classified
EDGE = 6                       # blocks this close to the disc's edge are not judged


def write_png(path, w, h, pixel):
    """An 8-bit RGB PNG whose pixel (x, y) is pixel(x, y), floats 0..1."""
    values = []
    for y in range(h):
        for x in range(w):
            values.extend(pixel(x, y) + (1.0,))
    buf = Gegl.Buffer.new("R'G'B'A float", 0, 0, w, h)
    buf.set(Gegl.Rectangle.new(0, 0, w, h), "R'G'B'A float",
            struct.pack("%df" % len(values), *values))
    out = Gegl.Buffer.new("R'G'B' u8", 0, 0, w, h)
    buf.copy(Gegl.Rectangle.new(0, 0, w, h), Gegl.AbyssPolicy.NONE, out,
             Gegl.Rectangle.new(0, 0, w, h))
    tsops.save_buffer(out, path)


def crop_pixels(name):
    """The top-left HALF x HALF pixels of a bundled exemplar, as a function."""
    w, _, px = tsops.load(tsops.exemplar(name))
    return lambda x, y: tuple(px[(y * w + x) * 4:(y * w + x) * 4 + 3])


brick, weave = crop_pixels("brick.png"), crop_pixels("3dweave.png")
exemplar = os.path.join(work, "exemplar.png")
guide = os.path.join(work, "guide.png")
small_guide = os.path.join(work, "small-guide.png")
target = os.path.join(work, "target.png")
gradient = os.path.join(work, "gradient.png")
write_png(exemplar, 2 * HALF, HALF, lambda x, y: brick(x, y) if x < HALF else weave(x - HALF, y))
write_png(guide, 2 * HALF, HALF, lambda x, y: (0.0,) * 3 if x < HALF else (1.0,) * 3)
write_png(small_guide, HALF, HALF, lambda x, y: (0.0,) * 3)
inside = lambda x, y: math.hypot(x + 0.5 - CENTRE[0], y + 0.5 - CENTRE[1]) < RADIUS  # noqa: E731
write_png(target, TARGET_W, TARGET_H, lambda x, y: (1.0,) * 3 if inside(x, y) else (0.0,) * 3)
write_png(gradient, TARGET_W, TARGET_H, lambda x, y: (0.15 + 0.7 * x / (TARGET_W - 1),) * 3)

BLENDS = ("FALSE", "TRUE")
by_numbers_out = {blend: os.path.join(work, "by-numbers-%s.png" % blend) for blend in BLENDS}
style_out = os.path.join(work, "style.png")


def load_as(name, path):
    """Bindings: image `name`-img and its layer `name` loaded from `path`."""
    binding = sf.load(path).replace("(img ", "(%s-img " % name).replace("(drw ", "(%s " % name)
    return binding.replace(" img)", " %s-img)" % name)


def layer_count(image):
    return sf.n_layers(image)


def by_numbers_call(guide_layer, blend="FALSE", seed=1):
    drawables = "(vector tgt)" if V3 else "tgt"
    return ("(plug-in-texsynth-texture-by-numbers RUN-NONINTERACTIVE tgt-img %s ex %s 1.0 %s FALSE "
            "2 %d)" % (drawables, guide_layer, blend, seed))


def save_layer(image, layer, path):
    # GIMP 3 saves the image; the new layer is on top and opaque.
    return sf.save(image, layer, path)


by_numbers = ["(let* (%s %s %s (before %s) (new (car %s))) %s %s)" % (
    load_as("tgt", target), load_as("ex", exemplar), load_as("gd", guide),
    layer_count("tgt-img"), by_numbers_call("gd", blend),
    save_layer("tgt-img", "new", by_numbers_out[blend]),
    sf.message("bynumbers-" + blend, "(- %s before)" % layer_count("tgt-img"),
               "(car (%s new))" % ("gimp-drawable-get-width" if V3 else "gimp-drawable-width"),
               "(car (%s new))" % ("gimp-drawable-get-height" if V3 else "gimp-drawable-height")))
              for blend in BLENDS]

style = ("(let* (%s %s (before %s)) (plug-in-texsynth-style-transfer RUN-NONINTERACTIVE "
         "tgt-img %s ex 1.0 2 1) %s %s)" % (
             load_as("tgt", gradient), load_as("ex", tsops.exemplar("brick.png")),
             layer_count("tgt-img"), "(vector tgt)" if V3 else "tgt",
             sf.save("tgt-img", "tgt", style_out),
             sf.message("style", "(- %s before)" % layer_count("tgt-img"))))

# GIMP 3 stops a batch at an uncaught error; `catch` goes on to the report.
bad_size = ('(begin (gimp-message "TSCALL badsize") (let* (%s %s %s (before %s)) '
            "(catch #f %s) %s))" % (
                load_as("tgt", target), load_as("ex", exemplar), load_as("gd", small_guide),
                layer_count("tgt-img"), by_numbers_call("gd"),
                sf.message("badsize", "(- %s before)" % layer_count("tgt-img"))))

code, out, _ = gimp.run(by_numbers + [style, bad_size])
lines = out.splitlines()
tsops.check(code == 0, "GIMP exits normally (exit code %d)" % code)
tsops.check(not any("crashed" in line for line in lines), "the plug-in never crashes")


def fields(tag):
    for line in lines:
        if "TSRESULT %s " % tag in line:
            return [int(float(v)) for v in line.split("TSRESULT %s " % tag)[1].split()]
    return None


def block_means(path):
    """Mean R'G'B' of each BLOCK x BLOCK block: {(bx, by): (r, g, b)}."""
    w, h, px = tsops.load(path)
    means = {}
    for by in range(h // BLOCK):
        for bx in range(w // BLOCK):
            total = [0.0, 0.0, 0.0]
            for y in range(by * BLOCK, (by + 1) * BLOCK):
                for x in range(bx * BLOCK, (bx + 1) * BLOCK):
                    for c in range(3):
                        total[c] += px[(y * w + x) * 4 + c]
            means[(bx, by)] = tuple(t / BLOCK ** 2 for t in total)
    return means


def window_features(pixel, x0, y0):
    """Mean and spread of each channel over the BLOCK x BLOCK window at (x0, y0)."""
    values = [pixel(x, y) for y in range(y0, y0 + BLOCK) for x in range(x0, x0 + BLOCK)]
    means = [sum(v[c] for v in values) / len(values) for c in range(3)]
    spreads = [math.sqrt(sum((v[c] - means[c]) ** 2 for v in values) / len(values))
               for c in range(3)]
    return tuple(means + spreads)


def texture_windows(pixel):
    """Features of the texture's windows, every other pixel: a texture is
    told by its nearest window, since one colour does not stand for a
    texture with parts of several (the weave's brown strands)."""
    return [window_features(pixel, x, y)
            for y in range(0, HALF - BLOCK + 1, 2) for x in range(0, HALF - BLOCK + 1, 2)]


def nearest(features, windows):
    return min(math.dist(features, w) for w in windows)


brick_windows, weave_windows = texture_windows(brick), texture_windows(weave)
for blend in BLENDS:
    what = "texture by numbers, %s label edges" % ("blended" if blend == "TRUE" else "cut")
    r = fields("bynumbers-" + blend)
    if not tsops.check(r is not None, "%s returns a new layer" % what):
        continue
    tsops.check(r == [1, TARGET_W, TARGET_H], "%s: one new layer of the target's size %dx%d "
                "(got %s)" % (what, TARGET_W, TARGET_H, r))
    w, _, px = tsops.load(by_numbers_out[blend])
    result = lambda x, y: px[(y * w + x) * 4:(y * w + x) * 4 + 3]  # noqa: E731
    right = judged = 0
    for by in range(TARGET_H // BLOCK):
        for bx in range(TARGET_W // BLOCK):
            cx, cy = (bx + 0.5) * BLOCK, (by + 0.5) * BLOCK
            distance = math.hypot(cx - CENTRE[0], cy - CENTRE[1]) - RADIUS
            if abs(distance) < EDGE + BLOCK / 2:
                continue
            features = window_features(result, bx * BLOCK, by * BLOCK)
            nearer_weave = nearest(features, weave_windows) < nearest(features, brick_windows)
            judged += 1
            right += nearer_weave == (distance < 0)
    share = right / judged if judged else 0.0
    tsops.check(share >= 0.95, "%s: %.3f of %d blocks away from the disc's edge take the "
                "texture their label asks for (>= 0.95)" % (what, share, judged))

if all(os.path.exists(by_numbers_out[blend]) for blend in BLENDS):
    tsops.check(tsops.load(by_numbers_out["FALSE"])[2] != tsops.load(by_numbers_out["TRUE"])[2],
                "blend-edges reaches the op: blended and cut label edges give different layers")

r = fields("style")
if tsops.check(r is not None, "style transfer runs"):
    tsops.check(r == [0], "style transfer adds no layer (%s)" % r)
    means = block_means(style_out)
    ours = [sum(c) / 3 for _, c in sorted(means.items())]
    want = [0.15 + 0.7 * ((bx + 0.5) * BLOCK - 0.5) / (TARGET_W - 1) for (bx, _), _ in sorted(means.items())]
    mo, mw = sum(ours) / len(ours), sum(want) / len(want)
    cov = sum((a - mo) * (b - mw) for a, b in zip(ours, want))
    corr = cov / math.sqrt(sum((a - mo) ** 2 for a in ours) * sum((b - mw) ** 2 for b in want))
    tsops.check(corr >= 0.9, "style transfer: the %dx%d-block lightness follows the layer's "
                "gradient (correlation %.3f >= 0.9)" % (BLOCK, BLOCK, corr))

r = fields("badsize")
tsops.check(r == [0], "an exemplar's guide of another size adds no layer (%s)" % r)
error = gimp.error_text(lines, "badsize")
tsops.check(error is not None and "guide" in error,
            "an exemplar's guide of another size is refused with a message (%s)" % error)
tsops.finish()
