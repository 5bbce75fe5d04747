/* GIMP 2.10 glue shared by its procedures (main-gimp2.c, heal-gimp2.c,
 * layers-gimp2.c, guided-gimp2.c): a procedure's outcome, reading layers and making
 * images.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#ifndef TEXSYNTH_COMPAT_GIMP2_H
#define TEXSYNTH_COMPAT_GIMP2_H

#include "texsynth-plugin.h"

typedef struct
{
  GimpPDBStatusType status;
  gchar            *message;   /* for the caller when status is an error */
  gint32            new_image; /* -1 if none */
  gint32            new_layer; /* -1 if none */
} Outcome;

/* Records a failure (status and message, which it takes) and returns FALSE. */
static inline gboolean
fail (Outcome *outcome, GimpPDBStatusType status, gchar *message)
{
  outcome->status = status;
  outcome->message = message;
  return FALSE;
}

/* Copies the layer (or its selected part: the selection's bounds, with
 * unselected pixels made transparent) into `exemplar`; FALSE with a
 * message for the user. */
gboolean read_exemplar (gint32 drawable, gboolean crop_to_selection, TsExemplar *exemplar,
                        gchar **message);

/* A new image like the exemplar's (type, precision, profile) with one
 * layer per buffer, named `names`, the first on top; alphas[i] says
 * whether layer i has alpha (NULL: as the exemplar). -1 on failure. */
gint32 new_image (const TsExemplar *exemplar, GeglBuffer **layers, const gchar **names,
                  const gboolean *alphas, gint n);

/* The end of a run that made outcome->new_image: a failure if it could
 * not be made; else the run's `args` (`size` bytes) kept as the last
 * values of `procedure` unless non-interactive, and the image shown if
 * interactive. */
gboolean finish_with_image (Outcome *outcome, GimpRunMode mode, const gchar *procedure,
                            gconstpointer args, guint32 size);

/* Writes `result` (the layer's size) over the layer's pixels, as one
 * undo step; an indexed image is converted to RGB first, with a message.
 * FALSE if out of memory. Only a finished run may call it: a cancelled
 * one leaves the image as it was. */
gboolean ts_replace_layer_pixels2 (gint32 drawable, GeglBuffer *result);

#endif /* TEXSYNTH_COMPAT_GIMP2_H */
