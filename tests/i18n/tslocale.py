# Locales for the translation tests: the system's if it has the locale,
# else compiled with localedef (Debian package 'locales') into a scratch
# folder that LOCPATH points at, which needs no root.
# SPDX-License-Identifier: LGPL-3.0-or-later

import os
import subprocess
import sys

import tsops

SKIP = 77
LOCALES = {"et": "et_EE", "es": "es_ES", "fi": "fi_FI", "hr": "hr_HR", "zh_CN": "zh_CN"}


def locale_env(lang, scratch):
    """(environment selecting `lang`, how it was found), or (None, None) if
    its locale cannot be made."""
    name = LOCALES[lang] + ".UTF-8"
    env = dict(os.environ, LANGUAGE=lang, LANG=name, LC_ALL=name)
    env.pop("LOCPATH", None)
    check = [sys.executable, "-c", "import locale; locale.setlocale(locale.LC_ALL, '')"]
    if subprocess.run(check, env=env, capture_output=True).returncode == 0:
        return env, "the system's " + name
    localedef = subprocess.run(["localedef", "-i", LOCALES[lang], "-f", "UTF-8",
                                os.path.join(scratch, name)], capture_output=True, text=True)
    env["LOCPATH"] = scratch
    # localedef exits 1 for mere warnings; the check says whether it worked.
    if localedef.returncode not in (0, 1) or \
            subprocess.run(check, env=env, capture_output=True).returncode != 0:
        tsops.note("cannot make the %s locale: %s" % (name, localedef.stderr.strip()))
        return None, None
    return env, "%s compiled into %s (LOCPATH)" % (name, scratch)


def estonian_or_skip(scratch):
    """The environment of the Estonian locale, or exit 77 (skip) saying why."""
    env, how = locale_env("et", scratch)
    if env is None:
        tsops.note("SKIP: the et_EE.UTF-8 locale is missing and localedef cannot make it "
                   "(install the Debian package 'locales'; scripts/install-deps.sh "
                   "generates it)")
        sys.exit(SKIP)
    tsops.note("locale: " + how)
    return env
