# Bad input through the GEGL operations: every case ends with no crash or
# hang, an image of the requested size, and either no warning or a warning
# from the op that says what was wrong (with a transparent result for
# texsynth:synthesize, the unchanged image for texsynth:tileable and
# texsynth:heal). The cases run in this one process, each on the graph the
# gegl tool would build from the same chain (tsops.chain_node), since every
# gegl run would start GEGL anew; for each op a refusal also runs through
# the gegl tool, which must exit 0.
# Prints how many distinct bad inputs were tried.
# SPDX-License-Identifier: LGPL-3.0-or-later

import math
import os
import resource
import struct
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "ops"))
import tsops  # noqa: E402
from tsops import check, note  # noqa: E402

SYNTH, TILE, HEAL = "texsynth:synthesize", "texsynth:tileable", "texsynth:heal"
Gegl = tsops.gegl()
for op in (SYNTH, TILE, HEAL):
    if not Gegl.has_operation(op):
        tsops.die("GEGL cannot find %s (GEGL_PATH=%s)" % (op, os.environ.get("GEGL_PATH")))

tmp = tsops.workdir()
bark = tsops.exemplar("bark.png")
out = os.path.join(tmp, "out.png")
tried = {"accepted": 0, "refused": 0}


def op_warnings(stderr, op):
    return [line for line in stderr.splitlines() if op + ": " in line]


def render_chain(args):
    """Renders the gegl tool's chain `args` (its arguments after '--', with
    '-i PATH' first for an input) in this process: (ok, w, h, pixels,
    stderr), ok False when the tool would have failed."""
    with tsops.captured_stderr() as err:
        node = tsops.chain_node(args)
        w, h, px = tsops.render(node) if node else (0, 0, [])
    return node is not None, w, h, px, err[0]


def tool_chain(args):
    """The same through the gegl tool: (exit status 0, w, h, pixels, stderr)."""
    if args and args[0] == "-i":
        args = ["-i", args[1], "-o", out, "--"] + args[2:]
    else:
        args = ["-o", out, "--"] + args
    if os.path.exists(out):
        os.unlink(out)
    code, _, err = tsops.run_gegl(args, timeout=300)
    w, h, px = tsops.load(out) if code == 0 and os.path.isfile(out) else (0, 0, [])
    return code == 0, w, h, px, err


def cli_case(label, source, op, props, size, word=None, glib_word=None, tool=False):
    """One case. `source` is ["-i", PATH, ops...] or [ops...], as for the
    gegl tool; `word` None means the op must accept the input, else its
    warning must say it; `tool` runs it through the gegl tool."""
    args = source + [op] + ["%s=%s" % kv for kv in props.items()]
    ran, w, h, px, err = (tool_chain if tool else render_chain)(args)
    warnings = op_warnings(err, op)
    ok = ran and (w, h) == size
    if word is None:
        ok = ok and not warnings
        tried["accepted"] += 1
    else:
        ok = ok and bool(warnings) and word in warnings[0]
        if ok and op == SYNTH:
            ok = max(tsops.alphas(px)) == 0.0
        tried["refused"] += 1
    if glib_word:
        ok = ok and glib_word in err
    check(ok, "%s: %s %s%s -> %s, %dx%d, %s" % (
        op, label, props, " (gegl tool)" if tool else "", "ran" if ran else "failed", w, h,
        warnings[0].split(op + ": ")[1] if warnings else "no warning from the op"))
    return err


note("-- degenerate exemplars")
crop = lambda w, h: ["-i", bark, "gegl:crop", "width=%d" % w, "height=%d" % h]
color = lambda value, w, h: ["gegl:color", "value=%s" % value, "gegl:crop", "width=%d" % w,
                             "height=%d" % h]
for op, props, size in ((SYNTH, {"width": 24, "height": 20, "seed": 3}, None),
                        (TILE, {"seed": 3}, "input")):
    cases = [
        ("no (0x0) exemplar", [], (0, 0), "no pixels"),
        ("1x1 exemplar", crop(1, 1), (1, 1), "1x1"),
        ("2x5 exemplar", crop(2, 5), (2, 5), "2x5"),
        ("7x7 exemplar", crop(7, 7), (7, 7), "7x7"),
        ("transparent exemplar", color("transparent", 16, 16), (16, 16), "transparent"),
        ("one-colour exemplar", color("rgb(0.2,0.5,0.7)", 16, 16), (16, 16), None),
        ("unbounded exemplar", ["gegl:color", "value=red"], None, "unbounded"),
    ]
    for label, source, input_size, word in cases:
        if size is None:
            expected = (props["width"], props["height"])
        elif input_size is None or input_size == (0, 0):
            continue   # tileable keeps the input's size: nothing to write
        else:
            expected = input_size
        if op == SYNTH and label == "7x7 exemplar":
            word = None   # large enough for synthesis, too small to make tileable
        cli_case(label, source, op, props, expected, word, tool=label == "2x5 exemplar")

note("-- every property at its minimum and maximum, and out of range")
small = {"width": 24, "height": 20, "seed": 3}
limits = [
    ({"width": 1, "height": 1}, None),
    ({"width": 16384, "height": 1}, None),
    ({"quality": 1}, None), ({"quality": 10}, None),
    ({"patch-size": 0}, None), ({"patch-size": 31}, None),
    ({"fine-patch-size": 0}, None), ({"fine-patch-size": 31}, None),
    ({"iterations": 0}, None), ({"iterations": 100}, None),
    ({"seed": 0}, None), ({"seed": 2147483647}, None),
    ({"histogram-matching": "false"}, None), ({"tileable": "true"}, None),
    ({"memory-limit": 0}, None), ({"memory-limit": 2147483647}, None),
    ({"memory-limit": 1}, "MiB"),
]
for extra, word in limits:
    props = dict(small, **extra)
    size = (int(props["width"]), int(props["height"]))
    cli_case("limit", ["-i", bark], SYNTH, props, size, word)
for extra, glib in [({"width": 0}, "width"), ({"quality": 99}, "quality"),
                    ({"patch-size": -4}, "patch-size"), ({"iterations": 1000}, "iterations")]:
    # GObject refuses the value with its own warning and keeps the default.
    props = dict(small, **extra)
    size = (512 if "width" in extra else 24, 20)
    cli_case("out of range", ["-i", bark], SYNTH, props, size, None, glib_word=glib)

bark_size = tsops.load(bark)[:2]
for extra, word in [({"seam-width": 0.02}, None), ({"seam-width": 0.25}, None),
                    ({"direction": "horizontal"}, None), ({"direction": "vertical"}, None),
                    ({"quality": 1, "patch-size": 31, "fine-patch-size": 31}, None),
                    ({"memory-limit": 1}, "MiB")]:
    cli_case("limit", ["-i", bark], TILE, dict({"seed": 3}, **extra), bark_size, word)

note("-- a huge size is refused from the estimate, before anything is allocated")
code, _, err = tsops.run_gegl(["-i", bark, "-o", out, "--", SYNTH, "width=16384",
                               "height=16384", "gegl:crop", "width=8", "height=8"])
warnings = op_warnings(err, SYNTH)
peak_mib = resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss / 1024.0
tried["refused"] += 1
check(code == 0 and warnings and "would need about" in warnings[0] and "MiB" in warnings[0]
      and "raise the memory limit" in warnings[0],
      "16384x16384: %s" % (warnings[0].split(SYNTH + ": ")[1] if warnings else "no warning"))
check(peak_mib < 1024, "the refusal peaks at %.0f MiB of memory (< 1024), far below the "
      "16 GiB it would need" % peak_mib)
err = cli_case("memory-limit=1", ["-i", bark], SYNTH, {"width": 64, "height": 64,
                                                        "memory-limit": 1}, (64, 64), "MiB")
need = op_warnings(err, SYNTH)
check(need and "limit of 1.0 MiB" in need[0], "memory-limit=1 refuses 64x64 and says the limit")
cli_case("memory-limit=64 lets 64x64 through", ["-i", bark], SYNTH,
         {"width": 64, "height": 64, "memory-limit": 64}, (64, 64))

note("-- pixel formats and non-finite pixels")
bw, bh, bark_px = tsops.load(bark, "R'G'B'A float")


def run_on_buffer(op, fmt, pixels, w, h, **props):
    data = struct.pack("%df" % len(pixels), *pixels)
    rgba = Gegl.Buffer.new("R'G'B'A float", 0, 0, w, h)
    rgba.set(Gegl.Rectangle.new(0, 0, w, h), "R'G'B'A float", data)
    buf = Gegl.Buffer.new(fmt, 0, 0, w, h)
    rgba.copy(Gegl.Rectangle.new(0, 0, w, h), Gegl.AbyssPolicy.NONE, buf,
              Gegl.Rectangle.new(0, 0, w, h))
    graph, _, node = tsops.op_on_buffer(buf, op, **props)
    return tsops.render(node)


formats = ["R'G'B'A u16", "RGBA float", "R'G'B'A half", "Y' u8", "Y'A u8", "Y u16", "YA float",
           "R'G'B' u8", "RGB float"]
for fmt in formats:
    for op, props in ((SYNTH, {"width": 40, "height": 32, "seed": 2}), (TILE, {"seed": 2})):
        w, h, px = run_on_buffer(op, fmt, bark_px, bw, bh, **props)
        expected = (40, 32) if op == SYNTH else (bw, bh)
        finite = all(math.isfinite(v) for v in px)
        tried["accepted"] += 1
        check((w, h) == expected and finite and max(tsops.alphas(px)) > 0.99,
              "%s: %s exemplar gives an opaque, finite %dx%d result" % (op, fmt, w, h))

for label, value, channel in [("NaN", float("nan"), 0), ("+Inf", float("inf"), 1),
                              ("-Inf", float("-inf"), 2), ("NaN alpha", float("nan"), 3),
                              ("alpha 1e30", 1e30, 3)]:
    px = list(bark_px)
    for i in range(0, bw * bh, 5):
        px[4 * i + channel] = value
    for op, props in ((SYNTH, {"width": 40, "height": 32, "seed": 2}), (TILE, {"seed": 2})):
        w, h, res = run_on_buffer(op, "RGBA float", px, bw, bh, **props)
        finite = all(math.isfinite(v) for v in res)
        alpha_ok = all(0.0 <= a <= 1.0 for a in tsops.alphas(res))
        tried["accepted"] += 1
        check(finite and alpha_ok, "%s: exemplar with %s pixels gives finite pixels, alpha in "
              "[0, 1]" % (op, label))

note("-- texsynth:heal: degenerate images, masks and properties")
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "heal"))
import healcases  # noqa: E402


def mask_file(name, w, h, fn):
    p = os.path.join(tmp, "mask-%s.png" % name)
    healcases.write_grey_png(p, w, h, fn)
    return ["aux=[", "gegl:load", "path=" + p, "]"]


def heal_case(label, image_ops, aux, props, size, word=None, tool=False):
    """Like cli_case for texsynth:heal; a refusal must give back the input."""
    run = tool_chain if tool else render_chain
    ran, w, h, px, err = run(image_ops + [HEAL] + ["%s=%s" % kv for kv in props.items()] + aux)
    warnings = op_warnings(err, HEAL)
    ok = ran and (w, h) == size and (bool(warnings) and word in warnings[0]
                                     if word else not warnings)
    if word and ok:
        ok = run(image_ops)[3] == px
    tried["refused" if word else "accepted"] += 1
    check(ok, "%s: %s %s%s -> %s, %dx%d, %s" % (
        HEAL, label, props, " (gegl tool)" if tool else "", "ran" if ran else "failed", w, h,
        warnings[0].split(HEAL + ": ")[1] if warnings else "no warning from the op"))


bark_ops = ["gegl:load", "path=" + bark]
centre = mask_file("centre", 82, 90, healcases.square(82, 90, 20))
heal_case("1x1 image", bark_ops + ["gegl:crop", "width=1", "height=1"],
          mask_file("one", 1, 1, lambda x, y: 255), {}, (1, 1), "nothing to fill", tool=True)
heal_case("2x5 image, half masked", bark_ops + ["gegl:crop", "width=2", "height=5"],
          mask_file("half", 2, 5, lambda x, y: 255 if y < 2 else 0), {}, (2, 5), "nothing to fill")
heal_case("transparent image, no mask", color("transparent", 16, 16), [], {}, (16, 16),
          "no fully opaque pixel")
heal_case("transparent image, a mask", color("transparent", 16, 16),
          mask_file("t", 16, 16, healcases.square(16, 16, 4)), {}, (16, 16), "nothing to fill")
heal_case("one-colour image", color("rgb(0.2,0.5,0.7)", 32, 32),
          mask_file("c", 32, 32, healcases.square(32, 32, 8)), {}, (32, 32))
heal_case("mask covering everything", bark_ops, mask_file("all", 82, 90, lambda x, y: 255), {},
          bark_size, "nothing to fill")
heal_case("unbounded white mask", bark_ops, ["aux=[", "gegl:color", "value=white", "]"], {},
          bark_size, "nothing to fill")
heal_case("empty mask", bark_ops, mask_file("none", 82, 90, lambda x, y: 0), {}, bark_size)
heal_case("mask larger than the image", bark_ops,
          mask_file("large", 300, 300, healcases.square(300, 300, 20, 40, 45)), {}, bark_size)
heal_case("mask 1x1 at the origin", bark_ops, mask_file("dot", 1, 1, lambda x, y: 255), {},
          bark_size)
heal_case("grey 49 % mask", bark_ops, mask_file("grey", 82, 90, lambda x, y: 125), {}, bark_size)
for extra, word in [({"context": 0}, None), ({"context": 16384}, None),
                    ({"context": 3}, "too small"), ({"context": 1}, "too small"),
                    ({"sample-from": "sides"}, None), ({"sample-from": "above-below"}, None),
                    ({"quality": 1}, None), ({"quality": 10}, None),
                    ({"patch-size": 31, "fine-patch-size": 31}, None),
                    ({"patch-size": 3, "fine-patch-size": 3}, None),
                    ({"seed": 0}, None), ({"seed": 2147483647}, None),
                    ({"memory-limit": 2147483647}, None)]:
    heal_case("limit", bark_ops, centre, dict({"seed": 3}, **extra), bark_size, word)
heal_case("memory limit below the need", bark_ops + ["gegl:scale-size", "x=2048", "y=2048"],
          mask_file("m", 2048, 2048, healcases.square(2048, 2048, 1500)), {"memory-limit": 1},
          (2048, 2048), "MiB")
heal_case("sides of a band across the whole width", bark_ops,
          mask_file("band", 82, 90, lambda x, y: 255 if 30 <= y < 60 else 0),
          {"sample-from": "sides"}, bark_size, "nothing to fill")
for label, value, channel in [("NaN", float("nan"), 0), ("+Inf", float("inf"), 1),
                              ("NaN alpha", float("nan"), 3), ("alpha 1e30", 1e30, 3)]:
    px = list(bark_px)
    # Scattered over every 5th pixel, or for alpha a 10x10 block (scattered
    # holes would leave no 7x7 patch of known pixels to copy).
    spots = (range(0, bw * bh, 5) if channel != 3 else
             [y * bw + x for y in range(30, 40) for x in range(30, 40)])
    for i in spots:
        px[4 * i + channel] = value
    # Without a mask: the pixels that are not fully opaque are the hole
    # (a NaN alpha counts as 0); kept pixels come back as they were, NaN
    # included, so only the filled ones must be finite.
    w, h, res = run_on_buffer(HEAL, "RGBA float", px, bw, bh, seed=2)
    filled = list(spots) if channel == 3 and value != value else []
    tried["accepted"] += 1
    check((w, h) == (bw, bh) and all(math.isfinite(res[4 * i + c]) for i in filled
                                     for c in range(4)),
          "%s: an image with %s pixels heals to its size, filled pixels finite" % (HEAL, label))

total = tried["accepted"] + tried["refused"]
note("\nops bad-input figures: %d distinct inputs tried, %d refused with a warning from the op, "
     "%d accepted, 0 crashes, 0 hangs" % (total, tried["refused"], tried["accepted"]))
tsops.finish()
