# The plug-in in Estonian in real, headless GIMP 2.10: under
# LANGUAGE=et LC_ALL=et_EE.UTF-8, with TEXSYNTH_LOCALEDIR at the build
# tree's catalogues, GIMP registers the plug-in's text domain, so its menu
# label "Texture _Synthesis..." reads "Mustri _süntees...", and a refused
# call shows the plug-in's message in Estonian.
#
# GIMP 2.10's PDB has no call that returns a translated menu label
# (gimp-plugins-query and gimp-procedural-db-proc-info give the registered
# English strings), and gimp-console builds no menus. So the label is
# translated here the way GIMP's menus do it: with the text domain and
# folder the plug-in registered, as GIMP recorded them in the profile's
# pluginrc (locale-def), applied to the label GIMP recorded (proc-def).
# SPDX-License-Identifier: GPL-3.0-or-later
#
# Usage: test-gimp-i18n.py --gimp GIMP-CONSOLE-2.10 --plugin PLUG-IN --localedir BUILD/po

import argparse
import gettext
import os
import re
import sys

here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(here, "..", "ops"))
sys.path.insert(0, os.path.join(here, "..", "i18n"))
import tsops  # noqa: E402
import gimpbatch  # noqa: E402
from tslocale import estonian_or_skip  # noqa: E402

PROC = "plug-in-texsynth-render"
LABEL = "Texture _Synthesis..."
QUALITY_MESSAGE = "Quality must be between %d and %d (got %d)."

parser = argparse.ArgumentParser()
parser.add_argument("--gimp", required=True, help="gimp-console-2.10")
parser.add_argument("--plugin", required=True, help="the built GIMP 2.10 plug-in")
parser.add_argument("--localedir", required=True, help="the build tree's po folder")
args = parser.parse_args()

work = tsops.workdir()
os.environ.update(estonian_or_skip(work))
os.environ["TEXSYNTH_LOCALEDIR"] = args.localedir
catalogue = gettext.translation("texsynth", args.localedir, languages=["et"])

gimp = gimpbatch.Gimp(args.gimp, args.plugin, work)
bark = os.path.join(os.environ.get("TEXSYNTH_SOURCE_ROOT", "."), "examples", "bark.png")
code, output, _ = gimp.run([gimp.sf.call_render("quality", bark, 64, 64, 0, 99, 1)], timeout=300)

# --- the menu label, as GIMP's menus translate it --------------------------
pluginrc = os.path.join(gimp.profile, "pluginrc")
text = ""
if os.path.isfile(pluginrc):  # it holds binary icon data too
    with open(pluginrc, encoding="utf-8", errors="replace") as f:
        text = f.read()
domain = re.search(r'\(locale-def "texsynth" "((?:[^"\\]|\\.)*)"\)', text)
tsops.check(domain and domain.group(1) == args.localedir,
            "GIMP registered the plug-in's text domain 'texsynth' in %s"
            % (domain.group(1) if domain else "(no locale-def in pluginrc)"))
strings = r'"((?:[^"\\]|\\.)*)"\s+'
proc = re.search(r'\(proc-def "%s" \d+\s+' % re.escape(PROC) + strings * 6, text)
label = proc.group(6) if proc else None
tsops.check(label == LABEL, "GIMP recorded the menu label %r" % label)
if domain and label:
    shown = gettext.translation("texsynth", domain.group(1), languages=["et"]).gettext(label)
    tsops.check(shown == "Mustri _süntees...",
                "the menu label reads %r in Estonian (Filters > Render > Pattern)" % shown)

# --- a message of the plug-in, shown by GIMP ---------------------------------
estonian = catalogue.gettext(QUALITY_MESSAGE)
shown = re.search(re.escape(estonian).replace("%d", r"-?\d+"), output)
tsops.check(estonian != QUALITY_MESSAGE and shown and "99" in shown.group(),
            "GIMP shows the plug-in's refusal of quality 99 in Estonian: %r"
            % (shown.group() if shown else estonian))

tsops.finish()
