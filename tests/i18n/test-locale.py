# The GEGL ops speak the user's language: under an Estonian locale
# (LANGUAGE=et LANG=et_EE.UTF-8 LC_ALL=et_EE.UTF-8) a GEGL program finds
# texsynth:synthesize's Estonian title, every property label and blurb of
# the ops in Estonian, and an engine error message in Estonian; the other
# languages of po/LINGUAS are checked the same way when their locale can be
# made. Translations are read from the build tree (TEXSYNTH_LOCALEDIR).
#
# The locale: the system's if it has it, else compiled with localedef
# (Debian package 'locales') into a scratch folder that LOCPATH points at;
# the test is skipped (exit 77) only if et_EE.UTF-8 cannot be made at all.
#
# The ops are queried through the GEGL API from Python (GObject
# introspection), like GIMP does, not with `gegl --info`: the gegl tool
# never calls setlocale(), so it shows every op, GEGL's own too, in English.
# SPDX-License-Identifier: LGPL-3.0-or-later
#
# Usage: test-locale.py --localedir BUILD/po --po-dir SOURCE/po

import argparse
import gettext
import json
import os
import re
import subprocess
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "ops"))
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import tsops  # noqa: E402
from tslocale import locale_env, estonian_or_skip  # noqa: E402

OPS = ["texsynth:synthesize", "texsynth:tileable", "texsynth:volume-load",
       "texsynth:volume-slice", "texsynth:volume-save"]


def probe():
    """Run under the locale: print what GEGL shows, make the engine fail."""
    import locale
    locale.setlocale(locale.LC_ALL, "")
    import gi
    gi.require_version("Gegl", "0.4")
    from gi.repository import Gegl

    Gegl.init(None)
    shown = {"messages_locale": locale.setlocale(locale.LC_MESSAGES), "ops": {}}
    for op in OPS:
        if not Gegl.has_operation(op):
            shown["ops"][op] = None
            continue
        props = {p.name: [p.nick, p.blurb] for p in Gegl.Operation.list_properties(op)}
        shown["ops"][op] = {"title": Gegl.Operation.get_key(op, "title"),
                            "description": Gegl.Operation.get_key(op, "description"),
                            "menu-label": Gegl.Operation.get_key(op, "gimp:menu-label"),
                            "properties": props}
    print(json.dumps(shown), flush=True)

    # A 2x2 exemplar is too small for the engine's smallest neighbourhood:
    # the op warns "texsynth:synthesize: <engine message>" on stderr.
    graph = Gegl.Node()
    color = graph.create_child("gegl:color")
    crop = graph.create_child("gegl:crop")
    crop.set_property("width", 2.0)
    crop.set_property("height", 2.0)
    synth = graph.create_child("texsynth:synthesize")
    synth.set_property("width", 16)
    synth.set_property("height", 16)
    color.link(crop)
    crop.link(synth)
    sink = graph.create_child("gegl:buffer-sink")
    synth.link(sink)
    sink.process()
    sys.exit(0)


def c_format_regex(fmt):
    """A regex matching what printf makes of a C format string."""
    spec = re.compile(r"%(?:\d+\$)?[-+ #0]*\d*(?:\.\d+)?(?:hh|h|ll|l|z|j|t)?[diouxXeEfgGs%]")
    parts, last = [], 0
    for m in spec.finditer(fmt):
        parts.append(re.escape(fmt[last:m.start()]))
        parts.append("%" if m.group().endswith("%") else ".+?")
        last = m.end()
    parts.append(re.escape(fmt[last:]))
    return "".join(parts)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--probe", action="store_true", help=argparse.SUPPRESS)
    parser.add_argument("--localedir", help="the build tree's po folder")
    parser.add_argument("--po-dir", help="the source po folder (LINGUAS)")
    args = parser.parse_args()
    if args.probe:
        probe()

    with open(os.path.join(args.po_dir, "LINGUAS"), encoding="utf-8") as f:
        languages = [w for line in f if not line.startswith("#") for w in line.split()]
    scratch = tsops.workdir()
    english = None
    no_locale = []
    for lang in ["et"] + [lang for lang in languages if lang != "et"]:
        if lang == "et":
            env, how = estonian_or_skip(scratch), "et_EE.UTF-8"
        else:
            env, how = locale_env(lang, scratch)
        if env is None:
            tsops.note("%s: no locale, not checked" % lang)
            no_locale.append(lang)
            continue
        tsops.note("\n--- %s: %s" % (lang, how))
        env["TEXSYNTH_LOCALEDIR"] = args.localedir
        mo = os.path.join(args.localedir, lang, "LC_MESSAGES", "texsynth.mo")
        if not tsops.check(os.path.isfile(mo), "%s is built" % mo):
            continue
        catalogue = gettext.GNUTranslations(open(mo, "rb"))
        run = subprocess.run([sys.executable, os.path.abspath(__file__), "--probe"],
                             env=env, capture_output=True, text=True, timeout=120)
        lines = run.stdout.splitlines()
        if not tsops.check(run.returncode == 0 and lines,
                           "%s: the GEGL probe runs (exit %d) %s" % (lang, run.returncode,
                                                                    run.stderr[-2000:])):
            continue
        shown = json.loads(lines[0])
        if english is None:
            c_env = dict(os.environ, LC_ALL="C.UTF-8", LANGUAGE="", LANG="C.UTF-8")
            c_env.pop("LOCPATH", None)
            english = json.loads(subprocess.run(
                [sys.executable, os.path.abspath(__file__), "--probe"], env=c_env,
                capture_output=True, text=True, timeout=120).stdout.splitlines()[0])
        check_language(lang, catalogue, shown, english, run.stderr)
    tsops.finish(skipped="" if not no_locale else
                 "%s: their locales are missing and localedef cannot make them (Debian "
                 "package 'locales')" % ", ".join(no_locale))


def check_language(lang, catalogue, shown, english, stderr):
    tr = catalogue.gettext

    def known(text):  # in the catalogue (its translation may equal it: "Format")
        return text in catalogue._catalog

    for op in OPS:
        ours, theirs = shown["ops"][op], english["ops"][op]
        if not tsops.check(ours is not None and theirs is not None, "%s is found" % op):
            continue
        for key in ("title", "description", "menu-label"):
            if theirs[key] is None:
                continue
            want = tr(theirs[key])
            tsops.check(known(theirs[key]) and ours[key] == want,
                        "%s: %s's %s is translated: %r" % (lang, op, key, ours[key]))
        untranslated = [name for name, (nick, blurb) in theirs["properties"].items()
                        if ours["properties"][name] != [tr(nick), tr(blurb) if blurb else blurb]
                        or not known(nick) or (blurb and not known(blurb))]
        tsops.check(not untranslated, "%s: every property label and blurb of %s is translated%s"
                    % (lang, op, "" if not untranslated else ": not " + ", ".join(untranslated)))
    if lang == "et":
        tsops.check(shown["ops"]["texsynth:synthesize"]["title"] == "Mustri süntees",
                    "et: the Estonian title is 'Mustri süntees'")

    message = "the exemplar is %zux%zu pixels; it needs at least %dx%d (the smallest neighbourhood)"
    pattern = "texsynth:synthesize: " + c_format_regex(tr(message))
    tsops.check(known(message) and tr(message) != message and re.search(pattern, stderr),
                "%s: the engine's error message is shown translated: %s" % (
                    lang, next((line.strip() for line in stderr.splitlines()
                                if "texsynth:synthesize:" in line), repr(stderr[-500:]))))


main()
