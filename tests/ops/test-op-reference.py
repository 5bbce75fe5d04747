# docs/operations.md against the ops: the page is what scripts/op-reference.py
# generates from the ops now (its --check), and, read back independently of
# the generator, it agrees with `gegl --info` for every texsynth op GEGL
# lists: keys, property names, types, descriptions and the defaults gegl
# prints. Both checks are also shown to catch a page whose default was
# edited, and the generator to fail when GEGL finds no texsynth op.
# SPDX-License-Identifier: LGPL-3.0-or-later
#
# Usage: test-op-reference.py [--page PAGE] [--build BUILD]
# (defaults: TEXSYNTH_SOURCE_ROOT/docs/operations.md, TEXSYNTH_BUILD_ROOT)

import argparse
import os
import re
import shutil
import subprocess
import sys
import tempfile

import tsops
from tsops import check, note

PREFIX = "texsynth:"
# The C locale keeps the ops' translatable strings in English.
C_LOCALE = {"LANGUAGE": "C", "LC_ALL": "C"}
# gegl --info prints the class pointer under this key: not text.
UNPRINTABLE_KEYS = {"operation-class"}
# The value types whose default gegl --info prints (others it leaves out).
GEGL_PRINTS_DEFAULT = {"gint", "gdouble", "gboolean", "gchararray"}

source_root = os.environ.get("TEXSYNTH_SOURCE_ROOT", ".")
parser = argparse.ArgumentParser()
parser.add_argument("--page", default=os.path.join(source_root, "docs", "operations.md"))
parser.add_argument("--build", default=os.environ.get("TEXSYNTH_BUILD_ROOT"))
args = parser.parse_args()
if not args.build:
    tsops.die("no build folder: give --build or set TEXSYNTH_BUILD_ROOT")
if not os.path.isfile(args.page):
    tsops.die("the operation reference %s is missing" % args.page)
tsops.use_build_ops(args.build)
generator = os.path.join(source_root, "scripts", "op-reference.py")
if not os.path.isfile(generator):
    tsops.die("the generator %s is missing" % generator)


def run(cmd, env=None):
    full_env = dict(os.environ)
    full_env.update(C_LOCALE)
    full_env.update(env or {})
    proc = subprocess.run(cmd, env=full_env, stdin=subprocess.DEVNULL,
                          capture_output=True, timeout=300)
    if proc.returncode < 0:
        tsops.die("%s was killed by signal %d" % (" ".join(cmd), -proc.returncode))
    # gegl --info prints the raw class pointer bytes: not always UTF-8.
    return (proc.returncode, proc.stdout.decode("utf-8", "replace"),
            proc.stderr.decode("utf-8", "replace"))


def run_check(page, env=None):
    return run([sys.executable, generator, "--check", page, args.build], env)


# --- the page, read back ------------------------------------------------------

def cells(line):
    """A table row's cells, still in Markdown; '\\|' does not split."""
    out, cell, i = [], "", 0
    body = line.strip()[1:-1]
    while i < len(body):
        if body[i] == "\\" and i + 1 < len(body):
            cell += body[i:i + 2]
            i += 2
            continue
        if body[i] == "|":
            out.append(cell.strip())
            cell = ""
        else:
            cell += body[i]
        i += 1
    out.append(cell.strip())
    return out


def plain(markdown):
    """The text a cell shows: escapes undone, no dash for 'nothing'."""
    value = re.sub(r"\\(.)", r"\1", markdown)
    return "" if value == "\u2014" else value


def first_code(markdown):
    found = re.match(r"`([^`]*)`", markdown)
    return found.group(1) if found else None


def tables(lines):
    """Each table in `lines` as (header cells, rows of cells)."""
    found, i = [], 0
    while i < len(lines):
        if lines[i].startswith("|") and i + 1 < len(lines) and lines[i + 1].startswith("| ---"):
            header, rows = cells(lines[i]), []
            i += 2
            while i < len(lines) and lines[i].startswith("|"):
                rows.append(cells(lines[i]))
                i += 1
            found.append((header, rows))
        else:
            i += 1
    return found


def read_page(text):
    """{op: {"keys": {key: text}, "props": [dict per row]}} from the page."""
    ops = {}
    sections = re.split(r"^## ", text, flags=re.M)[1:]
    for section in sections:
        lines = section.splitlines()
        name = lines[0].strip()
        intro = next((l for l in lines if l.startswith("**")), "")
        found = re.match(r"^\*\*(.*)\.\*\* (.*)$", intro)
        keys = {"title": plain(found.group(1)), "description": plain(found.group(2))} if found else {}
        props = []
        for header, rows in tables(lines):
            if header[:2] == ["Key", "Value"]:
                for row in rows:
                    keys[first_code(row[0])] = plain(row[1])
            elif header[0] == "Property":
                for row in rows:
                    record = dict(zip(header, row))
                    props.append({"name": first_code(record["Property"]),
                                  "type": first_code(record["Type"]),
                                  "default": first_code(record["Default"]),
                                  "description": plain(record["Description"])})
        ops[name] = {"keys": keys, "props": props}
    return ops


# --- gegl --info, read back ---------------------------------------------------

# A key or property line: its name, then the value or description.
ENTRY_LINE = re.compile(r"^([a-z][a-z0-9:_-]*)(?: +(.*))?$")


def read_gegl_info(text):
    """(keys, properties) of gegl --info's output; wrapped lines joined.
    The class pointer's bytes may hold a line break: the lines after it that
    are no entry are skipped, not taken for keys."""
    keys, props, entries, in_props, skipping = {}, [], [], False, False
    for line in text.split("\n"):
        stripped = line.strip()
        found = ENTRY_LINE.match(line)
        if stripped == "Properties:":
            in_props, skipping = True, False
        elif not stripped or (skipping and not found):
            continue
        elif line[:1].isspace():
            if entries:
                entries[-1][2] += " " + stripped
        elif found:
            entries.append([in_props, found.group(1), (found.group(2) or "").strip()])
            skipping = found.group(1) in UNPRINTABLE_KEYS
        else:
            entries.append([in_props, line, ""])
    for is_prop, name, rest in entries:
        if not is_prop:
            keys[name] = rest
            continue
        found = re.match(r"^\[(\S+)\]\s*(.*)$", rest)
        if not found:
            props.append({"name": name, "type": None, "default": None, "description": rest})
            continue
        blurb, default = found.group(2), None
        with_default = re.match(r"^(.*?)\s*\(default: (.*)\)$", blurb)
        if with_default:
            blurb, default = with_default.groups()
        props.append({"name": name, "type": found.group(1), "default": default,
                      "description": blurb})
    return keys, props


def same_default(value_type, shown, page_value):
    """gegl prints %d, %f, TRUE/FALSE and "text"; the page the values."""
    try:
        if value_type == "gboolean":
            return {"TRUE": "true", "FALSE": "false"}.get(shown) == page_value
        if value_type in ("gdouble", "gfloat"):
            return abs(float(shown) - float(page_value)) <= 5e-7 * max(1.0, abs(float(shown)))
        if value_type in ("gint", "guint", "gint64", "guint64"):
            return int(shown) == int(page_value)
    except (TypeError, ValueError):
        return False
    return shown == page_value


def words(value):
    return " ".join((value or "").split())


def compare_with_gegl(page_ops, gegl_ops, report):
    """Every disagreement between the page and gegl --info, via report()."""
    for op in sorted(set(page_ops) | set(gegl_ops)):
        if op not in page_ops or op not in gegl_ops:
            report("%s: on the page %s, in gegl --list-all %s"
                   % (op, op in page_ops, op in gegl_ops))
            continue
        (keys, props), page = gegl_ops[op], page_ops[op]
        for key in sorted(set(keys) | set(page["keys"])):
            if words(keys.get(key)) != words(page["keys"].get(key)):
                report("%s key %s: gegl --info %r, page %r"
                       % (op, key, keys.get(key), page["keys"].get(key)))
        shown_names = [p["name"] for p in props]
        page_names = [p["name"] for p in page["props"]]
        if shown_names != page_names:
            report("%s properties: gegl --info %s, page %s" % (op, shown_names, page_names))
        on_page = {p["name"]: p for p in page["props"]}
        for prop in props:
            mine = on_page.get(prop["name"])
            if mine is None:
                continue
            where = "%s %s" % (op, prop["name"])
            if prop["type"] != mine["type"]:
                report("%s type: gegl --info %s, page %s" % (where, prop["type"], mine["type"]))
            if words(prop["description"]) != words(mine["description"]):
                report("%s description: gegl --info %r, page %r"
                       % (where, prop["description"], mine["description"]))
            if prop["default"] is None:
                if prop["type"] in GEGL_PRINTS_DEFAULT:
                    report("%s: gegl --info printed no default for a %s" % (where, prop["type"]))
            elif not same_default(prop["type"], prop["default"], mine["default"]):
                report("%s default: gegl --info %s, page %s"
                       % (where, prop["default"], mine["default"]))


def gegl_ops():
    code, out, err = run([tsops.gegl_binary(), "--list-all"])
    if code != 0:
        tsops.die("gegl --list-all failed (exit %d):\n%s" % (code, err))
    names = sorted(line.strip() for line in out.splitlines() if line.startswith(PREFIX))
    found = {}
    for name in names:
        code, out, err = run([tsops.gegl_binary(), "--info", name])
        if code != 0:
            tsops.die("gegl --info %s failed (exit %d):\n%s" % (name, code, err))
        keys, props = read_gegl_info(out)
        found[name] = ({k: v for k, v in keys.items() if k not in UNPRINTABLE_KEYS}, props)
    return found


# --- the checks ---------------------------------------------------------------

note("-- the page is what the generator makes of the ops")
code, out, err = run_check(args.page)
check(code == 0, "op-reference.py --check %s passes (exit %d)%s"
      % (args.page, code, "" if code == 0 else "\n" + out + err))

note("-- the page agrees with gegl --info")
with open(args.page, encoding="utf-8") as handle:
    page_text = handle.read()
page_ops = read_page(page_text)
shown = gegl_ops()
check(len(shown) > 0, "gegl --list-all lists texsynth ops: %s" % sorted(shown))
check(sorted(page_ops) == sorted(shown), "the page has one section per op gegl lists: %s"
      % sorted(page_ops))
for op in sorted(shown):
    check(len(shown[op][1]) > 0 and len(page_ops.get(op, {}).get("props", [])) == len(shown[op][1]),
          "%s: %d properties in gegl --info, %d on the page"
          % (op, len(shown[op][1]), len(page_ops.get(op, {}).get("props", []))))
problems = []
compare_with_gegl(page_ops, shown, problems.append)
for problem in problems:
    note("      " + problem)
check(not problems, "every key, property name, type, description and printed default "
      "matches gegl --info")

note("-- a stale page is caught")
stale = None
for op in sorted(page_ops):
    for prop in page_ops[op]["props"]:
        if prop["type"] == "gint" and prop["default"] is not None:
            stale = (op, prop["name"], prop["default"])
            break
    if stale:
        break
check(stale is not None, "the page has a gint property to edit")
if stale:
    op, name, default = stale
    edited_default = str(int(default) + 1)
    row = re.compile(r"^(\| `%s` \|(?:[^|]*\|){2} )`%s`" % (re.escape(name), re.escape(default)),
                     re.M)
    section_at = page_text.index("## " + op + "\n")
    found = row.search(page_text, section_at)
    check(found is not None, "the %s row of %s is found on the page" % (name, op))
    if found:
        edited = (page_text[:found.start()] + found.group(1) + "`%s`" % edited_default
                  + page_text[found.end():])
        scratch = tempfile.mkdtemp(prefix="texsynth-op-reference-")
        try:
            copy = os.path.join(scratch, "operations.md")
            with open(copy, "w", encoding="utf-8") as handle:
                handle.write(edited)
            code, out, _ = run_check(copy)
            removed = "-%s`%s`" % (found.group(1), edited_default)
            check(code == 1 and ("+" + found.group(0)) in out and removed in out,
                  "--check fails with a diff on a copy whose %s %s default is %s (exit %d)"
                  % (op, name, edited_default, code))
        finally:
            shutil.rmtree(scratch, True)
        problems = []
        compare_with_gegl(read_page(edited), shown, problems.append)
        check(any("%s %s default" % (op, name) in p for p in problems),
              "the gegl --info comparison reports that default: %s" % problems)

note("-- no texsynth op is an error, not an empty page")
empty = tempfile.mkdtemp(prefix="texsynth-no-ops-")
try:
    code, out, err = run([sys.executable, generator], env={"GEGL_PATH": empty})
finally:
    shutil.rmtree(empty, True)
check(code != 0 and "no texsynth:" in err,
      "op-reference.py fails when GEGL_PATH holds no op: exit %d, %s" % (code, err.strip()))

tsops.finish()
