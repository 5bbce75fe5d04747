/* GIMP 3 glue shared by its procedures (main-gimp3.c, heal-gimp3.c,
 * layers-gimp3.c, guided-gimp3.c): describing procedures, a run's return
 * values, the drawables' checks, reading layers and making images.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#ifndef TEXSYNTH_COMPAT_GIMP3_H
#define TEXSYNTH_COMPAT_GIMP3_H

#include <libgimp/gimp.h>

#include "texsynth-plugin.h"

/* The return values of a failed run, with `message` (taken; may be NULL). */
GimpValueArray *failure (GimpProcedure *procedure, GimpPDBStatusType status, gchar *message);

/* How many drawables the NULL-terminated `drawables` holds (0 if NULL). */
gint count_drawables (GimpDrawable **drawables);

/* Checks common to all procedures: one to `max` layers, the ops found;
 * NULL if fine, else a message. */
gchar *check_drawables (GimpDrawable **drawables, gint max);

/* Copies the layer (or its selected part: the selection's bounds, with
 * unselected pixels made transparent) into `exemplar`; FALSE with a
 * message for the user. */
gboolean read_exemplar (GimpDrawable *drawable, gboolean crop_to_selection,
                        TsExemplar *exemplar, gchar **message);

/* A new image like the exemplar's (type, precision, profile) with one
 * layer per buffer, named `names`, the first on top; alphas[i] says
 * whether layer i has alpha (NULL: as the exemplar). NULL on failure. */
GimpImage *new_image (const TsExemplar *exemplar, GeglBuffer **layers, const gchar **names,
                      const gboolean *alphas, gint n);

/* An interactive run's result: shown, and returned as the new image. */
GimpValueArray *success_with_image (GimpProcedure *procedure, GimpRunMode mode,
                                    GimpImage *image);

/* Writes `result` (the layer's size) over the layer's pixels, as one
 * undo step; an indexed image is converted to RGB first, with a message.
 * FALSE if out of memory. Only a finished run may call it: a cancelled
 * one leaves the image as it was. */
gboolean ts_replace_layer_pixels3 (GimpDrawable *drawable, GeglBuffer *result);

/* A procedure's menu label and path, documentation and attribution; its
 * image types are those of every texsynth procedure. */
void ts_describe3 (GimpProcedure *procedure, const gchar *label, const gchar *menu,
                   const gchar *blurb, const gchar *help);
/* The "quality" and "seed" arguments; `quality_texts`: the plugin-args.c
 * entry whose label and tooltip "quality" shows. */
void ts_add_quality_and_seed3 (GimpProcedure *procedure, const gchar *quality_texts);

#endif /* TEXSYNTH_COMPAT_GIMP3_H */
