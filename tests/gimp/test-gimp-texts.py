# What the plug-in's procedures tell their users, read back from real,
# headless GIMP's procedure database: every procedure has a blurb, every
# argument a description (and in GIMP 3 a label, the dialogs' text), and
# every number argument that may be 0 says what 0 does. In GIMP 3 the
# solid texture's file is a file argument (GIMP's file chooser in the
# dialog) that a Python caller passes as a Gio.File.
# SPDX-License-Identifier: GPL-3.0-or-later
#
# Usage: test-gimp-texts.py --gimp GIMP-CONSOLE --plugin PLUG-IN

import argparse
import os
import re
import subprocess
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "ops"))
import tsops  # noqa: E402
import gimpbatch  # noqa: E402

parser = argparse.ArgumentParser()
parser.add_argument("--gimp", required=True, help="gimp-console-2.10 or gimp-console-3.0")
parser.add_argument("--plugin", required=True, help="the built plug-in executable")
args = parser.parse_args()

PROCEDURES = {
    "plug-in-texsynth-render": ["width", "height", "tileable", "quality", "seed"],
    "plug-in-texsynth-render-layers": ["width", "height", "tileable", "quality", "seed"],
    "plug-in-texsynth-tileable": ["quality", "seed"],
    "plug-in-texsynth-solid": ["size", "path", "quality", "seed", "cell-structure"],
    "plug-in-texsynth-heal-selection": ["context", "sample-from", "quality", "seed"],
    "plug-in-texsynth-heal-transparency": ["context", "sample-from", "quality", "seed"],
    "plug-in-texsynth-uncrop": ["percent", "quality", "seed"],
    "plug-in-texsynth-texture-by-numbers": ["exemplar", "exemplar-guide", "guide-weight",
                                            "blend-edges", "tileable", "quality", "seed"],
    "plug-in-texsynth-style-transfer": ["style", "guide-weight", "quality", "seed"],
}
# GIMP 2.10's database has no ranges: the number arguments that may be 0.
MAY_BE_ZERO = {"seed", "context", "sample-from", "cell-structure", "guide-weight"}

work = tsops.workdir()
gimp = gimpbatch.Gimp(args.gimp, args.plugin, work)
volume = os.path.join(work, "python.vol")
bark = os.path.join(os.environ.get("TEXSYNTH_SOURCE_ROOT", "."), "examples", "bark.png")

# Each line: TSBLURB proc | blurb, or TSARG proc | name | type | min | nick | blurb.
if gimp.version == 2:
    names = " ".join('"%s"' % p for p in PROCEDURES)
    snippet = """
(for-each
  (lambda (p)
    (let* ((info (gimp-procedural-db-proc-info p)) (n (list-ref info 6)) (i 0))
      (gimp-message (string-append "TSBLURB " p " | " (car info)))
      (while (< i n)
        (let ((arg (gimp-procedural-db-proc-arg p i)))
          (gimp-message (string-append "TSARG " p " | " (cadr arg) " | " (number->string (car arg))
                                       " | - | - | " (caddr arg))))
        (set! i (+ i 1)))))
  (list %s))""" % names
    command = gimp.command([snippet])
else:
    # Python: GIMP 3's argument specs (labels, ranges, value types), and a
    # call with the file argument as a Gio.File.
    snippet = """
import gi
gi.require_version("Gimp", "3.0")
from gi.repository import Gimp, Gio, GObject
pdb = Gimp.get_pdb()
for name in %r:
    proc = pdb.lookup_procedure(name)
    print("TSBLURB %%s | %%s" %% (name, proc.get_blurb()))
    for spec in proc.get_arguments():
        low = getattr(spec, "minimum", "-")
        print("TSARG %%s | %%s | %%s | %%s | %%s | %%s" %% (name, spec.get_name(), spec.value_type.name,
              low, spec.get_nick(), spec.get_blurb()))
        if spec.value_type.name == "GFile":
            print("TSFILEACTION %%s | %%s" %% (spec.get_name(), Gimp.param_spec_file_get_action(spec).value_nick))
image = Gimp.file_load(Gimp.RunMode.NONINTERACTIVE, Gio.File.new_for_path(%r))
proc = pdb.lookup_procedure("plug-in-texsynth-solid")
config = proc.create_config()
config.set_property("run-mode", Gimp.RunMode.NONINTERACTIVE)
config.set_property("image", image)
config.set_core_object_array("drawables", [image.get_layers()[0]])
for key, value in (("size", 16), ("path", Gio.File.new_for_path(%r)), ("quality", 1), ("seed", 3),
                   ("cell-structure", 0)):
    config.set_property(key, value)
result = proc.run(config)
print("TSSOLID %%s" %% result.index(0).value_nick)
""" % (list(PROCEDURES), bark, volume)
    command = [args.gimp, "-i", "-d", "-f", "--batch-interpreter=python-fu-eval", "--quit",
               "-b", snippet]

try:
    proc = subprocess.run(command, env=gimp.env(), stdin=subprocess.DEVNULL, stdout=subprocess.PIPE,
                          stderr=subprocess.STDOUT, text=True, timeout=600)
except subprocess.TimeoutExpired:
    tsops.die("GIMP did not finish within 600 s")
tsops.note("---- GIMP output ----\n%s---- end of GIMP output ----" % proc.stdout)
tsops.check(proc.returncode == 0, "GIMP exits normally (exit code %d)" % proc.returncode)

blurbs, arguments = {}, {}
for line in proc.stdout.splitlines():
    found = re.search(r"TSBLURB (\S+) \| (.*)$", line)
    if found:
        blurbs[found.group(1)] = found.group(2).strip()
    found = re.search(r"TSARG (\S+) \| (\S+) \| (\S+) \| (\S+) \| (.*?) \| (.*)$", line)
    if found:
        procedure, name, kind, low, nick, blurb = found.groups()
        arguments.setdefault(procedure, {})[name] = (kind, low, nick.strip(), blurb.strip())

for procedure, names in PROCEDURES.items():
    tsops.check(len(blurbs.get(procedure, "")) >= 20, "%s: a blurb (%r)"
                % (procedure, blurbs.get(procedure)))
    found = arguments.get(procedure, {})
    for name in names:
        if not tsops.check(name in found, "%s: has the argument %s" % (procedure, name)):
            continue
        kind, low, nick, blurb = found[name]
        tsops.check(len(blurb) >= 10, "%s %s: a description (%r)" % (procedure, name, blurb))
        if gimp.version >= 3:
            tsops.check(nick and nick != name, "%s %s: a label for the dialog (%r)"
                        % (procedure, name, nick))
            zero_allowed = kind in ("gint", "gdouble") and re.fullmatch(r"0(\.0*)?", low)
        else:
            zero_allowed = name in MAY_BE_ZERO
        if zero_allowed:
            tsops.check(re.search(r"\b0\b", nick + " " + blurb),
                        "%s %s: may be 0, and its texts say what 0 does (%r, %r)"
                        % (procedure, name, nick, blurb))
        if name == "context" and gimp.version >= 3:
            tsops.check("0" in nick, "%s context: the label itself says what 0 does (%r)"
                        % (procedure, nick))

if gimp.version >= 3:
    kind = arguments.get("plug-in-texsynth-solid", {}).get("path", ("?",))[0]
    tsops.check(kind == "GFile", "solid: path is a file argument (%s)" % kind)
    action = re.search(r"TSFILEACTION path \| (\S+)", proc.stdout)
    tsops.check(action and action.group(1) == "save",
                "solid: its file chooser saves (%s)" % (action.group(1) if action else None))
    status = re.search(r"TSSOLID (\S+)", proc.stdout)
    tsops.check(status and status.group(1) == "success",
                "solid called from Python with a Gio.File: %s" % (status.group(1) if status else None))
    size = os.path.getsize(volume) if os.path.isfile(volume) else 0
    tsops.check(size >= 16 ** 3 * 3, "solid from Python: the volume file was written (%d bytes)"
                % size)

tsops.finish()
