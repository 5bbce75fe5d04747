#!/usr/bin/env python3
# The source tree's architecture, checked: no circles among the C modules
# (a .c file and its .h, joined by what they include and by the functions
# of other modules they call), no call circles among the engine's object
# files (read with nm from the built library), and the parts of common/
# depend only on common/engine, never the other way or on each other.
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
# Comments, string and character literals, preprocessor lines (with their
# continuations): what no function name in code can stand in.
NOT_CODE = re.compile(r'/\*.*?\*/|//[^\n]*|"(?:\\.|[^"\\\n])*"|\'(?:\\.|[^\'\\\n])*\'|^[ \t]*#(?:\\\n|[^\n])*',
                      re.S | re.M)
WORD = re.compile(r'[A-Za-z_]\w*')
# The end of a function's declarator: its name, then its parameter list.
DECLARATOR = re.compile(r'([A-Za-z_]\w*)\s*\(([^()]|\([^()]*\))*\)\s*$')


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


def code_of(text):
    return NOT_CODE.sub(" ", text)


def defined_functions(code):
    """Names of the functions `code` defines with external linkage: at
    file scope, a declarator followed by a body, not static."""
    names, depth, start = set(), 0, 0
    for i, ch in enumerate(code):
        if ch == "{":
            if depth == 0:
                head = code[start:i]
                match = DECLARATOR.search(head)
                if match and "=" not in head:
                    before = head[:match.start()]
                    specifiers = before[before.rfind(")") + 1:]
                    if "static" not in WORD.findall(specifiers):
                        names.add(match.group(1))
            depth += 1
        elif ch == "}":
            depth = max(depth - 1, 0)
            if depth == 0:
                start = i + 1
        elif ch == ";" and depth == 0:
            start = i + 1
    return names


def closure(graph, start):
    """`start` and every node reachable from it."""
    seen, todo = {start}, [start]
    while todo:
        for child in graph.get(todo.pop(), ()):
            if child not in seen:
                seen.add(child)
                todo.append(child)
    return seen


def part(path):
    """common/<part>/file -> part; None outside the engine's parts."""
    pieces = path.split(os.sep)
    return pieces[1] if len(pieces) > 2 and pieces[0] == "common" else None


# Include graph, with a .c file and its .h joined into one node ("module"):
# a circle of modules is a circle of concerns even when no header includes
# itself.
includes = collections.defaultdict(set)
file_includes = collections.defaultdict(set)  # file -> the files it includes
files = sorted(sources())
if not any(f.startswith("common" + os.sep + "engine") for f in files):
    failures.append("no sources under common/engine (wrong SOURCE_ROOT %s?)" % root)
for f in files:
    text = open(os.path.join(root, f), encoding="utf-8").read()
    for name in INCLUDE.findall(text):
        target = resolve(f, name, ["common", f.split(os.sep)[0], "operations"])
        if target is None:
            continue  # GEGL's gegl-op.h and the op's own .c by name
        file_includes[f].add(target)
        module, target_module = os.path.splitext(f)[0], os.path.splitext(target)[0]
        if module != target_module:
            includes[module].add(target_module)
        if part(f) and part(target) and part(f) != part(target) and part(target) != "engine":
            failures.append("%s includes %s: parts of common/ may depend on common/engine only"
                            % (f, target))
        if part(f) == "engine" and part(target) and part(target) != "engine":
            failures.append("%s includes %s: the 2D engine must not depend on another part"
                            % (f, target))

# Calls between modules: a module uses another when its code names a
# function the other's .c defines, declared in a header both see. This
# finds the circle an include graph misses when a header declares another
# module's functions (a.h declaring b.c's: a.c calls b while b includes a.h).
code = {f: code_of(open(os.path.join(root, f), encoding="utf-8").read()) for f in files}
seen_headers = {f: {h for h in closure(file_includes, f) if h.endswith(".h")} for f in files}
declared_in = collections.defaultdict(set)  # function name -> headers naming it
definers = collections.defaultdict(set)     # function name -> .c files defining it
for f in files:
    if f.endswith(".c"):
        for name in defined_functions(code[f]):
            definers[name].add(f)
for f in files:
    if f.endswith(".h"):
        for name in set(WORD.findall(code[f])) & definers.keys():
            declared_in[name].add(f)
uses = 0
for f in (f for f in files if f.endswith(".c")):
    module = os.path.splitext(f)[0]
    for name in set(WORD.findall(code[f])) & definers.keys():
        for definer in definers[name]:
            target_module = os.path.splitext(definer)[0]
            if target_module != module and declared_in[name] & seen_headers[f] & seen_headers[definer]:
                includes[module].add(target_module)
                uses += 1
if len(definers) < 100:
    failures.append("only %d functions found defined in the sources" % len(definers))

cycle = find_cycle(includes)
if cycle:
    failures.append("module circle: " + " -> ".join(cycle))
print("module graph (includes and calls): %d modules, %d edges (%d from calls), %s" % (
    len(includes), sum(len(v) for v in includes.values()), uses,
    "a circle" if cycle else "no circle"))

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
