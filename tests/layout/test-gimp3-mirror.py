#!/usr/bin/env python3
# scripts/gimp3-env takes its Debian mirror from the machine's own apt
# sources and names none itself: `gimp3-env mirror APT-DIR OS-RELEASE`
# on made-up apt folders (one-line and deb822 sources, options, disabled
# stanzas, security-only and foreign archives, none at all) and on this
# machine's, and no package host written anywhere in scripts/.
# Usage: test-gimp3-mirror.py SOURCE_ROOT
# SPDX-License-Identifier: LGPL-3.0-or-later
import os
import re
import subprocess
import sys
import tempfile

root = sys.argv[1]
script = os.path.join(root, "scripts", "gimp3-env")
failures = []

BOOKWORM = "ID=debian\nVERSION_CODENAME=bookworm\n"
UBUNTU = "ID=ubuntu\nVERSION_CODENAME=jammy\n"

# (what it shows, os-release, {file under the apt folder: text}, expected mirror)
CASES = [
    ("no sources at all", BOOKWORM, {}, ""),
    ("a one-line entry", BOOKWORM,
     {"sources.list": "# a comment\ndeb-src http://src.example/debian bookworm main\n"
                      "deb http://one.example/debian bookworm main\n"},
     "http://one.example/debian"),
    ("options before the URI", BOOKWORM,
     {"sources.list.d/a.list": "deb [ arch=amd64 signed-by=/k.gpg ] http://opt.example/debian/ "
                               "bookworm main contrib\n"},
     "http://opt.example/debian/"),
    ("a deb822 stanza after a disabled one", BOOKWORM,
     {"sources.list.d/debian.sources":
      "Types: deb\nURIs: http://off.example/debian\nSuites: bookworm\nEnabled: no\n\n"
      "Types: deb deb-src\n# a comment\nURIs: https://on.example/debian\n"
      "Suites: bookworm bookworm-updates\nComponents: main\n"},
     "https://on.example/debian"),
    ("security and foreign archives only", BOOKWORM,
     {"sources.list": "deb http://security.example/debian-security bookworm-security main\n",
      "sources.list.d/node.sources": "Types: deb\nURIs: https://node.example/node\n"
                                     "Suites: nodistro\n"},
     ""),
    ("the main archive after a security one", BOOKWORM,
     {"sources.list.d/x.sources": "Types: deb\nURIs: http://m.example/debian-security\n"
                                  "Suites: bookworm-security\n\n"
                                  "Types: deb\nURIs: http://m.example/debian\nSuites: bookworm\n"},
     "http://m.example/debian"),
    ("sources.list before sources.list.d", BOOKWORM,
     {"sources.list": "deb http://first.example/debian stable main\n",
      "sources.list.d/b.list": "deb http://second.example/debian bookworm main\n"},
     "http://first.example/debian"),
    ("not Debian: its own release is no Debian suite", UBUNTU,
     {"sources.list": "deb http://archive.ubuntu.example/ubuntu jammy main\n"},
     ""),
    ("a cdrom entry is not a mirror", BOOKWORM,
     {"sources.list": "deb cdrom:[Debian 12]/ bookworm main\n"},
     ""),
]


def mirror(apt, os_release, env=None):
    run = subprocess.run(["bash", script, "mirror", apt, os_release], capture_output=True,
                         text=True, env=env or {k: v for k, v in os.environ.items()
                                               if k != "TEXSYNTH_DEBIAN_MIRROR"})
    if run.returncode != 0:
        failures.append("gimp3-env mirror %s exited %d: %s" % (apt, run.returncode, run.stderr))
    return run.stdout.strip()


with tempfile.TemporaryDirectory() as work:
    for n, (what, release, files, expected) in enumerate(CASES):
        apt = os.path.join(work, "apt%d" % n)
        os.makedirs(os.path.join(apt, "sources.list.d"))
        for name, text in files.items():
            with open(os.path.join(apt, name), "w", encoding="utf-8") as f:
                f.write(text)
        os_release = os.path.join(work, "os-release%d" % n)
        with open(os_release, "w", encoding="utf-8") as f:
            f.write(release)
        got = mirror(apt, os_release)
        print("%-45s -> %s" % (what, got or "(debootstrap's default)"))
        if got != expected:
            failures.append("%s: got %r, expected %r" % (what, got, expected))
    # The override wins over any source.
    env = dict(os.environ, TEXSYNTH_DEBIAN_MIRROR="http://override.example/debian")
    got = mirror(os.path.join(work, "apt1"), os.path.join(work, "os-release1"), env)
    if got != "http://override.example/debian":
        failures.append("TEXSYNTH_DEBIAN_MIRROR not honoured: got %r" % got)

# This machine's own sources: whatever they give is one of their URIs.
got = mirror("/etc/apt", "/etc/os-release")
print("this machine's sources -> %s" % (got or "(debootstrap's default)"))
if got:
    listed = ""
    for folder, _, names in os.walk("/etc/apt"):
        for name in names:
            if name == "sources.list" or name.endswith((".list", ".sources")):
                with open(os.path.join(folder, name), encoding="utf-8", errors="replace") as f:
                    listed += f.read()
    if got not in listed.split():
        failures.append("this machine's mirror %r is not in its apt sources" % got)

# No package host written into the scripts.
HOST = re.compile(r"https?://[^\s\"')]*(debian|ubuntu)[^\s\"')]*", re.I)
for folder, _, names in os.walk(os.path.join(root, "scripts")):
    for name in names:
        path = os.path.join(folder, name)
        with open(path, encoding="utf-8", errors="replace") as f:
            for number, line in enumerate(f, 1):
                if HOST.search(line):
                    failures.append("%s:%d names a package host: %s"
                                    % (os.path.relpath(path, root), number, line.strip()))

for f in failures:
    print("FAIL:", f)
sys.exit(1 if failures else 0)
