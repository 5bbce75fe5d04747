#!/usr/bin/python3
# What the GIMP dialogs' previews cost against the runs they preview: in
# one process (no gegl start-up), the wall time of each preview's graph as
# gimp-plugin/plugin-preview.c builds it and of the procedure's run.
# First table: texsynth:synthesize at the render preview's size (at most
# PREVIEW px a side) and at the result's size, and texsynth:volume-slice
# (its volume synthesised first) for the solid preview's cube and the
# result's. Second table, the procedures that work on a whole layer: a
# WIDTH x HEIGHT layer (the exemplar scaled up) made seamless, healed
# where a rectangle of a quarter of its width and height in the middle is
# transparent, uncropped by 20 % (the dialogs' default), painted by numbers with the exemplar as its own guide and
# restyled with the exemplar, against the previews of the layer scaled
# down (seamless: to half the side, then repeated 2x2) or of its middle
# PREVIEW x PREVIEW (the guided ones). Each run has its own seed, so the
# volume cache never answers; medians of RUNS.
# Usage: benchmarks/preview-time.py [-b BUILD] [-r RUNS] [-W WIDTH] [-H HEIGHT]
#                                   [-s SIZE] [--layers-only] [EXEMPLAR.png...]
# SPDX-License-Identifier: LGPL-3.0-or-later
import argparse
import os
import statistics
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
# gimp-plugin/plugin-preview.h: TS_PREVIEW_SIDE, TS_PREVIEW_SOLID_SIZE,
# TS_PREVIEW_TILE_SIDE; the heal dialogs' default uncrop border (percent).
PREVIEW_SIDE, PREVIEW_SOLID, PREVIEW_TILE, UNCROP_PERCENT = 160, 48, 80, 20
parser = argparse.ArgumentParser()
parser.add_argument("-b", "--build", default=os.path.join(ROOT, "build"))
parser.add_argument("-r", "--runs", type=int, default=3)
parser.add_argument("-W", "--width", type=int, default=1024)
parser.add_argument("-H", "--height", type=int, default=768)
parser.add_argument("-s", "--size", type=int, default=128, help="the solid's edge")
parser.add_argument("--layers-only", action="store_true",
                    help="only the second table, the procedures on a whole layer")
parser.add_argument("exemplars", nargs="*", default=[os.path.join(ROOT, "examples", "bark.png")])
args = parser.parse_args()
sys.path.insert(0, os.path.join(ROOT, "tests", "ops"))
import tsops  # noqa: E402
tsops.use_build_ops(args.build)
Gegl = tsops.gegl()


def timed(path, op, seed, **props):
    """Seconds to render `op` on the exemplar at `path` into a buffer."""
    graph = Gegl.Node()
    load = graph.create_child("gegl:load")
    load.set_property("path", path)
    node = graph.create_child(op)
    node.set_property("seed", seed)
    for key, value in props.items():
        node.set_property(key.replace("_", "-"), value)
    load.link(node)
    load.get_bounding_box()  # the file read before the clock starts
    start = time.perf_counter()
    node.blit_buffer(None, node.get_bounding_box(), 0, Gegl.AbyssPolicy.NONE)
    return time.perf_counter() - start


def median(op, path, **props):
    return statistics.median(timed(path, op, seed, **props) for seed in range(1, args.runs + 1))


def first_table():
    pw, ph = min(args.width, PREVIEW_SIDE), min(args.height, PREVIEW_SIDE)
    ps = min(args.size, PREVIEW_SOLID)
    print("| exemplar | render preview %dx%d (s) | render %dx%d (s) | solid preview %d³ (s) | "
          "solid %d³ (s) |" % (pw, ph, args.width, args.height, ps, args.size))
    print("|---|---|---|---|---|")
    for path in args.exemplars:
        row = [median("texsynth:synthesize", path, width=pw, height=ph),
               median("texsynth:synthesize", path, width=args.width, height=args.height),
               median("texsynth:volume-slice", path, size=ps, index=ps // 2),
               median("texsynth:volume-slice", path, size=args.size, index=args.size // 2)]
        print("| %s | %s |" % (os.path.basename(path), " | ".join("%.2f" % t for t in row)),
              flush=True)
    print()


if not args.layers_only:
    first_table()

# --- the procedures on a whole layer ---------------------------------------

def child(graph, op, **props):
    node = graph.create_child(op)
    for key, value in props.items():
        node.set_property(key.replace("_", "-"), value)
    return node


def chain(*nodes):
    for a, b in zip(nodes, nodes[1:]):
        a.link(b)
    return nodes[-1]


def cpu_seconds():
    times = os.times()
    return times.user + times.system


def run_graph(build, seed):
    """Wall and CPU seconds (all threads) to render the node that
    build(graph, seed) returns; CPU time depends far less on other work."""
    graph = Gegl.Node()
    node = build(graph, seed)
    node.get_bounding_box()
    start, cpu = time.perf_counter(), cpu_seconds()
    node.blit_buffer(None, node.get_bounding_box(), 0, Gegl.AbyssPolicy.NONE)
    return time.perf_counter() - start, cpu_seconds() - cpu


def median_graph(build):
    runs = [run_graph(build, seed) for seed in range(1, args.runs + 1)]
    return statistics.median(r[0] for r in runs), statistics.median(r[1] for r in runs)


def fit(width, height, side):
    """plugin-preview.c's scale to fit `side`, and the whole pixels it gives."""
    ratio = min(1.0, side / max(width, height))
    return ratio, max(1, int(width * ratio + 1e-6)), max(1, int(height * ratio + 1e-6))


def scaled(graph, node, ratio, width, height):
    return chain(node, child(graph, "gegl:scale-ratio", x=ratio, y=ratio),
                 child(graph, "gegl:crop", x=0.0, y=0.0, width=float(width), height=float(height)))


def bordered(graph, node, width, height, bx, by, seed):
    """Uncrop: `node` (width x height) with a border healed around it."""
    total_w, total_h = width + 2 * bx, height + 2 * by
    mask = chain(child(graph, "gegl:color", value=Gegl.Color.new("white")),
                 child(graph, "gegl:crop", x=0.0, y=0.0, width=float(total_w),
                       height=float(total_h)))
    over = child(graph, "gegl:over")
    mask.link(over)
    child(graph, "gegl:rectangle", x=float(bx), y=float(by), width=float(width),
          height=float(height), color=Gegl.Color.new("black")).connect_to("output", over, "aux")
    heal = child(graph, "texsynth:heal", seed=seed)
    chain(node, child(graph, "gegl:translate", x=float(bx), y=float(by)),
          child(graph, "gegl:crop", x=0.0, y=0.0, width=float(total_w), height=float(total_h)),
          heal)
    over.connect_to("output", heal, "aux")
    return heal


def layer_rows(exemplar, layer_path):
    W, H = args.width, args.height
    def load(graph):
        return child(graph, "gegl:load", path=layer_path)

    # The layer with a rectangle of a quarter of its sides cleared in the
    # middle.
    def holed(graph):
        hole = child(graph, "gegl:rectangle", x=W * 3 / 8, y=H * 3 / 8, width=W / 4,
                     height=H / 4, color=Gegl.Color.new("black"))
        out = child(graph, "svg:dst-out")
        load(graph).link(out)
        hole.connect_to("output", out, "aux")
        return out

    def guided(graph, seed, target, guide):
        op = child(graph, "texsynth:guided", seed=seed)
        target.link(op)
        child(graph, "gegl:load", path=exemplar).connect_to("output", op, "aux")
        if guide:
            child(graph, "gegl:load", path=exemplar).connect_to("output", op, "aux2")
        return op

    def middle(graph):
        w, h = min(W, PREVIEW_SIDE), min(H, PREVIEW_SIDE)
        x, y = (W - w) // 2, (H - h) // 2
        return chain(load(graph),
                     child(graph, "gegl:crop", x=float(x), y=float(y), width=float(w),
                           height=float(h)),
                     child(graph, "gegl:translate", x=float(-x), y=float(-y)))

    tile_ratio, tw, th = fit(W, H, PREVIEW_TILE)
    ratio, pw, ph = fit(W, H, PREVIEW_SIDE)
    bx, by = max(1, W * UNCROP_PERCENT // 100), max(1, H * UNCROP_PERCENT // 100)
    u_ratio, uw, uh = fit(W + 2 * bx, H + 2 * by, PREVIEW_SIDE)
    uw, uh = max(1, int(W * u_ratio + 1e-6)), max(1, int(H * u_ratio + 1e-6))
    ubx, uby = max(1, int(bx * u_ratio + 1e-6)), max(1, int(by * u_ratio + 1e-6))
    rows = [
        ("Make Seamless", "%dx%d, 2x2" % (tw, th),
         lambda g, s: chain(scaled(g, load(g), tile_ratio, tw, th),
                            child(g, "texsynth:tileable", seed=s), child(g, "gegl:tile"),
                            child(g, "gegl:crop", x=0.0, y=0.0, width=2.0 * tw,
                                  height=2.0 * th)),
         lambda g, s: chain(load(g), child(g, "texsynth:tileable", seed=s))),
        ("Heal Transparency", "%dx%d" % (pw, ph),
         lambda g, s: chain(scaled(g, holed(g), ratio, pw, ph), child(g, "texsynth:heal", seed=s)),
         lambda g, s: chain(holed(g), child(g, "texsynth:heal", seed=s))),
        ("Uncrop %d %%" % UNCROP_PERCENT, "%dx%d" % (uw + 2 * ubx, uh + 2 * uby),
         lambda g, s: bordered(g, scaled(g, load(g), u_ratio, uw, uh), uw, uh, ubx, uby, s),
         lambda g, s: bordered(g, load(g), W, H, bx, by, s)),
        ("Texture by Numbers", "%dx%d" % (min(W, PREVIEW_SIDE), min(H, PREVIEW_SIDE)),
         lambda g, s: guided(g, s, middle(g), True),
         lambda g, s: guided(g, s, load(g), True)),
        ("Style Transfer", "%dx%d" % (min(W, PREVIEW_SIDE), min(H, PREVIEW_SIDE)),
         lambda g, s: guided(g, s, middle(g), False),
         lambda g, s: guided(g, s, load(g), False)),
    ]
    for name, size, preview, run in rows:
        yield name, size, median_graph(preview), median_graph(run)


print("| exemplar | dialog | preview | preview (s) | preview CPU (s) | run on a %dx%d layer (s) "
      "| run CPU (s) |" % (args.width, args.height))
print("|---|---|---|---|---|---|---|")
with tempfile.TemporaryDirectory() as work:
    for path in args.exemplars:
        layer = os.path.join(work, "layer.png")
        graph = Gegl.Node()
        chain(child(graph, "gegl:load", path=path),
              child(graph, "gegl:scale-size", x=float(args.width), y=float(args.height)),
              child(graph, "gegl:crop", x=0.0, y=0.0, width=float(args.width),
                    height=float(args.height)),
              child(graph, "gegl:png-save", path=layer)).process()
        for name, size, preview, run in layer_rows(path, layer):
            print("| %s | %s | %s | %.2f | %.2f | %.2f | %.2f |"
                  % ((os.path.basename(path), name, size) + preview + run), flush=True)
