# Helpers for the texsynth GEGL operation tests.
# SPDX-License-Identifier: LGPL-3.0-or-later
#
# Run with the system Python (/usr/bin/python3): it has PyGObject and the
# Gegl typelib, which images are read and written with.

import atexit
import contextlib
import json
import os
import shutil
import struct
import subprocess
import sys
import tempfile
import warnings

OP = "texsynth:synthesize"
PREFIX = OP + ": "

_failures = []


def _own_babl_cache():
    """babl caches, per user, the conversions every process has used and
    sets all of them up at each start; one from 8 bits among them makes
    babl 0.1.98 time its lookup tables in every process (a 256 MiB buffer,
    about a second of CPU), which the tests, starting hundreds of GEGL
    processes, would pay in each. Each test script keeps a cache of its
    own in the build folder, so its processes still share their choice of
    paths; its child processes keep what it gives them."""
    build = os.environ.get("TEXSYNTH_BUILD_ROOT")
    if build and "TEXSYNTH_TEST_CACHE" not in os.environ:
        name = os.path.splitext(os.path.basename(sys.argv[0]))[0]
        os.environ["TEXSYNTH_TEST_CACHE"] = os.path.join(build, "test-caches", name)
        os.environ["XDG_CACHE_HOME"] = os.environ["TEXSYNTH_TEST_CACHE"]


_own_babl_cache()


def note(message):
    print(message, flush=True)


def check(condition, message):
    """Record a failed check without stopping, so one run shows them all."""
    if condition:
        note("ok    " + message)
    else:
        note("FAIL  " + message)
        _failures.append(message)
    return condition


def finish(skipped=""):
    """Exits 1 if a check failed; else 77 (SKIP) if `skipped` names checks
    this machine cannot make, saying why; else 0."""
    if _failures:
        note("\n%d check(s) failed:" % len(_failures))
        for message in _failures:
            note("  - " + message)
        sys.exit(1)
    if skipped:
        note("\nSKIP  every check made passed, but not made here: " + skipped)
        sys.exit(77)
    note("\nall checks passed")
    sys.exit(0)


def small():
    """True in small-size runs (TEXSYNTH_TEST_SMALL set and not "0";
    scripts/sanitize.sh sets it): the tests reach the same op code on less
    work and leave quality thresholds, and their measuring, to the native
    run."""
    return os.environ.get("TEXSYNTH_TEST_SMALL", "") not in ("", "0")


def die(message):
    note("ERROR: " + message)
    sys.exit(1)


def exemplars_dir():
    return os.environ.get("TEXSYNTH_EXEMPLARS") or os.path.join(
        os.environ.get("TEXSYNTH_SOURCE_ROOT", "."), "tests", "exemplars")


def exemplar(name):
    path = os.path.join(exemplars_dir(), name)
    if not os.path.isfile(path):
        die("exemplar %s not found (TEXSYNTH_EXEMPLARS=%s)" % (name, exemplars_dir()))
    return path


def workdir():
    """A scratch folder, removed at exit unless TEXSYNTH_KEEP_RESULTS is set."""
    path = tempfile.mkdtemp(prefix="texsynth-ops-")
    if not os.environ.get("TEXSYNTH_KEEP_RESULTS"):
        atexit.register(shutil.rmtree, path, True)
    else:
        note("results kept in " + path)
    return path


# --- where GEGL finds the ops -------------------------------------------------

def use_build_ops(build):
    """Points GEGL_PATH at BUILD's op modules and at GEGL's own folder, which
    GEGL_PATH otherwise replaces; call it before gegl() or a gegl tool reads
    the variable. Never at the build root: GEGL would load meson's
    compile_commands.json as an op and abort. Returns the value."""
    try:
        plugins = subprocess.run(["pkg-config", "--variable=pluginsdir", "gegl-0.4"],
                                 capture_output=True, text=True, check=True).stdout.strip()
    except (OSError, subprocess.CalledProcessError) as error:
        plugins, reason = "", str(error)
    else:
        reason = "it printed nothing"
    if not plugins:
        die("pkg-config cannot name GEGL's op folder (Debian packages pkg-config "
            "and libgegl-dev): %s" % reason)
    path = os.path.join(os.path.abspath(build), "operations") + os.pathsep + plugins
    os.environ["GEGL_PATH"] = path
    return path


# --- the gegl command-line tool ---------------------------------------------

def gegl_binary():
    path = os.environ.get("TEXSYNTH_GEGL") or shutil.which("gegl")
    if not path:
        die("the gegl command-line tool is not installed (Debian package 'gegl')")
    return path


def run_gegl(args, env=None, timeout=600):
    """Run gegl; return (returncode, stdout, stderr). A crash is a failure."""
    full_env = dict(os.environ)
    full_env.update(env or {})
    try:
        proc = subprocess.run([gegl_binary()] + list(args), env=full_env,
                              stdin=subprocess.DEVNULL, capture_output=True,
                              text=True, timeout=timeout)
    except subprocess.TimeoutExpired:
        die("gegl %s did not finish within %d s" % (" ".join(args), timeout))
    if proc.returncode < 0:
        die("gegl %s was killed by signal %d\n%s"
            % (" ".join(args), -proc.returncode, proc.stderr))
    return proc.returncode, proc.stdout, proc.stderr


@contextlib.contextmanager
def captured_stderr():
    """Within it, fd 2 goes to a file, where GLib and GEGL write warnings
    (the ops' own too), and Python warnings are recorded, which PyGObject
    makes of GObject's (a refused property value); afterwards the list it
    gives holds all of that as one text."""
    text = []
    with tempfile.TemporaryFile() as captured, warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        sys.stdout.flush()
        sys.stderr.flush()
        saved = os.dup(2)
        os.dup2(captured.fileno(), 2)
        try:
            yield text
        finally:
            os.dup2(saved, 2)
            os.close(saved)
            captured.seek(0)
            text.append(captured.read().decode(errors="replace")
                        + "".join("%s\n" % w.message for w in caught))


def chain_node(args):
    """The graph the gegl tool builds from its chain `args` (its arguments
    after '--', or with '-i PATH' first for an input), made in this process
    by the same parser (gegl_node_new_from_serialized); None if it cannot
    be parsed."""
    if args and args[0] == "-i":
        args = ["gegl:load", "path=" + args[1]] + list(args[2:])

    def quoted(arg):
        key, eq, value = arg.partition("=")
        if eq and any(c in value for c in ' "\\'):
            return '%s="%s"' % (key, value.replace("\\", "\\\\").replace('"', '\\"'))
        return arg
    return gegl().Node.new_from_serialized(" ".join(quoted(a) for a in args), os.getcwd())


def run_gegl_here(args):
    """run_gegl's twin in this process, for a test that runs many chains:
    every gegl run starts GEGL anew, about a second of CPU. `args` are the
    gegl tool's (-i IN, -o OUT, '--', the chain); the result is saved with
    gegl:save as the tool does. Returns (0, "", what went to stderr), or
    exit status 1 if the chain cannot be parsed."""
    args = list(args)
    split = args.index("--") if "--" in args else len(args)
    options, chain = args[:split], args[split + 1:]
    source = options[options.index("-i") + 1] if "-i" in options else None
    output = options[options.index("-o") + 1] if "-o" in options else None
    with captured_stderr() as err:
        graph = chain_node((["-i", source] if source else []) + chain)
        if graph is not None and output:
            save = graph.create_child("gegl:save")
            save.set_property("path", output)
            graph.connect_to("output", save, "input")
            save.process()
    return (0 if graph is not None else 1), "", err[0]


def require_op():
    """An unknown op is not an error for gegl: it prints a message and passes
    the image through, so every test must first make sure the op loads."""
    code, out, err = run_gegl(["--exists", OP])
    if code != 0:
        die("gegl cannot find %s (GEGL_PATH=%s)\n%s%s"
            % (OP, os.environ.get("GEGL_PATH", "<unset>"), out, err))


def synthesize_cli(src, dst, env=None, timeout=600, extra_ops=(), here=False, **props):
    """gegl -i src -o dst -- texsynth:synthesize key=value ... [extra ops];
    with `here`, on the same graph in this process (run_gegl_here)."""
    args = ["-i", src, "-o", dst, "--", OP]
    args += ["%s=%s" % (k.replace("_", "-"), _prop_text(v)) for k, v in props.items()]
    args += list(extra_ops)
    return run_gegl_here(args) if here else run_gegl(args, env=env, timeout=timeout)


def _prop_text(value):
    if isinstance(value, bool):
        return "true" if value else "false"
    return str(value)


def op_warnings(stderr):
    """The op's own warning lines (they carry the op name as a prefix)."""
    return [line for line in stderr.splitlines() if PREFIX in line]


# --- images through GObject introspection ------------------------------------

_gegl = None


def gegl():
    """The Gegl module, initialised once."""
    global _gegl
    if _gegl is None:
        try:
            import gi
            gi.require_version("Gegl", "0.4")
            from gi.repository import Gegl
        except (ImportError, ValueError) as error:
            die("PyGObject with the Gegl 0.4 typelib is needed (Debian packages "
                "python3-gi and gir1.2-gegl-0.4; run with /usr/bin/python3): %s" % error)
        Gegl.init(None)
        _gegl = Gegl
    return _gegl


def op_on_buffer(buffer, op, **props):
    """A new graph: gegl:buffer-source of `buffer` into `op`, whose
    properties are `props` (underscores in names become dashes).
    Returns (graph, source node, op node); keep the graph while the nodes
    are in use, since it owns them."""
    graph = gegl().Node()
    source = graph.create_child("gegl:buffer-source")
    source.set_property("buffer", buffer)
    node = graph.create_child(op)
    for key, value in props.items():
        node.set_property(key.replace("_", "-"), value)
    source.connect_to("output", node, "input")
    return graph, source, node


def render_bytes(node, fmt):
    """Render a node's whole bounding box: (width, height, bytes in `fmt`)."""
    Gegl = gegl()
    box = node.get_bounding_box()
    buf = Gegl.Buffer.new(fmt, box.x, box.y, box.width, box.height)
    graph = node.get_parent() or node
    sink = graph.create_child("gegl:write-buffer")
    sink.set_property("buffer", buf)
    node.connect_to("output", sink, "input")
    sink.process()
    return box.width, box.height, bytes(buf.get(box, 1.0, fmt, Gegl.AbyssPolicy.NONE))


def render(node, fmt="R'G'B'A float"):
    """Render a node's whole bounding box: (width, height, floats)."""
    w, h, data = render_bytes(node, fmt)
    return w, h, struct.unpack("%df" % (len(data) // 4), data)


def load_bytes(path, fmt):
    """Read an image file: (width, height, bytes in `fmt`)."""
    graph = gegl().Node()
    node = graph.create_child("gegl:load")
    node.set_property("path", path)
    return render_bytes(node, fmt)


def load(path, fmt="R'G'B'A float"):
    """Read an image file: (width, height, floats in `fmt`)."""
    w, h, data = load_bytes(path, fmt)
    return w, h, struct.unpack("%df" % (len(data) // 4), data)


def load_chain(graph, path, *ops):
    """In `graph`: gegl:load of `path`, then each (op, {property: value})
    in turn; the last node."""
    node = graph.create_child("gegl:load")
    node.set_property("path", path)
    for op, props in ops:
        nxt = graph.create_child(op)
        for key, value in props.items():
            nxt.set_property(key, value)
        node.connect_to("output", nxt, "input")
        node = nxt
    return node


def apply_layout(graph, source, layout):
    """gegl:map-absolute (nearest) of `source` through the source map
    `layout` (texsynth's source-map=true output), cropped to the layout."""
    Gegl = gegl()
    mapper = graph.create_child("gegl:map-absolute")
    mapper.set_property("sampler-type", Gegl.SamplerType.NEAREST)
    source.connect_to("output", mapper, "input")
    layout.connect_to("output", mapper, "aux")
    box = layout.get_bounding_box()
    crop = graph.create_child("gegl:crop")
    for key, value in (("x", box.x), ("y", box.y), ("width", box.width), ("height", box.height)):
        crop.set_property(key, float(value))
    mapper.connect_to("output", crop, "input")
    return crop


def save_node(node, path):
    """Render `node` into the PNG file `path`."""
    out = node.get_parent().create_child("gegl:png-save")
    out.set_property("path", path)
    node.connect_to("output", out, "input")
    out.process()


def save_buffer(buf, path, bitdepth=8):
    Gegl = gegl()
    graph = Gegl.Node()
    source = graph.create_child("gegl:buffer-source")
    source.set_property("buffer", buf)
    save = graph.create_child("gegl:png-save")
    save.set_property("path", path)
    save.set_property("bitdepth", bitdepth)
    source.connect_to("output", save, "input")
    save.process()


def convert(src, dst, fmt, bitdepth=8, alpha_fn=None, colour_fn=None):
    """Write `src` to PNG `dst` in babl format `fmt`; alpha_fn(x, y, w, h)
    gives an alpha to impose (for formats with alpha), colour_fn(x, y, w, h)
    an (R', G', B') to paint over the pixel, or None to keep it."""
    Gegl = gegl()
    w, h, px = load(src, "R'G'B'A float")
    if alpha_fn or colour_fn:
        px = list(px)
        for y in range(h):
            for x in range(w):
                if alpha_fn:
                    px[(y * w + x) * 4 + 3] = alpha_fn(x, y, w, h)
                colour = colour_fn(x, y, w, h) if colour_fn else None
                if colour:
                    px[(y * w + x) * 4:(y * w + x) * 4 + 3] = colour
    rgba = Gegl.Buffer.new("R'G'B'A float", 0, 0, w, h)
    rgba.set(Gegl.Rectangle.new(0, 0, w, h), "R'G'B'A float",
             struct.pack("%df" % len(px), *px))
    out = Gegl.Buffer.new(fmt, 0, 0, w, h)
    rgba.copy(Gegl.Rectangle.new(0, 0, w, h), Gegl.AbyssPolicy.NONE,
              out, Gegl.Rectangle.new(0, 0, w, h))
    save_buffer(out, dst, bitdepth)


# --- pixel statistics ---------------------------------------------------------

def max_abs_diff(a, b):
    return max(abs(x - y) for x, y in zip(a, b)) if len(a) == len(b) else float("inf")


def alphas(px):
    return px[3::4]


def wrap_seam_excess(w, h, px):
    """How the wrap-around edges compare with the image's own pixel
    boundaries: for columns and for rows, the mean colour step across the
    wrap-around edge over the 90th percentile of the mean steps across each
    inner boundary. At most about 1 when seamless; a structured texture has
    strong inner boundaries (mortar, cell edges) too, hence the percentile."""
    def step(x0, y0, x1, y1):
        i, j = (y0 * w + x0) * 4, (y1 * w + x1) * 4
        return sum(abs(px[i + c] - px[j + c]) for c in range(3))

    def excess(n, m, pair):
        means = [sum(step(*pair(k, (k + 1) % n, t)) for t in range(m)) / m for k in range(n)]
        inner = sorted(means[:-1])
        return means[-1] / max(inner[int(0.9 * (len(inner) - 1))], 1e-6)

    return (excess(w, h, lambda a, b, y: (a, y, b, y)),
            excess(h, w, lambda a, b, x: (x, a, x, b)))


# --- texsynth-measure -----------------------------------------------------------

def run_measure(measure_path, exemplar, result, tileable=False):
    """texsynth-measure --json [--tileable] EXEMPLAR RESULT as a dict of
    floats (NaN for null)."""
    return run_measures(measure_path, [(exemplar, result, tileable)])[0]


def run_measures(measure_path, pairs):
    """run_measure for each (exemplar, result, tileable) of `pairs`, in one
    texsynth-measure run (argument lists joined by '+': one GEGL start-up):
    a list of dicts."""
    cmd = [measure_path]
    for exemplar, result, tileable in pairs:
        cmd += (["+"] if len(cmd) > 1 else []) + ["--json"] + (["--tileable"] if tileable else [])
        cmd += [exemplar, result]
    proc = subprocess.run(cmd, capture_output=True, text=True)
    rows = [json.loads(line) for line in proc.stdout.splitlines()] if proc.returncode == 0 else []
    if proc.returncode != 0 or [r["result"] for r in rows] != [p[1] for p in pairs]:
        die("%s failed:\n%s%s" % (" ".join(cmd), proc.stdout, proc.stderr))
    return [{k: (float("nan") if v is None else float(v)) for k, v in values.items()
             if v is None or isinstance(v, (int, float))} for values in rows]
