#!/usr/bin/env python3
# The source tree's architecture, checked: no include circles among the C
# files, no call circles among the engine's object files (read with nm
# from the built library), and the parts of common/ depend only on
# common/engine, never the other way or on each other.
# Usage: test-source-graph.py SOURCE_ROOT ENGINE_ARCHIVE
# SPDX-License-Identifier: LGPL-3.0-or-later
import collections
import os
import re
import subprocess
import sys

root, archive = sys.argv[1], sys.argv[2]
failures = []
INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"', re.M)


def sources():
    for top in ("common", "operations", "tools", "gimp-plugin"):
        for folder, _, names in os.walk(os.path.join(root, top)):
            for name in names:
                if name.endswith((".c", ".h")):
                    yield os.path.relpath(os.path.join(folder, name), root)


def resolve(including, name, search):
    """The file a quoted #include names: beside the including file first,
    then on the include path (common/, the including file's top folder)."""
    for folder in [os.path.dirname(including)] + search:
        candidate = os.path.normpath(os.path.join(folder, name))
        if os.path.isfile(os.path.join(root, candidate)):
            return candidate
    return None


def find_cycle(graph):
    """One cycle of `graph` as a list of nodes, or None (iterative DFS)."""
    state = {}
    for start in sorted(graph):
        if start in state:
            continue
        stack = [(start, iter(sorted(graph[start])))]
        path = [start]
        state[start] = "open"
        while stack:
            node, children = stack[-1]
            child = next(children, None)
            if child is None:
                stack.pop()
                path.pop()
                state[node] = "done"
            elif state.get(child) == "open":
                return path[path.index(child):] + [child]
            elif child not in state:
                state[child] = "open"
                path.append(child)
                stack.append((child, iter(sorted(graph.get(child, ())))))
    return None


def part(path):
    """common/<part>/file -> part; None outside the engine's parts."""
    pieces = path.split(os.sep)
    return pieces[1] if len(pieces) > 2 and pieces[0] == "common" else None


# Include graph, with a .c file and its .h joined into one node ("module"):
# a circle of modules is a circle of concerns even when no header includes
# itself.
includes = collections.defaultdict(set)
files = sorted(sources())
if not any(f.startswith("common" + os.sep + "engine") for f in files):
    failures.append("no sources under common/engine (wrong SOURCE_ROOT %s?)" % root)
for f in files:
    text = open(os.path.join(root, f), encoding="utf-8").read()
    for name in INCLUDE.findall(text):
        target = resolve(f, name, ["common", f.split(os.sep)[0], "operations"])
        if target is None:
            continue  # GEGL's gegl-op.h and the op's own .c by name
        module, target_module = os.path.splitext(f)[0], os.path.splitext(target)[0]
        if module != target_module:
            includes[module].add(target_module)
        if part(f) and part(target) and part(f) != part(target) and part(target) != "engine":
            failures.append("%s includes %s: parts of common/ may depend on common/engine only"
                            % (f, target))
        if part(f) == "engine" and part(target) and part(target) != "engine":
            failures.append("%s includes %s: the 2D engine must not depend on another part"
                            % (f, target))
cycle = find_cycle(includes)
if cycle:
    failures.append("include circle: " + " -> ".join(cycle))
print("include graph: %d modules, %d edges, %s" % (
    len(includes), sum(len(v) for v in includes.values()), "a circle" if cycle else "no circle"))

# Call graph of the engine's objects: who needs whose symbols.
nm = subprocess.run(["nm", "-A", archive], capture_output=True, text=True)
if nm.returncode != 0:
    failures.append("nm %s failed: %s" % (archive, nm.stderr.strip()))
defined, needed = {}, collections.defaultdict(set)
for line in nm.stdout.splitlines():
    fields = line.split()
    if len(fields) < 2:
        continue
    obj = fields[0].rsplit(":", 2)[-2] if fields[0].count(":") >= 2 else fields[0]
    kind, symbol = fields[-2], fields[-1]
    if kind in "TDBR":
        defined[symbol] = obj
    elif kind == "U":
        needed[obj].add(symbol)
calls = collections.defaultdict(set)
for obj, symbols in needed.items():
    for symbol in symbols:
        if symbol in defined and defined[symbol] != obj:
            calls[obj].add(defined[symbol])
if len(defined) < 50:
    failures.append("only %d symbols defined in %s" % (len(defined), archive))
cycle = find_cycle(calls)
if cycle:
    failures.append("call circle: " + " -> ".join(cycle))
print("engine call graph: %d objects, %d edges, %s" % (
    len(calls), sum(len(v) for v in calls.values()), "a circle" if cycle else "no circle"))

# Every file under common/ belongs to one part's folder, but the public API.
for name in sorted(os.listdir(os.path.join(root, "common"))):
    if os.path.isfile(os.path.join(root, "common", name)) and name not in ("texsynth.h", "meson.build"):
        failures.append("common/%s lies outside the parts' folders" % name)

for f in failures:
    print("FAIL:", f)
sys.exit(1 if failures else 0)
