#!/usr/bin/env python3
"""The operation reference, docs/operations.md, generated from the ops.

Every texsynth:* operation that GEGL loads is read through GEGL itself
(GObject introspection): its keys (name, title, categories, description...),
its pads, and every property's name, label, type, range, default, ui-meta
hints and description. The page is written in the C locale, so it is in
English and the same on every machine.

Usage:
  op-reference.py [BUILD]                  print the page
  op-reference.py --output PAGE [BUILD]    write the page to PAGE
  op-reference.py --check PAGE [BUILD]     exit 1, with a diff, if PAGE differs

BUILD is a meson build folder: the ops are loaded from BUILD/operations (and
GEGL's own folder). Without it, GEGL finds the ops as configured (GEGL_PATH
or its default folders, where installed ops live).

Run with the system Python (/usr/bin/python3): it has PyGObject and the
Gegl typelib (Debian packages python3-gi and gir1.2-gegl-0.4).
"""
# SPDX-License-Identifier: LGPL-3.0-or-later

import argparse
import difflib
import locale
import os
import re
import subprocess
import sys

PREFIX = "texsynth:"

# GEGL stores the op's class pointer under this key: not text, so left out.
UNPRINTABLE_KEYS = {"operation-class"}
# Shown as each section's first line, not in its table of keys.
INTRO_KEYS = ["title", "description"]
# The table of keys starts with these; the other keys follow sorted.
LEADING_KEYS = ["name", "categories"]

# Property spec kinds whose widget differs from their value type's.
SPEC_KINDS = {"GeglParamSeed": "seed", "GeglParamFilePath": "file path",
              "GeglParamUri": "URI"}

NO_VALUE = "\u2014"

PAGE_PATH = "docs/operations.md"
REGENERATE = "python3 scripts/op-reference.py BUILD > " + PAGE_PATH


def fail(message):
    sys.stderr.write("op-reference: %s\n" % message)
    sys.exit(2)


def force_c_locale():
    """The ops' strings are translatable: read them untranslated."""
    os.environ["LANGUAGE"] = "C"
    os.environ["LC_ALL"] = "C"
    locale.setlocale(locale.LC_MESSAGES, "C")


def use_build_ops(build):
    """GEGL_PATH replaces GEGL's own folder, so it lists both; never the
    build root itself, whose compile_commands.json GEGL would try to load."""
    ops_dir = os.path.join(os.path.abspath(build), "operations")
    if not os.path.isdir(ops_dir):
        fail("%s has no operations folder: is it a meson build folder?" % build)
    try:
        plugins = subprocess.run(["pkg-config", "--variable=pluginsdir", "gegl-0.4"],
                                 capture_output=True, text=True, check=True).stdout.strip()
    except (OSError, subprocess.CalledProcessError) as error:
        fail("pkg-config cannot name GEGL's op folder (Debian packages pkg-config "
             "and libgegl-dev): %s" % error)
    os.environ["GEGL_PATH"] = ops_dir + os.pathsep + plugins


def load_gegl():
    try:
        import gi
        gi.require_version("Gegl", "0.4")
        from gi.repository import Gegl, GObject
    except (ImportError, ValueError) as error:
        fail("PyGObject with the Gegl 0.4 typelib is needed (Debian packages "
             "python3-gi and gir1.2-gegl-0.4; run with /usr/bin/python3): %s" % error)
    Gegl.init(None)
    return Gegl, GObject


# --- reading the ops ------------------------------------------------------------

def number_text(value):
    """Integers as they are; floats in Python's shortest round-trip form, the
    same on every platform."""
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, float):
        return repr(value)
    return str(int(value))


def pad_order(name):
    return (0 if name == "input" else 1, len(name), name)


def read_keys(Gegl, op):
    keys = {}
    for key in Gegl.Operation.list_keys(op):
        if key in UNPRINTABLE_KEYS:
            continue
        keys[key] = Gegl.Operation.get_key(op, key) or ""
    return keys


def read_enum(spec):
    default = spec.default_value
    values = [(int(number), value.value_nick, value.value_name)
              for number, value in type(default).__enum_values__.items()]
    return default.value_nick, [(nick, label) for _, nick, label in sorted(values)]


def read_property(Gegl, GObject, op, spec):
    value_type = spec.value_type
    prop = {
        "name": spec.name,
        "label": spec.nick or "",
        "type": value_type.name,
        "description": spec.blurb or "",
        "hints": [],
        "range": None,
        "values": None,
        "kind": SPEC_KINDS.get(spec.__gtype__.name),
    }
    for key in sorted(Gegl.Operation.list_property_keys(op, spec.name)):
        prop["hints"].append((key, Gegl.Operation.get_property_key(op, spec.name, key) or ""))

    if value_type.is_a(GObject.TYPE_ENUM):
        prop["default"], prop["values"] = read_enum(spec)
    elif value_type.is_a(GObject.TYPE_BOOLEAN):
        prop["default"] = number_text(bool(spec.default_value))
    elif value_type.is_a(GObject.TYPE_STRING):
        prop["default"] = '"%s"' % (spec.default_value or "")
    elif hasattr(spec, "minimum") and hasattr(spec, "maximum"):
        prop["default"] = number_text(spec.default_value)
        prop["range"] = (number_text(spec.minimum), number_text(spec.maximum))
    else:
        fail("%s: property %s has a type this page cannot show (%s)"
             % (op, spec.name, value_type.name))
    return prop


def read_op(Gegl, GObject, op):
    graph = Gegl.Node()
    node = graph.create_child(op)
    return {
        "name": op,
        "keys": read_keys(Gegl, op),
        "inputs": sorted(node.list_input_pads(), key=pad_order),
        "outputs": sorted(node.list_output_pads(), key=pad_order),
        "properties": [read_property(Gegl, GObject, op, spec)
                       for spec in Gegl.Operation.list_properties(op)],
    }


def read_ops():
    Gegl, GObject = load_gegl()
    names = sorted(op for op in Gegl.list_operations() if op.startswith(PREFIX))
    if not names:
        fail("GEGL knows no %s* operation (GEGL_PATH=%s): build the ops, or give "
             "the build folder" % (PREFIX, os.environ.get("GEGL_PATH", "<unset>")))
    return [read_op(Gegl, GObject, op) for op in names]


# --- writing the page -----------------------------------------------------------

def text(value):
    """Markdown text that shows `value` literally, also inside a table cell."""
    value = " ".join(value.split())
    return re.sub(r"([\\`*_\[\]<>|#])", r"\\\1", value)


def code(value):
    if re.search(r"[`|\\\n]", value):
        fail("%r cannot be shown as code in a table cell" % value)
    return "`%s`" % value


def anchor(heading):
    """The anchor GitHub and GitLab give a heading."""
    slug = re.sub(r"[^\w\- ]", "", heading.lower())
    return slug.replace(" ", "-")


def row(cells):
    return "| " + " | ".join(cells) + " |"


def range_cell(prop):
    if prop["values"]:
        return "<br>".join("%s (%s)" % (code(nick), text(label))
                           for nick, label in prop["values"])
    if prop["range"]:
        return "%s to %s" % prop["range"]
    return NO_VALUE


def hints_cell(prop):
    if not prop["hints"]:
        return NO_VALUE
    return "<br>".join("%s: %s" % (code(key), text(value)) for key, value in prop["hints"])


def op_section(op):
    keys = op["keys"]
    lines = ["## " + op["name"], ""]
    lines.append("**%s.** %s" % (text(keys.get("title", "")), text(keys.get("description", ""))))
    lines.append("")
    inputs = ", ".join(code(pad) for pad in op["inputs"]) or "none"
    outputs = ", ".join(code(pad) for pad in op["outputs"]) or "none (a sink)"
    lines += ["Input pads: %s. Output pads: %s." % (inputs, outputs), ""]

    lines += [row(["Key", "Value"]), row(["---", "---"])]
    ordered = [k for k in LEADING_KEYS if k in keys]
    ordered += sorted(k for k in keys if k not in LEADING_KEYS + INTRO_KEYS)
    for key in ordered:
        lines.append(row([code(key), text(keys[key]) or NO_VALUE]))
    lines.append("")

    columns = ["Property", "Label", "Type", "Default", "Range", "UI hints", "Description"]
    lines += [row(columns), row(["---"] * len(columns))]
    for prop in op["properties"]:
        default = code(prop["default"])
        if prop["values"]:
            default += " (%s)" % text(dict(prop["values"]).get(prop["default"], ""))
        kind = " (%s)" % text(prop["kind"]) if prop["kind"] else ""
        lines.append(row([code(prop["name"]), text(prop["label"]), code(prop["type"]) + kind,
                          default, range_cell(prop), hints_cell(prop),
                          text(prop["description"]) or NO_VALUE]))
    lines.append("")
    return lines


def page(ops):
    lines = [
        "# Operation reference",
        "",
        "> Generated from the ops themselves by `scripts/op-reference.py`, which "
        "reads them through GEGL in the C locale; do not edit by hand. Regenerate "
        "with `meson compile -C BUILD op-reference` or `%s`. The test "
        "`ops-op-reference` fails when this page and the ops (or `gegl --info`) "
        "disagree." % REGENERATE,
        "",
        "Every texsynth GEGL operation, with its keys, pads and properties as "
        "GEGL reports them, the properties in the order the op declares them "
        "(the order of `gegl --info` and of generated dialogs). On the `gegl` "
        "command line a property is set as `name=value` after the op, an enum "
        "by the nick shown in code, e.g. "
        "`gegl -i in.png -o out.png -- texsynth:synthesize width=1024 seed=3`. "
        "Ranges are the values GEGL accepts. UI hints are the ops' ui-meta keys, "
        "read by front ends such as GIMP: `visible` 0 keeps a property out of "
        "generated dialogs, `unit` and `axis` mark a size in pixels along x or y, "
        "`role` advanced marks a setting most users can leave alone. A type may "
        "name the property's own widget: a seed, a file path.",
        "",
        row(["Operation", "Title", "Categories"]),
        row(["---"] * 3),
    ]
    for op in ops:
        keys = op["keys"]
        lines.append(row(["[%s](#%s)" % (code(op["name"]), anchor(op["name"])),
                          text(keys.get("title", "")) or NO_VALUE,
                          text(keys.get("categories", "")) or NO_VALUE]))
    lines.append("")
    for op in ops:
        lines += op_section(op)
    return "\n".join(lines).rstrip("\n") + "\n"


# --- main -----------------------------------------------------------------------

def check_page(path, generated):
    try:
        with open(path, encoding="utf-8") as handle:
            current = handle.read()
    except OSError as error:
        fail("cannot read %s: %s" % (path, error))
    if current == generated:
        print("%s matches the ops" % path)
        return 0
    sys.stdout.writelines(difflib.unified_diff(
        current.splitlines(True), generated.splitlines(True),
        fromfile=path, tofile="generated from the ops"))
    print("\n%s is stale: regenerate it with %s" % (path, REGENERATE))
    return 1


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    mode = parser.add_mutually_exclusive_group()
    mode.add_argument("--check", metavar="PAGE", help="compare PAGE with the ops")
    mode.add_argument("--output", metavar="PAGE", help="write the page to PAGE")
    parser.add_argument("build", nargs="?", metavar="BUILD",
                        help="meson build folder whose ops to read")
    args = parser.parse_args()

    force_c_locale()
    if args.build:
        use_build_ops(args.build)
    generated = page(read_ops())

    if args.check:
        return check_page(args.check, generated)
    if args.output:
        with open(args.output, "w", encoding="utf-8") as handle:
            handle.write(generated)
        return 0
    sys.stdout.buffer.write(generated.encode("utf-8"))
    return 0


if __name__ == "__main__":
    sys.exit(main())
