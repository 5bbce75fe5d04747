# The translations are complete and current: every language of po/LINGUAS
# passes `msgfmt --check` with every message translated (none fuzzy or
# untranslated), every string the sources mark today (a fresh xgettext run
# over po/POTFILES) has a translation in every language, and every source
# file with marked strings is listed in po/POTFILES.
# SPDX-License-Identifier: LGPL-3.0-or-later
#
# Usage: test-catalogues.py --source-root DIR [--xgettext-arg ARG]...

import argparse
import os
import re
import subprocess
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "ops"))
import tsops  # noqa: E402

parser = argparse.ArgumentParser()
parser.add_argument("--source-root", required=True)
parser.add_argument("--xgettext-arg", action="append", default=[],
                    help="the project's own xgettext arguments (po/meson.build)")
args = parser.parse_args()

root = args.source_root
po_dir = os.path.join(root, "po")
work = tsops.workdir()

# meson's 'glib' preset: the GLib marking macros, as the pot target uses them.
GLIB_PRESET = ["--from-code=UTF-8", "--keyword=_", "--keyword=N_", "--keyword=C_:1c,2",
               "--keyword=NC_:1c,2", "--keyword=g_dcgettext:2", "--keyword=g_dngettext:2,3",
               "--keyword=g_dpgettext2:2c,3"]


def read_lines(name):
    with open(os.path.join(po_dir, name), encoding="utf-8") as f:
        return [line.strip() for line in f
                if line.strip() and not line.lstrip().startswith("#")]


languages = read_lines("LINGUAS")
tsops.check(languages, "po/LINGUAS lists languages: %s" % " ".join(languages))

# --- msgfmt --check --statistics: all translated, nothing fuzzy or missing --
for lang in languages:
    po = os.path.join(po_dir, lang + ".po")
    if not tsops.check(os.path.isfile(po), "%s.po exists" % lang):
        continue
    run = subprocess.run(["msgfmt", "--check", "--check-accelerators=_", "--statistics",
                          "-o", os.devnull, po],
                         capture_output=True, text=True, env=dict(os.environ, LC_ALL="C"))
    stats = run.stderr.strip()
    tsops.note("%s: %s" % (lang, stats))
    tsops.check(run.returncode == 0,
                "%s.po passes msgfmt --check (formats, header, mnemonics)" % lang)
    last = stats.splitlines()[-1] if stats else ""
    tsops.check(re.fullmatch(r"\d+ translated messages?\.", last),
                "%s.po is 100%% translated: no fuzzy or untranslated messages" % lang)

# --- every marked string of today's sources is translated ------------------
potfiles = read_lines("POTFILES")
missing_files = [p for p in potfiles if not os.path.isfile(os.path.join(root, p))]
tsops.check(not missing_files, "every file in po/POTFILES exists %s" % (missing_files or ""))

fresh = os.path.join(work, "fresh.pot")
run = subprocess.run(["xgettext", "--package-name=texsynth", "-D", root, "-o", fresh,
                      "-f", os.path.join(po_dir, "POTFILES")] + GLIB_PRESET + args.xgettext_arg,
                     capture_output=True, text=True)
if not tsops.check(run.returncode == 0 and os.path.isfile(fresh),
                   "xgettext extracts the marked strings " + run.stderr.strip()):
    tsops.finish()

for lang in languages:
    po = os.path.join(po_dir, lang + ".po")
    if not os.path.isfile(po):
        continue
    # msgcmp: every msgid of the fresh template must have a (non-fuzzy) translation.
    run = subprocess.run(["msgcmp", po, fresh], capture_output=True, text=True,
                         env=dict(os.environ, LC_ALL="C"))
    tsops.check(run.returncode == 0,
                "%s.po translates every string the sources mark now%s" % (
                    lang, "" if run.returncode == 0 else
                    "; run `meson compile -C build texsynth-update-po` and translate:\n"
                    + run.stderr.strip()))

# --- every source file with marked strings is in POTFILES ------------------
MARK = re.compile(r'\b(?:_|N_|C_|NC_|TS_|TS_N_)\s*\(\s*"|\bts_fail\s*\([^;]*?"', re.S)
unlisted = []
for folder in ("common", "operations", "gimp-plugin"):
    for dirpath, _dirs, files in os.walk(os.path.join(root, folder)):
        for name in sorted(files):
            if not name.endswith((".c", ".h")):
                continue
            path = os.path.join(dirpath, name)
            rel = os.path.relpath(path, root)
            with open(path, encoding="utf-8", errors="replace") as f:
                if MARK.search(f.read()) and rel not in potfiles:
                    unlisted.append(rel)
tsops.check(not unlisted, "every source file with translatable strings is in po/POTFILES%s" % (
    "" if not unlisted else "; add: " + " ".join(unlisted)))

tsops.finish()
