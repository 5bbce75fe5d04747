# GIMP 3's Script-Fu dialect for the plug-in's tests (see gimpbatch.py).
# SPDX-License-Identifier: GPL-3.0-or-later

import re

from gimpbatch import ScriptFu2, quote


class ScriptFu3(ScriptFu2):
    """GIMP 3: objects, drawables as a vector, get-width/height."""

    version = 3
    # GIMP_PRECISION_U16_LINEAR / _NON_LINEAR / _PERCEPTUAL
    u16_precisions = (200, 250, 275)

    def load(self, path):
        return ("(img (car (gimp-file-load RUN-NONINTERACTIVE %s)))"
                " (drw (vector-ref (car (gimp-image-get-selected-layers img)) 0))" % quote(path))

    def drawables(self):
        return "(vector drw)"

    def width(self, image):
        return "(car (gimp-image-get-width %s))" % image

    def height(self, image):
        return "(car (gimp-image-get-height %s))" % image

    def n_layers(self, image):
        return "(vector-length (car (gimp-image-get-layers %s)))" % image

    def active_layer(self, image):
        return "(vector-ref (car (gimp-image-get-layers %s)) 0)" % image

    def top_layer(self, image):
        return self.active_layer(image)

    def save(self, image, layer, path):
        return "(gimp-file-save RUN-NONINTERACTIVE %s %s -1)" % (image, quote(path))

    def pixel(self, layer, x, y):
        return "(car (gimp-drawable-get-pixel %s %d %d))" % (layer, x, y)

    def is_calling_error(self, text):
        # GIMP 3's Script-Fu checks the registered ranges itself, before
        # the PDB would (which gives a calling error to other callers).
        return "Calling error for procedure" in text or re.search(
            r"^Error: argument \d+ in call to plug-in-texsynth-\w+ has value .* out of range", text)

    def filter_report(self, tag, path):
        """GIMP's core finds the op: it runs as a non-destructive layer
        filter (what Filters > Map > Make Seamless by Synthesis adds)."""
        body = ('(let* ((f (car (gimp-drawable-filter-new drw "texsynth:tileable" ""))))'
                " (gimp-drawable-append-filter drw f) %s)"
                % self.message(tag, "(vector-length (car (gimp-drawable-get-filters drw)))"))
        return "(let* (%s) %s)" % (self.load(path), body)
