# Running headless GIMP (2.10 or 3) in batch mode for the plug-in's tests:
# a throwaway profile with the plug-in installed, and Script-Fu snippets in
# each version's dialect that print "TSRESULT <tag> <values>" lines.
# SPDX-License-Identifier: GPL-3.0-or-later

import os
import re
import shutil
import subprocess

import tsops


def gegl_has(op):
    """Whether the gegl tool (same GEGL_PATH as GIMP) finds `op`; without
    the tool the test stops with a failure that says so."""
    proc = subprocess.run([tsops.gegl_binary(), "--exists", op], capture_output=True, timeout=60)
    return proc.returncode == 0


def quote(text):
    return '"%s"' % text.replace("\\", "\\\\").replace('"', '\\"')


def _plugin_cache_path(version):
    """Where the tests of a build keep GIMP's registrations of the installed
    plug-ins: each test's fresh profile would otherwise make GIMP query
    every one of them (over a hundred processes, several seconds of CPU).
    The plug-in under test is left out, so each profile still queries it."""
    build = os.environ.get("TEXSYNTH_BUILD_ROOT")
    return os.path.join(build, "test-caches", "gimp%d-pluginrc" % version) if build else None


def _top_level_forms(text):
    """The top-level parenthesised forms of a pluginrc, as text (comments
    and what lies between forms dropped)."""
    forms, depth, start, in_string, escaped, in_comment = [], 0, 0, False, False, False
    for i, c in enumerate(text):
        if in_comment:
            in_comment = c != "\n"
        elif in_string:
            if escaped:
                escaped = False
            elif c == "\\":
                escaped = True
            elif c == '"':
                in_string = False
        elif c == '"':
            in_string = True
        elif c == "#" and depth == 0:
            in_comment = True
        elif c == "(":
            if depth == 0:
                start = i
            depth += 1
        elif c == ")" and depth > 0:
            depth -= 1
            if depth == 0:
                forms.append(text[start:i + 1])
    return forms


class ScriptFu2:
    """GIMP 2.10's Script-Fu: drawables by ID, results wrapped in lists."""

    version = 2
    # GIMP_PRECISION_U16_LINEAR / _GAMMA
    u16_precisions = (200, 250)

    def load(self, path):
        return ("(img (car (gimp-file-load RUN-NONINTERACTIVE %s %s)))"
                " (drw (car (gimp-image-get-active-drawable img)))" % (quote(path), quote(path)))

    def drawables(self):
        return "drw"

    def width(self, image):
        return "(car (gimp-image-width %s))" % image

    def height(self, image):
        return "(car (gimp-image-height %s))" % image

    def n_layers(self, image):
        return "(car (gimp-image-get-layers %s))" % image

    def active_layer(self, image):
        return "(car (gimp-image-get-active-layer %s))" % image

    def top_layer(self, image):
        return "(aref (cadr (gimp-image-get-layers %s)) 0)" % image

    def save(self, image, layer, path):
        return "(gimp-file-save RUN-NONINTERACTIVE %s %s %s %s)" % (
            image, layer, quote(path), quote(path))

    def pixel(self, layer, x, y):
        """The pixel's values as a Scheme list."""
        return "(vector->list (cadr (gimp-drawable-get-pixel %s %d %d)))" % (layer, x, y)

    def is_calling_error(self, text):
        return "Calling error for procedure" in text

    # -- common snippets built from the above --

    def message(self, tag, *values):
        parts = " \" \" ".join("(number->string %s)" % v for v in values)
        return '(gimp-message (string-append "TSRESULT %s " %s))' % (tag, parts)

    def render_call(self, w, h, tileable, quality, seed):
        return "(plug-in-texsynth-render RUN-NONINTERACTIVE img %s %d %d %s %d %d)" % (
            self.drawables(), w, h, tileable, quality, seed)

    def render_report(self, tag, path, w, h, tileable, quality, seed, save=None, select=None):
        body = ""
        # select: one rectangle (x, y, w, h) or a list of them, added up.
        for i, rect in enumerate([select] if isinstance(select, tuple) else select or []):
            body += "(gimp-image-select-rectangle img %s %d %d %d %d) " % (
                ("CHANNEL-OP-ADD" if i else "CHANNEL-OP-REPLACE",) + tuple(rect))
        body += "(let* ((out (car %s)) (layer %s)) " % (
            self.render_call(w, h, tileable, quality, seed), self.active_layer("out"))
        if save:
            body += self.save("out", "layer", save) + " "
        body += self.message(tag, self.width("out"), self.height("out"),
                             "(car (gimp-image-get-precision img))",
                             "(car (gimp-image-get-precision out))",
                             "(car (gimp-drawable-has-alpha layer))")
        return "(let* (%s) %s))" % (self.load(path), body)

    def tileable_report(self, tag, path, quality, seed, save=None):
        corner = self.pixel("drw", 0, 0)
        middle = self.pixel("drw", 48, 48)
        body = ("(let* ((c0 %s) (m0 %s)) (plug-in-texsynth-tileable RUN-NONINTERACTIVE img %s %d %d) "
                % (corner, middle, self.drawables(), quality, seed))
        if save:
            body += self.save("img", "drw", save) + " "
        body += self.message(tag, "(if (equal? c0 %s) 0 1)" % corner,
                             "(if (equal? m0 %s) 1 0)" % middle) + ")"
        return "(let* (%s) %s)" % (self.load(path), body)

    def solid_call(self, size, volume, quality, seed, cell_structure):
        return "(plug-in-texsynth-solid RUN-NONINTERACTIVE img %s %d %s %d %d %d)" % (
            self.drawables(), size, quote(volume), quality, seed, cell_structure)

    def solid_report(self, tag, path, size, volume, quality, seed, cell_structure=0,
                     save=None):
        """cell_structure: 0 off, 1 on, 2 automatic. save: where to export
        the top layer, the slice across x."""
        body = "(let* ((out (car %s)) (layer %s)) " % (
            self.solid_call(size, volume, quality, seed, cell_structure), self.top_layer("out"))
        if save:
            body += self.save("out", "layer", save) + " "
        body += self.message(tag, self.width("out"), self.height("out"), self.n_layers("out")) + ")"
        return "(let* (%s) %s)" % (self.load(path), body)

    def solid_last_values_report(self, tag, path, last_values, save):
        """GIMP 2.10 only: stores `last_values` (bytes) as the solid's last
        values, runs it with RUN-WITH-LAST-VALS and exports the top layer."""
        store = '(gimp-procedural-db-set-data "plug-in-texsynth-solid" %d (vector %s))' % (
            len(last_values), " ".join(str(b) for b in last_values))
        call = ("(plug-in-texsynth-solid RUN-WITH-LAST-VALS img %s 0 %s 0 0 0)"
                % (self.drawables(), quote("")))
        body = "%s (let* ((out (car %s)) (layer %s)) %s %s)" % (
            store, call, self.top_layer("out"), self.save("out", "layer", save),
            self.message(tag, self.width("out"), self.height("out")))
        return "(let* (%s) %s)" % (self.load(path), body)

    def marked(self, tag, call, path):
        return '(begin (gimp-message "TSCALL %s") (let* (%s) %s))' % (tag, self.load(path), call)

    def call_render(self, tag, path, w, h, tileable, quality, seed):
        return self.marked(tag, self.render_call(w, h, tileable, quality, seed), path)

    def call_solid(self, tag, path, size, volume, quality, seed, cell_structure=0):
        return self.marked(tag, self.solid_call(size, volume, quality, seed, cell_structure), path)


class Gimp:
    """One GIMP version: its console binary, a throwaway profile holding
    the plug-in, and batch runs."""

    def __init__(self, console, plugin, work):
        self.console = console
        self.version = 3 if "3" in os.path.basename(console).split("-")[-1] else 2
        self.sf = ScriptFu2() if self.version == 2 else __import__("scriptfu3").ScriptFu3()
        self.profile = os.path.join(work, "gimp-profile")
        plugin_dir = os.path.join(self.profile, "plug-ins", "texsynth")
        os.makedirs(plugin_dir)
        shutil.copy2(plugin, os.path.join(plugin_dir, "texsynth"))
        for folder in ("brushes", "gradients", "patterns", "palettes", "fonts", "tmp"):
            os.makedirs(os.path.join(self.profile, folder), exist_ok=True)
        self.home = os.path.join(work, "home")
        os.makedirs(self.home)
        self.plugin_cache = _plugin_cache_path(self.version)
        if self.plugin_cache and os.path.isfile(self.plugin_cache):
            shutil.copy(self.plugin_cache, os.path.join(self.profile, "pluginrc"))

    def env(self):
        env = dict(os.environ)
        env["GIMP2_DIRECTORY" if self.version == 2 else "GIMP3_DIRECTORY"] = self.profile
        env["HOME"] = self.home  # nothing may touch the user's own config
        env["XDG_CONFIG_HOME"] = os.path.join(self.home, ".config")
        env["XDG_CACHE_HOME"] = os.path.join(self.home, ".cache")
        env["XDG_DATA_HOME"] = os.path.join(self.home, ".local", "share")
        env.pop("DISPLAY", None)
        return env

    def command(self, snippets, interactive=False):
        cmd = [self.console, "-i", "-d", "-f"] if not interactive else [self.console, "-d", "-f", "-s"]
        if self.version >= 3:
            # GIMP 3 stops at the first failing command and would then wait.
            cmd += ["--batch-interpreter=plug-in-script-fu-eval", "--quit"]
        for snippet in snippets:
            cmd += ["-b", snippet]
        return cmd + (["-b", "(gimp-quit 0)"] if self.version == 2 else [])

    def run(self, snippets, timeout=600):
        """Run the snippets in one GIMP session: (exit code, output, '')
        with stderr merged into stdout so that messages keep their order."""
        try:
            proc = subprocess.run(self.command(snippets), env=self.env(), stdin=subprocess.DEVNULL,
                                  stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                                  text=True, timeout=timeout)
        except subprocess.TimeoutExpired:
            tsops.die("GIMP did not finish within %d s" % timeout)
        tsops.note("---- GIMP output ----\n%s---- end of GIMP output ----" % proc.stdout)
        self._keep_system_plugins()
        return proc.returncode, proc.stdout, ""

    def _keep_system_plugins(self):
        """Stores the installed plug-ins' registrations from this profile's
        pluginrc for the next test's profile, once per build."""
        pluginrc = os.path.join(self.profile, "pluginrc")
        if not self.plugin_cache or os.path.isfile(self.plugin_cache) or not os.path.isfile(pluginrc):
            return
        with open(pluginrc, encoding="latin-1") as f:
            forms = _top_level_forms(f.read())
        system = [form for form in forms
                  if not form.startswith("(plug-in-def") or '"${gimp_plug_in_dir}/' in form.split("\n")[0]]
        # The plug-in under test must be queried in every profile.
        if any(form.startswith("(plug-in-def") for form in system) and \
           not any("texsynth" in form for form in system):
            os.makedirs(os.path.dirname(self.plugin_cache), exist_ok=True)
            partial = "%s.%d" % (self.plugin_cache, os.getpid())
            with open(partial, "w", encoding="latin-1") as f:
                f.write("\n".join(system) + "\n")
            os.replace(partial, self.plugin_cache)

    @staticmethod
    def error_text(lines, tag):
        """GIMP's report of the error of the call marked `tag`, if any:
        "Calling error for procedure '...':" and the message after it."""
        seen = False
        for i, line in enumerate(lines):
            if "TSCALL " + tag in line:
                seen = True
            elif seen and "TSCALL " in line:
                return None
            elif seen and re.search(r"(Calling|Execution) error for procedure|^Error: argument", line):
                return " ".join(l.strip() for l in lines[i:i + 2])
        return None
